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
    /** The timing finding of the example whose latency requirement can be missed, as validate prints it. */
    static final String MISSED_LATENCY = missedLatency();

    static final List<String> EXP2_FINDINGS = exp2().stream().map(e -> "examples/exp2-defects.rsaml:" + e.line() + ":"
            + e.column() + ": " + e.severity() + " " + e.ruleId() + ": " + e.message()).toList();

    /** What validating the examples directory prints before its summary: exp2's findings, then the missed latency. */
    static final List<String> EXAMPLES_FINDINGS = java.util.stream.Stream.concat(EXP2_FINDINGS.stream(),
            java.util.stream.Stream.of(MISSED_LATENCY)).toList();

    /** The example models, as the command line names them ({@code examples/x.rsaml}), in the order it checks them. */
    static List<String> exampleModels() {
        try (java.util.stream.Stream<Path> files = Files.list(Cli.ROOT.resolve("examples"))) {
            return files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted()
                    .map(n -> "examples/" + n).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * The examples without findings, each named on a line of its own in the text report: every example but exp2 and the
     * one whose latency requirement can be missed.
     */
    static final List<String> EXAMPLES_CLEAN = exampleModels().stream()
            .filter(m -> !m.equals("examples/exp2-defects.rsaml") && !MISSED_LATENCY.startsWith(m + ":"))
            .map(m -> m + ": no findings").toList();

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

    /** The finding the missed-latency example states in its expect comment, as validate prints it. */
    private static String missedLatency() {
        try {
            List<ExpectedFinding> expected = ExpectedFinding.of(Cli.ROOT.resolve("examples/mobile-base-latency-missed.rsaml"));
            assertEquals(1, expected.size(), "mobile-base-latency-missed.rsaml states its one finding");
            ExpectedFinding e = expected.get(0);
            return "examples/mobile-base-latency-missed.rsaml:" + e.line() + ":" + e.column() + ": " + e.severity() + " " + e.ruleId()
                    + ": " + e.message();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
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
        Cli.Result r = Cli.run("validate", "examples/exp1-hybrid.rsaml", "examples/exp2-defects.rsaml");
        assertEquals(1, r.code(), r::toString);
        List<String> lines = r.outLines();
        assertEquals("examples/exp1-hybrid.rsaml: no findings", lines.get(0), r::toString);
        assertEquals(EXP2_FINDINGS, lines.subList(1, lines.size() - 1), r::toString);
        assertEquals(summary(2, exp2()), lines.get(lines.size() - 1), "both files are counted, exp2's findings with them");

        Cli.Result quiet = Cli.run("validate", "--quiet", "examples/exp1-hybrid.rsaml");
        assertEquals(0, quiet.code(), quiet::toString);
        assertEquals("", quiet.out(), "--quiet prints only what fails the run");

        // The structured formats of a file without findings stay well formed.
        Cli.Result sarif = Cli.run("validate", "--format", "sarif", "examples/exp1-hybrid.rsaml");
        assertEquals(java.util.Set.of(), ReportFormatsTest.sarifProblems(sarif.out()), sarif.out());
        Cli.Result json = Cli.run("validate", "--format", "json", "examples/exp1-hybrid.rsaml");
        assertEquals(0, com.google.gson.JsonParser.parseString(json.out()).getAsJsonObject().getAsJsonObject("summary")
                .get("exitCode").getAsInt(), json.out());
        Cli.Result junit = Cli.run("validate", "--format", "junit", "examples/exp1-hybrid.rsaml");
        assertTrue(junit.out().startsWith("<?xml") && junit.out().contains("failures=\"0\""), junit.out());
    }

    @Test
    void cleanModelExitsZero() {
        Cli.Result r = Cli.run("validate", "examples/exp1-hybrid.rsaml", "examples/exp3-task-interpreter.rsaml");
        assertEquals(0, r.code(), r::toString);
        assertEquals(List.of("examples/exp1-hybrid.rsaml: no findings", "examples/exp3-task-interpreter.rsaml: no findings",
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
        List<String> expected = new java.util.ArrayList<>(EXP2_FINDINGS);
        expected.add(exp2Summary());
        assertEquals(expected, errors.outLines(), "one line per stated finding of exp2, then the summary");
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
        assertEquals("exp1-hybrid.rsaml: no findings", r.outLines().get(0), r::toString);

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
