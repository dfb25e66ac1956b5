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
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rules;

/**
 * Analyses the timing of every model a user named, once each, and produces everything the run asks
 * for: the verdicts (told to the front end as each model is analysed, and as the JSON document
 * {@code rsaml analyze --format json} prints), the timing rules' findings as a {@link Report} (SARIF,
 * JUnit XML), each witness's SVG timeline, and the outcome. This is what {@code rsaml analyze} and the
 * Maven {@code analyze} goal run. A model that cannot be read or analysed costs that model only. The
 * front ends only show what they are told and turn the outcome into an exit code or a failed build.
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

        /**
         * A witness's timeline was written to {@code file}; {@code line} says so in the words every front end shows:
         * {@code timeline written: DIR/FILE.svg}, DIR as the user named it.
         */
        void timeline(Path file, String line);

        /**
         * A model's verdicts had no witness to draw a timeline of; {@code line} says so in the words every front end
         * shows: {@code MODEL: no timeline written: ...}.
         */
        void noTimeline(String displayName, String line);
    }

    /**
     * What a run asks for besides the verdicts.
     *
     * @param timeline where witnesses' SVG timelines are written, or {@code null} for none
     * @param failOn   which verdicts fail the run (and, as {@link TimingFailOn#findingThreshold()}, which findings)
     * @param json     whether to collect the verdicts as one JSON document
     * @param findings whether to collect the timing rules' findings as a report
     */
    public record Request(Path timeline, TimingFailOn failOn, boolean json, boolean findings) {
    }

    /**
     * What a run found.
     *
     * @param failing      the models whose verdict fails under the run's {@link TimingFailOn} (with "(not analysed)"
     *                     when the verdict is not a miss)
     * @param missed       those of {@code failing} that fail because a deadline or a latency requirement can be missed
     * @param unanalysable the models that could not be read or analysed
     * @param outputFailed whether a timeline could not be written
     * @param json         the verdicts as JSON, or {@code null} when the run did not ask for them
     * @param findings     the timing rules' findings, or {@code null} when the run did not ask for them
     * @param failOn       which verdicts failed the run
     * @param timeline     where the timelines were to be written, as the user named it, or {@code null}
     */
    public record Outcome(List<String> failing, List<String> missed, List<String> unanalysable, boolean outputFailed, TimingJson.Document json,
            Report findings, TimingFailOn failOn, Path timeline) {

        /**
         * {@code rsaml analyze}'s exit code: 2 for input or output errors, else 1 when a model fails (or, with
         * findings, one of them reaches the threshold), else 0.
         */
        public int exitCode() {
            int code = !unanalysable.isEmpty() || outputFailed ? ExitCodes.INPUT_ERROR
                    : failing.isEmpty() ? ExitCodes.OK : ExitCodes.FINDINGS;
            return findings == null ? code : Math.max(code, findings.exitCode());
        }

        /**
         * The timing rules' findings in one line, as the goal's log shows it after writing their reports into
         * {@code reportsShown}: {@code timing findings: 1 file checked: 1 error, 0 warnings; reports in target/rsaml}.
         */
        public String findingsSummary(String reportsShown) {
            return "timing findings: " + findings.summary(reportsShown);
        }

        /** Why the timelines are incomplete ({@code cannot write the timeline into DIR; ...}), or {@code null} when they are not. */
        public String outputFailure() {
            return outputFailed ? "cannot write the timeline into " + ModelFiles.display(timeline) + "; see the errors above" : null;
        }

        /** Which models could not be read or analysed ({@code cannot read or analyse A, B; ...}), or {@code null} when none. */
        public String inputFailure() {
            return unanalysable.isEmpty() ? null : "cannot read or analyse " + String.join(", ", unanalysable) + "; see the errors above";
        }

        /**
         * Which models' verdicts fail the run under its {@link TimingFailOn} ({@code a deadline or a latency requirement
         * can be missed in A (fail on miss)}), or {@code null} when none does.
         */
        public String verdictFailure() {
            if (failing.isEmpty()) {
                return null;
            }
            List<String> unproven = failing.stream().filter(m -> !missed.contains(m)).toList();
            List<String> parts = new java.util.ArrayList<>();
            if (!missed.isEmpty()) {
                parts.add("a deadline or a latency requirement can be missed in " + String.join(", ", missed));
            }
            if (!unproven.isEmpty()) {
                parts.add("the timing is not proven in " + String.join(", ", unproven));
            }
            return String.join("; ", parts) + Report.failingOn(failOn.label());
        }
    }

    private TimingBatch() {
    }

    /**
     * The verdicts and timelines alone.
     *
     * @param base     the directory relative paths are resolved against
     * @param paths    model files and directories as the user named them
     * @param timeline where witnesses' SVG timelines are written, or {@code null} for none
     * @param failOn   which verdicts fail the run
     */
    public static Outcome run(Path base, List<Path> paths, Path timeline, TimingFailOn failOn, Listener listener) {
        return run(base, paths, new Request(timeline, failOn, false, false), listener);
    }

    /**
     * Loads and analyses each model once, and from that one analysis tells the verdicts, writes the
     * timelines and collects what {@code request} asks for.
     *
     * @param base  the directory relative paths are resolved against
     * @param paths model files and directories as the user named them
     */
    public static Outcome run(Path base, List<Path> paths, Request request, Listener listener) {
        List<String> failing = new ArrayList<>();
        List<String> missed = new ArrayList<>();
        List<String> unanalysable = new ArrayList<>();
        List<FileResult> results = new ArrayList<>();
        TimingJson.Document json = request.json() ? new TimingJson.Document() : null;
        Path timeline = request.timeline();
        boolean outputFailed = false;
        for (ModelFiles.Input input : ModelFiles.select(base, paths)) {
            ArchitectureTiming[] analysed = new ArchitectureTiming[1];
            FileResult result = input.unusable() != null ? FileResult.unreadable(input.unusable(), 0)
                    : ModelBatch.check(input.path(), input.displayName(), (file, shown) -> {
                        LoadedModel model = ModelLoader.load(file, shown);
                        // The one decision whether a model can be analysed, in every format and front end.
                        analysed[0] = RsamlModelValidator.analyseTiming(model);
                        return request.findings() ? RsamlModelValidator.validateTiming(model, analysed[0]) : List.of();
                    });
            results.add(result);
            if (!result.readable()) {
                listener.unanalysable(Text.lines(result.error()));
                unanalysable.add(input.displayName());
                continue;
            }
            ArchitectureTiming timing = analysed[0];
            listener.analysed(input.displayName(), timing);
            if (json != null) {
                json.add(input.displayName(), timing);
            }
            if (timeline != null) {
                try {
                    List<Path> written = TimingSvg.write(base.resolve(timeline), timing);
                    for (Path file : written) {
                        listener.timeline(file, "timeline written: " + ModelFiles.display(timeline.resolve(file.getFileName())));
                    }
                    if (written.isEmpty()) {
                        listener.noTimeline(input.displayName(), input.displayName()
                                + ": no timeline written: no missed deadline or exceeded latency requirement has a witness");
                    }
                } catch (IOException e) {
                    listener.timelineFailed(ModelFiles.display(timeline) + ": error: cannot write the timeline: " + e.getMessage());
                    outputFailed = true;
                }
            }
            if (request.failOn().fails(timing.verdict())) {
                if (timing.verdict() == Verdict.MISSES) {
                    failing.add(input.displayName());
                    missed.add(input.displayName());
                } else {
                    failing.add(input.displayName() + " (not analysed)");
                }
            }
        }
        Report findings = request.findings() ? new Report(Rules.timing(), results, request.failOn().findingThreshold()) : null;
        return new Outcome(List.copyOf(failing), List.copyOf(missed), List.copyOf(unanalysable), outputFailed, json, findings, request.failOn(), timeline);
    }
}
