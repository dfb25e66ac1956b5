/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.rsaml.diagram.DiagramException;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.diagram.TimingMode;
import org.rsaml.validation.ModelLoadException;

/**
 * Draws every model a user named, in every view and format asked for, into one directory: what
 * {@code rsaml diagram} and the Maven {@code diagram} goal run. Two models that would be drawn to the
 * same file are refused before anything is written; a model that cannot be read or drawn costs that
 * model only. The front ends only say where the files went and what went wrong.
 */
public final class DiagramBatch {

    /** What the front end is told while the batch runs. */
    public interface Listener {
        /** A diagram was written to {@code file}. */
        void written(Path file);

        /**
         * A model could not be read or drawn: {@code lines} say so as the user should read them;
         * {@code cause} is the underlying defect, if any (for a debug trace).
         */
        void failed(List<String> lines, Throwable cause);
    }

    /** What a front end says of a diagram written to {@code file} (as the user reads it): {@code wrote DIR/FILE}. */
    public static String wrote(Path file) {
        return "wrote " + ModelFiles.display(file);
    }

    private final List<DiagramView> views;
    private final List<DiagramFormat> formats;
    private final TimingMode timing;

    public DiagramBatch(List<DiagramView> views, List<DiagramFormat> formats, TimingMode timing) {
        this.views = List.copyOf(views);
        this.formats = List.copyOf(formats);
        this.timing = timing;
    }

    /**
     * Why the batch will not draw into {@code directory} ({@code shownDirectory} as the user spelt it), said as the user
     * should read it, before anything is written: the directory is a file, or two models would overwrite each other's
     * diagram ({@link #clash}). Both front ends ask this before {@link #draw}.
     */
    public Optional<String> refusal(List<ModelFiles.Input> inputs, Path directory, Path shownDirectory) {
        if (Files.exists(directory) && !Files.isDirectory(directory)) {
            return Optional.of(ModelFiles.display(shownDirectory) + " is a file; name the directory the diagrams are written to");
        }
        return clash(inputs, shownDirectory).map(clash -> clash + "; draw them into different directories");
    }

    /**
     * The first pair of models that would overwrite each other's diagram, as
     * "{@code a and b would both be drawn to DIR/file}" with {@code shownDirectory} as the user spelt it.
     */
    public Optional<String> clash(List<ModelFiles.Input> inputs, Path shownDirectory) {
        for (DiagramView view : views) {
            RsamlDiagrams diagrams = new RsamlDiagrams(view);
            for (DiagramFormat format : formats) {
                Map<String, ModelFiles.Input> byFile = new LinkedHashMap<>();
                for (ModelFiles.Input input : inputs) {
                    if (input.unusable() == null) {
                        String file = diagrams.fileName(input.path(), format);
                        ModelFiles.Input other = byFile.putIfAbsent(file, input);
                        if (other != null) {
                            return Optional.of(other.displayName() + " and " + input.displayName() + " would both be drawn to "
                                    + ModelFiles.display(shownDirectory.resolve(file)));
                        }
                    }
                }
            }
        }
        return Optional.empty();
    }

    /**
     * What a batch did: how many models could not be read or drawn, and what that means for the run (findings never
     * change it; the validate command and goal judge those).
     */
    public record Outcome(int failed) {

        /** {@code rsaml diagram}'s exit code: 2 when a model could not be read or drawn, else 0. */
        public int exitCode() {
            return failed == 0 ? ExitCodes.OK : ExitCodes.INPUT_ERROR;
        }

        /** Why the run fails ({@code could not draw 2 models; see the errors above}), or {@code null} when every model was drawn. */
        public String failure() {
            return failed == 0 ? null : "could not draw " + failed + " model" + (failed == 1 ? "" : "s") + "; see the errors above";
        }
    }

    /** Draws every usable input into {@code directory} (ask {@link #refusal} first). */
    public Outcome draw(List<ModelFiles.Input> inputs, Path directory, Listener listener) {
        int failed = 0;
        for (ModelFiles.Input input : inputs) {
            if (input.unusable() != null) {
                listener.failed(Text.lines(input.unusable()), null);
                failed++;
                continue;
            }
            try {
                for (DiagramView view : views) {
                    RsamlDiagrams diagrams = new RsamlDiagrams(view).timing(timing);
                    for (DiagramFormat format : formats) {
                        listener.written(diagrams.write(input.path(), input.displayName(), format, directory));
                    }
                }
            } catch (ModelLoadException e) {
                listener.failed(Text.lines(e), null);
                failed++;
            } catch (DiagramException e) {
                listener.failed(List.of(input.displayName() + ": error: " + e.getMessage()), e.getCause());
                failed++;
            } catch (OutOfMemoryError e) {
                // The model and its layout are dropped with this file: the next one has the heap again.
                listener.failed(List.of(input.displayName() + ": error: the model is too large for the available heap ("
                        + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB) to be drawn; give the JVM more memory with -Xmx"), e);
                failed++;
            } catch (RuntimeException | StackOverflowError | LinkageError | AssertionError e) {
                // A defect of RsaML's own (or of the layout library): it costs this file only, not the batch.
                listener.failed(List.of(input.displayName() + ": error: internal error while drawing this file (a defect in RsaML,"
                        + " please report it): " + e), e);
                failed++;
            }
        }
        return new Outcome(failed);
    }
}
