/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.nio.file.Path;
import java.util.List;

import org.rsaml.generator.GenerationException;
import org.rsaml.generator.GenerationRefusedException;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.Rules;
import org.rsaml.validation.Severity;

/**
 * Code generation as the command line and the Maven plugin run it: the model's findings as a
 * {@link Report} (written by the same writers as validation), and one summary or error line.
 */
public final class Generation {

    /**
     * @param report   the model's findings (failing at {@code error}: those refuse generation)
     * @param result   what was generated, or {@code null} when nothing was
     * @param errors   why nothing was generated, a safe line each (every problem of a model that cannot be
     *                 read), or empty when it was
     * @param cause    the exception behind {@code error}, for a debugging stack trace, or {@code null}
     * @param exitCode 0 generated, 1 refused for error findings, 2 the model or the output is unusable
     */
    public record Outcome(Report report, GenerationResult result, List<String> errors, Throwable cause, int exitCode) {

        public Outcome {
            errors = List.copyOf(errors);
        }

        /** What was generated, in one line: {@code generated cpp into out: 12 written, 0 unchanged, 3 of yours kept}. */
        public String summary(String outputShown) {
            return "generated " + result.target().id() + " into " + outputShown + ": " + result.written().size()
                    + " written, " + result.unchanged().size() + " unchanged, " + result.preserved().size() + " of yours kept"
                    + (result.deleted().isEmpty() ? "" : ", " + result.deleted().size() + " obsolete removed");
        }

        /**
         * Whether the findings report goes to standard output in {@code format}: always in a structured format
         * (a tool reads it, clean or not), in text only when the model has findings ({@link #errors()} say why a
         * model could not be read).
         */
        public boolean showsReport(ReportFormat format) {
            return format != ReportFormat.TEXT || report.results().stream().anyMatch(r -> !r.findings().isEmpty());
        }

        /** The generator's remarks (what the model cannot express in code, methods of yours no longer called). */
        public List<String> warnings(String modelShown) {
            return result == null ? List.of() : result.warnings().stream().map(w -> modelShown + ": warning: " + w).toList();
        }
    }

    private Generation() {
    }

    /**
     * @param forceHint how the user overrides a refusal, e.g. {@code generate anyway with --force}
     */
    public static Outcome run(Path model, String modelShown, Target target, Path output, boolean force, String forceHint) {
        try {
            GenerationResult result = new RsamlGenerator().generate(model, modelShown, target, output, force);
            return new Outcome(report(modelShown, result.findings()), result, List.of(), null, ExitCodes.OK);
        } catch (GenerationRefusedException e) {
            int errors = e.errors().size();
            return new Outcome(report(modelShown, e.findings()), null, List.of(Text.line(modelShown + ": error: generation refused: the model has "
                    + errors + " error finding" + (errors == 1 ? "" : "s") + "; fix " + (errors == 1 ? "it" : "them")
                    + " or " + forceHint)), null, ExitCodes.FINDINGS);
        } catch (GenerationException e) {
            if (e.getCause() instanceof ModelLoadException unreadable) {
                // Every problem of the file, and a report that says it could not be read.
                return new Outcome(new Report(Rules.all(), List.of(FileResult.unreadable(unreadable, 0)), Severity.ERROR), null,
                        Text.lines(unreadable), unreadable.getCause(), ExitCodes.INPUT_ERROR);
            }
            return new Outcome(report(modelShown, List.of()), null, List.of(Text.line(e.toString())), e.getCause(), ExitCodes.INPUT_ERROR);
        } catch (RuntimeException | StackOverflowError | LinkageError e) {
            return new Outcome(report(modelShown, List.of()), null, List.of(Text.line(modelShown
                    + ": error: internal error while generating (a defect in RsaML, please report it): " + e)), e, ExitCodes.INPUT_ERROR);
        }
    }

    private static Report report(String modelShown, List<Finding> findings) {
        return new Report(Rules.all(), List.of(FileResult.of(modelShown, findings, 0)), Severity.ERROR);
    }
}
