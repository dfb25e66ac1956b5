/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.GenerationException;
import org.rsaml.generator.GenerationRefusedException;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;

/** The Java API the command line and the Maven plugin call: what it accepts, refuses and reports. */
class GenerationApiTest {

    final RsamlGenerator generator = new RsamlGenerator();

    @Test
    void targetsParseFromTheirNames() {
        assertEquals(Target.CPP, Target.parse("cpp"));
        assertEquals(Target.ROS2, Target.parse(" ROS2 "));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Target.parse("java"));
        assertEquals("unknown target 'java'; the targets are cpp, ros2", e.getMessage());
    }

    @Test
    void modelWithErrorsIsRefusedAndNothingIsWritten(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        GenerationRefusedException e = assertThrows(GenerationRefusedException.class,
                () -> generator.generate(Tools.example("exp2-defects.rsaml"), Target.CPP, out, false));
        List<ExpectedFinding> expected = ExpectedFinding.of(Tools.example("exp2-defects.rsaml")).stream()
                .filter(x -> x.severity().equals("error")).toList();
        assertEquals(expected.stream().map(ExpectedFinding::what).sorted().toList(),
                e.errors().stream().map(f -> f.ruleId() + " " + f.severity().label() + " " + f.qualifiedName()).sorted().toList(),
                "the refusal carries the errors the model states");
        assertTrue(e.getMessage().contains(expected.size() + " errors"), e.getMessage());
        assertTrue(e.file().endsWith("exp2-defects.rsaml"));
        assertFalse(Files.exists(out), "a refused generation must not create the output directory");
    }

    @Test
    void forceGeneratesAModelWithErrorsAndSaysWhatItLeftOut(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        GenerationResult r = generator.generate(Tools.example("exp2-defects.rsaml"), Target.CPP, out, true);
        assertEquals(ExpectedFinding.of(Tools.example("exp2-defects.rsaml")).stream().filter(x -> x.severity().equals("error")).count(),
                r.findings().stream().filter(f -> f.severity() == Severity.ERROR).count(), "forced, the result still carries the errors the model states");
        assertTrue(r.written().contains(Path.of("CMakeLists.txt")), "forced, the project is written: " + r.written());
        // RSA-02: the connection between a numeric and an alphanumeric port cannot be generated.
        assertEquals(List.of("connection control/resourceChecker.s0_ressourceCheck -> decision/proceduralExec.e0_prodExec is not generated: "
                + "the ports carry different data (numeric data vs alphanumeric data)"), r.warnings());
        // And the rest still builds and runs.
        Path exe = Tools.cmakeBuild(out, CppExamplesTest.executableName(out));
        new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", "100")).durationMs();
    }

    @Test
    void unreadableModelIsAnErrorNamingTheFile(@TempDir Path tmp) {
        Path missing = tmp.resolve("nowhere.rsaml");
        GenerationException e = assertThrows(GenerationException.class, () -> generator.generate(missing, Target.CPP, tmp.resolve("out"), false));
        assertEquals(missing.toString(), e.file());
        assertEquals(missing + ": error: no such file", e.toString());
    }

    @Test
    void outputPathThatIsAFileIsRefused(@TempDir Path tmp) throws Exception {
        Path out = Files.writeString(tmp.resolve("out"), "mine");
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false));
        assertEquals(out.toString(), e.file());
        assertEquals("the output path is a file, not a directory", e.getMessage());
        assertEquals("mine", Files.readString(out));
    }

    @Test
    void userFileWhereAGeneratedFileGoesStopsEverything(@TempDir Path tmp) throws Exception {
        Path out = Files.createDirectories(tmp.resolve("out"));
        Files.writeString(out.resolve("CMakeLists.txt"), "# my own build\n");
        Map<String, byte[]> before = Tools.snapshot(tmp);
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false));
        assertEquals(out.resolve("CMakeLists.txt").toString(), e.file());
        assertTrue(e.getMessage().contains("was not generated by RsaML"), e.getMessage());
        assertTrue(Tools.sameFiles(before, Tools.snapshot(tmp)), "nothing may be written, nor left beside the output");
    }

    @Test
    void fileWhereADirectoryIsNeededStopsEverything(@TempDir Path tmp) throws Exception {
        Path out = Files.createDirectories(tmp.resolve("out"));
        Files.writeString(out.resolve("gen"), "not a directory");
        Map<String, byte[]> before = Tools.snapshot(tmp);
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false));
        assertEquals(out.resolve("gen").toString(), e.file());
        assertTrue(Tools.sameFiles(before, Tools.snapshot(tmp)));
        try (Stream<Path> left = Files.list(tmp)) {
            assertEquals(List.of(out), left.toList(), "no temporary directory may be left beside the output");
        }
    }

    @Test
    void outputThatCannotBeCreatedIsAnError() {
        // /proc refuses new directories even to root, so this holds whoever runs the tests.
        Path out = Path.of("/proc/rsaml-generator-test/out");
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false));
        assertEquals(out.toString(), e.file());
        assertFalse(Files.exists(out));
    }

    @Test
    void resultListsWhatWasWrittenKeptAndLeftAlone(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        GenerationResult first = generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false);
        assertEquals(out.toAbsolutePath(), first.outputDirectory());
        assertTrue(first.written().containsAll(List.of(Path.of("gen/motion_control/MotionControllerBase.hpp"),
                Path.of("src/motion_control/MotionController.cpp"), Path.of("src/msg/MotionInstruction.hpp"))), first.written()::toString);
        assertTrue(first.unchanged().isEmpty() && first.preserved().isEmpty() && first.deleted().isEmpty());

        GenerationResult second = generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false);
        assertEquals(List.of(), second.written());
        assertTrue(second.preserved().contains(Path.of("src/motion_control/MotionController.cpp")));
        assertTrue(second.unchanged().contains(Path.of("gen/motion_control/MotionControllerBase.hpp")));
        assertEquals(first.written().size(), second.unchanged().size() + second.preserved().size());
    }
}
