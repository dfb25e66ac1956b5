/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.ExpectedFinding;
import org.junit.jupiter.api.io.TempDir;

/** The runnable jar and the ./rsaml launcher, as separate processes, the way CI and people call them. */
class ProcessTest {

    @Test
    void runnableJarValidatesTheExamples() throws Exception {
        Cli.Result r = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "examples/"));
        assertEquals(1, r.code(), r::toString);
        List<String> lines = r.outLines();
        assertEquals(ValidateCommandTest.EXAMPLES_FINDINGS, ValidateCommandTest.findingLines(lines), r::toString);
        assertEquals(ValidateCommandTest.EXAMPLES_CLEAN, ValidateCommandTest.cleanLines(lines), r::toString);
        assertEquals("", r.err());
    }

    @Test
    void runnableJarExitCodes() throws Exception {
        assertEquals(0, Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "examples/exp1-hybrid.rsaml")).code());
        Cli.Result usage = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "--format"));
        assertEquals(2, usage.code(), usage::toString);
        Cli.Result missing = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "nowhere.rsaml"));
        assertEquals(2, missing.code(), missing::toString);
        assertEquals("nowhere.rsaml: error: no such file or directory", missing.outLines().get(0));
        BadInputTest.assertNoStackTrace(missing);
    }

    @Test
    void emfMessagesSurviveInTheRunnableJar() throws Exception {
        // EMF reads its messages from plugin.properties at the jar's root; the runnable jar merges them.
        Cli.Result r = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate",
                "tests/org.rsaml.validation.tests/resources/rules/rule-RSA-00-violated.rsaml"));
        assertEquals(1, r.code(), r::toString);
        assertTrue(r.out().contains("error RSA-00: The required feature 'target' of 'Connection 'robot/s0 -> <none>'' must be set"), r::toString);
    }

    @Test
    void launcherAtTheRepositoryRoot() throws Exception {
        assertTrue(Files.isExecutable(Cli.ROOT.resolve("rsaml")), "./rsaml is executable");
        Cli.Result r = Cli.process(Cli.ROOT, List.of("./rsaml", "validate", "examples/"));
        assertEquals(1, r.code(), r::toString);
        for (String finding : ValidateCommandTest.EXAMPLES_FINDINGS) {
            assertTrue(r.out().contains(finding + "\n"), () -> "the launcher prints " + finding + "\n" + r);
        }
        assertTrue(r.out().endsWith(ValidateCommandTest.examplesSummary() + "\n"), r::toString);
        // A second run uses the class-data archive the first one left; the result is the same.
        Cli.Result again = Cli.process(Cli.ROOT, List.of("./rsaml", "validate", "--format", "json", "examples/exp2-defects.rsaml"));
        assertEquals(1, again.code(), again::toString);
        assertEquals("", again.err(), "nothing but the report, no JVM warnings");
        for (ExpectedFinding e : ValidateCommandTest.exp2()) {
            assertTrue(again.out().contains("\"ruleId\": \"" + e.ruleId() + "\""), () -> "the JSON report has " + e.what() + "\n" + again);
        }
    }

    @Test
    void launcherSymlinkedOntoThePathRunsFromAnotherDirectory(@TempDir Path dir) throws Exception {
        // As after 'ln -s ~/rsaml/rsaml ~/bin/rsaml': a link to a link, called from elsewhere.
        Path bin = Files.createDirectories(dir.resolve("bin"));
        Path tools = Files.createDirectories(dir.resolve("tools"));
        Files.createSymbolicLink(tools.resolve("rsaml"), Cli.ROOT.resolve("rsaml"));
        Files.createSymbolicLink(bin.resolve("rsaml"), Path.of("../tools/rsaml"));
        Path work = Files.createDirectories(dir.resolve("work"));
        Files.copy(Cli.ROOT.resolve("examples/exp2-defects.rsaml"), work.resolve("model.rsaml"));

        Cli.Result r = Cli.process(work, List.of(bin.resolve("rsaml").toString(), "validate", "model.rsaml"));
        // The link out of the temporary folder goes now, so JUnit need not warn about it.
        Files.delete(tools.resolve("rsaml"));
        assertEquals(1, r.code(), r::toString);
        assertTrue(r.out().startsWith("model.rsaml:"), r::toString);
        assertTrue(r.out().endsWith(ValidateCommandTest.exp2Summary() + "\n"), r::toString);
        assertEquals("", r.err(), "no first-use build: the launcher found its jar");
    }
}
