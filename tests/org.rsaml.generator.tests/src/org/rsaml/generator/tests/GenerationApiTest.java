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
        assertEquals(Target.CPP, Target.parse("cpp"), "--target cpp names the C++ target");
        assertEquals(Target.ROS2, Target.parse(" ROS2 "), "target names are read case-insensitively and trimmed");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Target.parse("java"), "an unknown target is refused");
        assertEquals("unknown target 'java'; the targets are cpp, ros2", e.getMessage(), "the refusal names the unknown target and lists the known ones");
    }

    @Test
    void modelWithErrorsIsRefusedAndNothingIsWritten(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        GenerationRefusedException e = assertThrows(GenerationRefusedException.class,
                () -> generator.generate(Tools.example("exp2-defects.rsaml"), Target.CPP, out, false), "a model with errors is refused unless forced");
        List<ExpectedFinding> expected = ExpectedFinding.of(Tools.example("exp2-defects.rsaml")).stream()
                .filter(x -> x.severity().equals("error")).toList();
        assertEquals(expected.stream().map(ExpectedFinding::what).sorted().toList(),
                e.errors().stream().map(f -> f.ruleId() + " " + f.severity().label() + " " + f.qualifiedName()).sorted().toList(),
                "the refusal carries the errors the model states");
        assertTrue(e.getMessage().contains(expected.size() + " errors"), e.getMessage());
        assertTrue(e.file().endsWith("exp2-defects.rsaml"), "the refusal names the model file: " + e.file());
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
                + "the ports carry different data (numeric data vs alphanumeric data)"), r.warnings(), "forced, the one connection between different data types is left out with a warning saying why");
        // And the rest still builds and runs.
        Path exe = Tools.cmakeBuild(out, CppExamplesTest.executableName(out));
        new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", "100")).durationMs();
    }

    @Test
    void unreadableModelIsAnErrorNamingTheFile(@TempDir Path tmp) {
        Path missing = tmp.resolve("nowhere.rsaml");
        GenerationException e = assertThrows(GenerationException.class, () -> generator.generate(missing, Target.CPP, tmp.resolve("out"), false), "a missing model is an error, not a stack trace");
        assertEquals(missing.toString(), e.file(), "the error names the missing file");
        assertEquals(missing + ": error: no such file", e.toString(), "the error prints in compiler style: file: error: what");
    }

    @Test
    void outputPathThatIsAFileIsRefused(@TempDir Path tmp) throws Exception {
        Path out = Files.writeString(tmp.resolve("out"), "mine");
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false), "an output path that is a file is refused");
        assertEquals(out.toString(), e.file(), "the error names the output path");
        assertEquals("the output path is a file, not a directory", e.getMessage(), "the error says what is wrong with the output path");
        assertEquals("mine", Files.readString(out), "the user's file at the output path is left untouched");
    }

    @Test
    void userFileWhereAGeneratedFileGoesStopsEverything(@TempDir Path tmp) throws Exception {
        Path out = Files.createDirectories(tmp.resolve("out"));
        Files.writeString(out.resolve("CMakeLists.txt"), "# my own build\n");
        Map<String, byte[]> before = Tools.snapshot(tmp);
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false), "a user's file where a generated file goes stops the generation");
        assertEquals(out.resolve("CMakeLists.txt").toString(), e.file(), "the error names the user's file");
        assertTrue(e.getMessage().contains("was not generated by RsaML"), e.getMessage());
        assertTrue(Tools.sameFiles(before, Tools.snapshot(tmp)), "nothing may be written, nor left beside the output");
    }

    @Test
    void fileWhereADirectoryIsNeededStopsEverything(@TempDir Path tmp) throws Exception {
        Path out = Files.createDirectories(tmp.resolve("out"));
        Files.writeString(out.resolve("gen"), "not a directory");
        Map<String, byte[]> before = Tools.snapshot(tmp);
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false), "a file where a generated directory goes stops the generation");
        assertEquals(out.resolve("gen").toString(), e.file(), "the error names the file in the way");
        assertTrue(Tools.sameFiles(before, Tools.snapshot(tmp)), "nothing may be written, nor left beside the output");
        try (Stream<Path> left = Files.list(tmp)) {
            assertEquals(List.of(out), left.toList(), "no temporary directory may be left beside the output");
        }
    }

    @Test
    void outputThatCannotBeCreatedIsAnError() {
        // /proc refuses new directories even to root, so this holds whoever runs the tests.
        Path out = Path.of("/proc/rsaml-generator-test/out");
        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false), "an output directory that cannot be created is an error");
        assertEquals(out.toString(), e.file(), "the error names the output directory");
        assertFalse(Files.exists(out), "nothing is created");
    }

    @Test
    void resultListsWhatWasWrittenKeptAndLeftAlone(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        GenerationResult first = generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false);
        assertEquals(out.toAbsolutePath(), first.outputDirectory(), "the result names the absolute output directory");
        assertTrue(first.written().containsAll(List.of(Path.of("gen/motion_control/MotionControllerBase.hpp"),
                Path.of("src/motion_control/MotionController.cpp"), Path.of("src/msg/MotionInstruction.hpp"))), first.written()::toString);
        assertTrue(first.unchanged().isEmpty() && first.preserved().isEmpty() && first.deleted().isEmpty(), "a first generation only writes: " + first.unchanged() + " unchanged, " + first.preserved() + " preserved, " + first.deleted() + " deleted");

        GenerationResult second = generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false);
        assertEquals(List.of(), second.written(), "generating the same model again rewrites nothing");
        assertTrue(second.preserved().contains(Path.of("src/motion_control/MotionController.cpp")), "the user's implementation file is preserved: " + second.preserved());
        assertTrue(second.unchanged().contains(Path.of("gen/motion_control/MotionControllerBase.hpp")), "the generated base class is reported unchanged: " + second.unchanged());
        assertEquals(first.written().size(), second.unchanged().size() + second.preserved().size(), "every file written the first time is reported unchanged or preserved the second time");
    }
}
