/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.tests.support.ExpectedFinding;

/** {@code rsaml validate} in text format: findings, summary, thresholds and exit codes. */
class ValidateCommandTest {

    /** Experiment 2's findings as {@code rsaml validate} prints them, from the expectations the model states. */
    static final List<String> EXP2_FINDINGS = printed("examples/exp2-defects.rsaml");

    /** Experiment 2's errors as {@code rsaml validate} prints them: its five defects, what fails the run (not its timing warning). */
    static final List<String> EXP2_ERRORS = exp2().stream().filter(e -> e.severity().equals("error"))
            .map(e -> printed("examples/exp2-defects.rsaml", e)).toList();

    /** What validating the examples directory prints before its summary: each example's stated findings, in the order of the files. */
    static final List<String> EXAMPLES_FINDINGS = exampleModels().stream().flatMap(m -> printed(m).stream()).toList();

    /** The example models, as the command line names them ({@code examples/x.rsaml}), in the order it checks them. */
    static List<String> exampleModels() {
        try (java.util.stream.Stream<Path> files = Files.list(Cli.ROOT.resolve("examples"))) {
            return files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted()
                    .map(n -> "examples/" + n).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The examples without findings, each named on a line of its own in the text report: those that state none. */
    static final List<String> EXAMPLES_CLEAN = exampleModels().stream().filter(m -> printed(m).isEmpty())
            .map(m -> m + ": no findings").toList();

    /** The findings {@code model} (as the command line names it, {@code examples/x.rsaml}) states, as validate prints them. */
    static List<String> printed(String model) {
        try {
            return ExpectedFinding.of(Cli.ROOT.resolve(model)).stream().map(e -> printed(model, e)).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String printed(String model, ExpectedFinding e) {
        return model + ":" + e.line() + ":" + e.column() + ": " + e.severity() + " " + e.ruleId() + ": " + e.message();
    }

    /** The lines of a text report but its summary, those of files without findings left out. */
    static List<String> findingLines(List<String> lines) {
        return lines.subList(0, lines.size() - 1).stream().filter(l -> !l.endsWith(": no findings")).toList();
    }

    /** The lines of a text report naming files without findings. */
    static List<String> cleanLines(List<String> lines) {
        return lines.stream().filter(l -> l.endsWith(": no findings")).toList();
    }

    /** The summary line of a text report on exp2 alone, counted from its expectations. */
    static String exp2Summary() {
        return summary(1, exp2());
    }

    /** The summary line of a text report on {@code files} files whose findings are {@code expected}. */
    static String summary(int files, List<ExpectedFinding> expected) {
        long errors = expected.stream().filter(e -> e.severity().equals("error")).count();
        long warnings = expected.stream().filter(e -> e.severity().equals("warning")).count();
        return files + (files == 1 ? " file" : " files") + " checked: " + errors + (errors == 1 ? " error, " : " errors, ") + warnings
                + (warnings == 1 ? " warning" : " warnings");
    }

    /** The summary line of a text report on the examples directory, from what each example states. */
    static String examplesSummary() {
        List<ExpectedFinding> expected = new java.util.ArrayList<>();
        for (String model : exampleModels()) {
            try {
                expected.addAll(ExpectedFinding.of(Cli.ROOT.resolve(model)));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return summary(exampleModels().size(), expected);
    }

    static List<ExpectedFinding> exp2() {
        try {
            List<ExpectedFinding> expected = ExpectedFinding.of(Cli.ROOT.resolve("examples/exp2-defects.rsaml"));
            assertFalse(expected.isEmpty(), "exp2-defects.rsaml states its findings in <!-- expect: --> comments");
            return expected;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void examplesDirectoryGivesThePaperFindingsAndFails() {
        Cli.Result r = Cli.run("validate", "examples/");
        assertEquals(1, r.code(), r::toString);
        List<String> lines = r.outLines();
        assertEquals(EXAMPLES_FINDINGS, findingLines(lines), r::toString);
        assertEquals(EXAMPLES_CLEAN, cleanLines(lines), r::toString);
        assertEquals(examplesSummary(), lines.get(lines.size() - 1), "the summary counts the examples and the findings they state");
        assertEquals("", r.err(), "a clean run writes nothing to standard error");
    }

    /** A file checked without findings is named, so that it cannot be taken for one that was never checked. */
    @Test
    void aFileWithoutFindingsIsNamedAsChecked() throws Exception {
        Cli.Result r = Cli.run("validate", "examples/exp3-task-interpreter.rsaml", "examples/exp2-defects.rsaml");
        assertEquals(1, r.code(), r::toString);
        List<String> lines = r.outLines();
        assertEquals("examples/exp3-task-interpreter.rsaml: no findings", lines.get(0), r::toString);
        assertEquals(EXP2_FINDINGS, lines.subList(1, lines.size() - 1), r::toString);
        assertEquals(summary(2, exp2()), lines.get(lines.size() - 1), "both files are counted, exp2's findings with them");

        Cli.Result quiet = Cli.run("validate", "--quiet", "examples/exp3-task-interpreter.rsaml");
        assertEquals(0, quiet.code(), quiet::toString);
        assertEquals("", quiet.out(), "--quiet prints only what fails the run");

        // The structured formats of a file without findings stay well formed.
        Cli.Result sarif = Cli.run("validate", "--format", "sarif", "examples/exp3-task-interpreter.rsaml");
        assertEquals(java.util.Set.of(), ReportFormatsTest.sarifProblems(sarif.out()), sarif.out());
        Cli.Result json = Cli.run("validate", "--format", "json", "examples/exp3-task-interpreter.rsaml");
        assertEquals(0, com.google.gson.JsonParser.parseString(json.out()).getAsJsonObject().getAsJsonObject("summary")
                .get("exitCode").getAsInt(), json.out());
        Cli.Result junit = Cli.run("validate", "--format", "junit", "examples/exp3-task-interpreter.rsaml");
        assertTrue(junit.out().startsWith("<?xml") && junit.out().contains("failures=\"0\""), junit.out());
    }

    @Test
    void cleanModelExitsZero() {
        Cli.Result r = Cli.run("validate", "examples/hierarchical-nasrem.rsaml", "examples/exp3-task-interpreter.rsaml");
        assertEquals(0, r.code(), r::toString);
        assertEquals(List.of("examples/hierarchical-nasrem.rsaml: no findings", "examples/exp3-task-interpreter.rsaml: no findings",
                "2 files checked: 0 errors, 0 warnings"), r.outLines(), "each clean model says it has no findings, then the summary");
    }

    @Test
    void warningsFailOnlyWhenAskedTo() {
        String model = Cli.INPUTS.resolve("warnings-only.rsaml").toString();
        Cli.Result byDefault = Cli.run("validate", model);
        assertEquals(0, byDefault.code(), byDefault::toString);
        assertTrue(byDefault.out().contains(":6:5: warning RSA-11: Module 'odometry' has a delay of 15.0 ms"), byDefault::toString);
        assertTrue(byDefault.out().endsWith("1 file checked: 0 errors, 1 warning\n"), byDefault::toString);

        Cli.Result strict = Cli.run("validate", "--fail-on", "warning", model);
        assertEquals(1, strict.code(), strict::toString);

        Cli.Result never = Cli.run("validate", "--fail-on", "never", "examples/exp2-defects.rsaml");
        assertEquals(0, never.code(), never::toString);
        assertEquals(EXP2_FINDINGS.size() + 1, never.outLines().size(), never::toString);
    }

    @Test
    void quietPrintsWhatFailsTheRunAndItsSummary() {
        Cli.Result warnings = Cli.run("validate", "--quiet", Cli.INPUTS.resolve("warnings-only.rsaml").toString());
        assertEquals(0, warnings.code(), warnings::toString);
        assertEquals("", warnings.out(), warnings::toString);

        Cli.Result errors = Cli.run("validate", "-q", "examples/exp2-defects.rsaml");
        assertEquals(1, errors.code(), errors::toString);
        List<String> expected = new java.util.ArrayList<>(EXP2_ERRORS);
        expected.add(exp2Summary());
        assertEquals(expected, errors.outLines(), "one line per stated error of exp2 (not its warning), then the summary");
    }

    @Test
    void quietWithFailOnWarningShowsTheWarningsThatFailTheRun() {
        Cli.Result r = Cli.run("validate", "--quiet", "--fail-on", "warning", Cli.INPUTS.resolve("warnings-only.rsaml").toString());
        assertEquals(1, r.code(), r::toString);
        List<String> lines = r.outLines();
        assertTrue(lines.size() >= 2, r::toString);
        assertTrue(lines.subList(0, lines.size() - 1).stream().allMatch(l -> l.contains(": warning RSA-")), r::toString);
        assertTrue(lines.get(lines.size() - 1).matches("1 file checked: 0 errors, [1-9]\\d* warnings?"), r::toString);
    }

    @Test
    void quietDoesNotEmptyAReportFile(@TempDir Path dir) throws Exception {
        Cli.Result r = Cli.run("validate", "--quiet", "--output", "text=" + dir.resolve("all.txt"),
                Cli.INPUTS.resolve("warnings-only.rsaml").toString());
        assertEquals(0, r.code(), r::toString);
        assertEquals("", r.out(), r::toString);
        String file = Files.readString(dir.resolve("all.txt"));
        assertTrue(file.contains(": warning RSA-"), file);
        assertTrue(file.contains("1 file checked"), file);
    }

    @Test
    void relativeNamesAreKeptAsTheUserWroteThem() {
        Cli.Result r = Cli.runIn(Cli.ROOT.resolve("examples"), "validate", ".");
        assertEquals(1, r.code(), r::toString);
        assertTrue(r.outLines().contains(EXP2_FINDINGS.get(0).substring("examples/".length())), r::toString);
        assertTrue(r.outLines().contains("exp3-task-interpreter.rsaml: no findings"), r::toString);

        Cli.Result spaced = Cli.runIn(Cli.INPUTS, "validate", "dir with space");
        assertEquals(0, spaced.code(), spaced::toString);
        assertEquals(List.of("dir with space/clean model.rsaml: no findings", "1 file checked: 0 errors, 0 warnings"), spaced.outLines(),
                "a folder and a file with spaces are named as given");
    }

    @Test
    void aFileNamedTwiceIsValidatedOnce() {
        Cli.Result r = Cli.run("validate", "examples/exp2-defects.rsaml", "examples", "./examples/exp2-defects.rsaml");
        assertEquals(1, r.code(), r::toString);
        assertEquals(EXAMPLES_FINDINGS.size() + EXAMPLES_CLEAN.size() + 1, r.outLines().size(), r::toString);
        assertTrue(r.out().contains(exampleModels().size() + " files checked"), r::toString);
    }

    @Test
    void usageErrorsExitTwoWithAHint() {
        for (String[] args : List.of(new String[] { "validate" }, new String[] { "validate", "--format", "pdf", "examples" },
                new String[] { "validate", "--fail-on", "sometimes", "examples" }, new String[] { "frobnicate" },
                new String[] { "validate", "--no-such-option", "examples" }, new String[] {},
                new String[] { "validate", "--output", "report.unknown", "examples" })) {
            Cli.Result r = Cli.run(args);
            assertEquals(2, r.code(), () -> String.join(" ", args) + "\n" + r);
            assertTrue(r.err().startsWith("rsaml: "), () -> String.join(" ", args) + "\n" + r);
            assertTrue(r.err().contains("--help"), () -> String.join(" ", args) + "\n" + r);
            assertFalse(r.err().contains("\tat "), r::toString);
            assertEquals("", r.out(), r::toString);
        }
    }
}
