/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code rsaml generate}: targets, refusal of invalid models, exit codes, user files kept. */
class GenerateCommandTest {

    @Test
    void cppProjectFromExperimentThreeAndAnIdleRegeneration(@TempDir Path dir) throws Exception {
        String model = Cli.ROOT.resolve("examples/exp3-task-interpreter.rsaml").toString();
        Cli.Result r = Cli.runIn(dir, "generate", "--target", "cpp", "-o", "out/exp3", model);
        assertEquals(0, r.code(), r::toString);
        assertTrue(Files.isRegularFile(dir.resolve("out/exp3/CMakeLists.txt")), r::toString);
        assertTrue(r.out().matches("(?s).*generated cpp into out/exp3: \\d+ written, 0 unchanged, 0 of yours kept\n"), r::toString);

        Path userFile;
        try (var files = Files.walk(dir.resolve("out/exp3/src"))) {
            userFile = files.filter(p -> p.toString().endsWith("MotionController.cpp")).findFirst().orElseThrow();
        }
        Files.writeString(userFile, Files.readString(userFile) + "\n// the architect's own code\n");
        Cli.Result again = Cli.runIn(dir, "generate", "-t", "cpp", "-o", "out/exp3", model);
        assertEquals(0, again.code(), again::toString);
        assertTrue(again.out().matches("(?s).*generated cpp into out/exp3: 0 written, \\d+ unchanged, [1-9]\\d* of yours kept\n"), again::toString);
        assertTrue(Files.readString(userFile).endsWith("// the architect's own code\n"), "the architect's own code is kept through a second generation");
    }

    @Test
    void ros2Packages(@TempDir Path dir) {
        Cli.Result r = Cli.runIn(dir, "generate", "--target", "ros2", "-o", "ros", Cli.ROOT.resolve("examples/exp3-task-interpreter.rsaml").toString());
        assertEquals(0, r.code(), r::toString);
        try (var files = Files.walk(dir.resolve("ros"))) {
            assertTrue(files.anyMatch(p -> p.getFileName().toString().equals("package.xml")), r::toString);
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void refusedFindingsComeThroughValidatesWritersInEveryFormat(@TempDir Path dir) {
        for (String format : List.of("json", "sarif", "junit")) {
            Cli.Result validate = Cli.run("validate", "--format", format, "examples/exp2-defects.rsaml");
            Cli.Result generate = Cli.run("generate", "--format", format, "-t", "cpp", "-o", dir.resolve(format).toString(),
                    "examples/exp2-defects.rsaml");
            assertEquals(1, generate.code(), generate::toString);
            // The same document; JUnit's time attribute is how long the check took, not a finding.
            assertEquals(validate.out().replaceAll(" time=\"[0-9.]+\"", ""), generate.out().replaceAll(" time=\"[0-9.]+\"", ""), format);
            assertTrue(generate.err().contains("generation refused"), generate::toString);
        }
    }

    @Test
    void aModelWithErrorsIsRefusedUnlessForced(@TempDir Path dir) {
        Cli.Result refused = Cli.runIn(Cli.ROOT, "generate", "-t", "cpp", "-o", dir.resolve("exp2").toString(), "examples/exp2-defects.rsaml");
        assertEquals(1, refused.code(), refused::toString);
        List<String> expected = new java.util.ArrayList<>(ValidateCommandTest.EXP2_FINDINGS);
        expected.add(ValidateCommandTest.exp2Summary());
        assertEquals(expected, refused.outLines(), "the same lines as rsaml validate");
        long errors = ValidateCommandTest.exp2().stream().filter(e -> e.severity().equals("error")).count();
        assertTrue(refused.err().startsWith("examples/exp2-defects.rsaml: error: generation refused: the model has " + errors
                + " error findings; fix them or generate anyway with --force"), refused::toString);
        assertFalse(Files.exists(dir.resolve("exp2")), "nothing is written for a refused model");

        Cli.Result forced = Cli.runIn(Cli.ROOT, "generate", "--force", "-t", "cpp", "-o", dir.resolve("exp2").toString(), "examples/exp2-defects.rsaml");
        assertEquals(0, forced.code(), forced::toString);
        assertTrue(Files.isRegularFile(dir.resolve("exp2/CMakeLists.txt")), "forcing generation over a model with findings writes the project");
    }

    @Test
    void badInputAndOutputExitTwo(@TempDir Path dir) throws Exception {
        Cli.Result missing = Cli.runIn(dir, "generate", "-t", "cpp", "-o", "out", "nowhere.rsaml");
        assertEquals(2, missing.code(), missing::toString);
        assertTrue(missing.err().startsWith("nowhere.rsaml: error: no such file"), missing::toString);

        Cli.Result malformed = Cli.runIn(Cli.INPUTS, "generate", "-t", "cpp", "-o", dir.resolve("m").toString(), "malformed.rsaml");
        assertEquals(2, malformed.code(), malformed::toString);
        assertTrue(malformed.err().startsWith("malformed.rsaml:6:5: error: malformed XML"), malformed::toString);

        Files.writeString(dir.resolve("taken"), "a file where the project should go");
        Cli.Result blocked = Cli.runIn(dir, "generate", "-t", "cpp", "-o", "taken", Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString());
        assertEquals(2, blocked.code(), blocked::toString);
        assertTrue(blocked.err().contains("taken"), blocked::toString);
        assertEquals("a file where the project should go", Files.readString(dir.resolve("taken")), "the file in the way of the project is left as it was");

        Cli.Result target = Cli.runIn(dir, "generate", "-t", "java", "-o", "x", Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString());
        assertEquals(2, target.code(), target::toString);
        assertTrue(target.err().contains("unknown target 'java'; the targets are cpp, ros2"), target::toString);
        for (Cli.Result r : new Cli.Result[] { missing, malformed, blocked, target }) {
            BadInputTest.assertNoStackTrace(r);
        }
        try (var listing = Files.list(dir)) {
            assertEquals(1, listing.count(), "nothing but the blocking file is left");
        }
    }
}
