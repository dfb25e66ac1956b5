/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.TimingSvg;
import org.rsaml.analysis.Verdict;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/**
 * Analyses the timing of every model a user named (load, analyse, optionally draw each witness's SVG
 * timeline) and decides the outcome: what {@code rsaml analyze} and the Maven {@code analyze} goal
 * run. A model that cannot be read or analysed costs that model only. The front ends only show the
 * verdicts (text or JSON) and turn the outcome into an exit code or a failed build.
 */
public final class TimingBatch {

    /** What the front end is told while the batch runs. */
    public interface Listener {
        /** A model was analysed. */
        void analysed(String displayName, ArchitectureTiming timing);

        /** A model could not be read or analysed: {@code lines} say so. */
        void unanalysable(List<String> lines);

        /** A timeline could not be written: {@code line} says so. */
        void timelineFailed(String line);

        /** A witness's timeline was written to {@code file}. */
        default void timeline(Path file) {
        }

        /** A model's verdicts had no witness to draw a timeline of. */
        default void noTimeline(String displayName) {
        }
    }

    /**
     * What a run found.
     *
     * @param failing      the models whose verdict fails under the run's {@link TimingFailOn} (with "(not analysed)"
     *                     when the verdict is not a miss)
     * @param unanalysable the models that could not be read or analysed
     * @param outputFailed whether a timeline could not be written
     */
    public record Outcome(List<String> failing, List<String> unanalysable, boolean outputFailed) {

        /** {@code rsaml analyze}'s exit code: 2 for input or output errors, else 1 when a model fails, else 0. */
        public int exitCode() {
            return !unanalysable.isEmpty() || outputFailed ? ExitCodes.INPUT_ERROR
                    : failing.isEmpty() ? ExitCodes.OK : ExitCodes.FINDINGS;
        }
    }

    private TimingBatch() {
    }

    /**
     * @param base     the directory relative paths are resolved against
     * @param paths    model files and directories as the user named them
     * @param timeline where witnesses' SVG timelines are written, or {@code null} for none
     * @param failOn   which verdicts fail the run
     */
    public static Outcome run(Path base, List<Path> paths, Path timeline, TimingFailOn failOn, Listener listener) {
        List<String> failing = new ArrayList<>();
        List<String> unanalysable = new ArrayList<>();
        boolean outputFailed = false;
        for (ModelFiles.Input input : ModelFiles.select(base, paths)) {
            if (input.unusable() != null) {
                listener.unanalysable(Text.lines(input.unusable()));
                unanalysable.add(input.displayName());
                continue;
            }
            ArchitectureTiming timing;
            try {
                // The one decision whether a model can be analysed, in every format and front end.
                timing = RsamlModelValidator.analyseTiming(ModelLoader.load(input.path(), input.displayName()));
            } catch (ModelLoadException e) {
                listener.unanalysable(Text.lines(e));
                unanalysable.add(input.displayName());
                continue;
            }
            listener.analysed(input.displayName(), timing);
            if (timeline != null) {
                try {
                    List<Path> written = TimingSvg.write(base.resolve(timeline), timing);
                    written.forEach(listener::timeline);
                    if (written.isEmpty()) {
                        listener.noTimeline(input.displayName());
                    }
                } catch (IOException e) {
                    listener.timelineFailed(ModelFiles.display(timeline) + ": error: cannot write the timeline: " + e.getMessage());
                    outputFailed = true;
                }
            }
            if (failOn.fails(timing.verdict())) {
                failing.add(input.displayName() + (timing.verdict() == Verdict.MISSES ? "" : " (not analysed)"));
            }
        }
        return new Outcome(List.copyOf(failing), List.copyOf(unanalysable), outputFailed);
    }
}
