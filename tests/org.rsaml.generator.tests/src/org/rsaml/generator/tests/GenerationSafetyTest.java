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

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.rsaml.generator.GenerationException;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * Generation never dies of an internal error nor emits code that overflows, never deletes through
 * a link or outside the output, and keeps the architect's files building when the architecture is
 * renamed.
 */
class GenerationSafetyTest {

    static final String FUNCTION_TIMING = "period=\"20.0\" delay=\"20.0\" execDuration=\"6.0\" execType=\"periodic\" schedPolicy=\"RM\"";

    /** Times the generated code cannot count are refused with a located message, forced or not, and nothing is written. */
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "period=\"Infinity\"|period Infinity ms of motionControl/motionController.executeInstructions is not a finite number",
            "period=\"1152921504607\"|period 1152921504607 ms of motionControl/motionController.executeInstructions is longer than generated code can count",
            "period=\"1e21\"|period 1.0E21 ms of motionControl/motionController.executeInstructions is longer than generated code can count",
            "period=\"1e-9\"|period 1.0E-9 ms of motionControl/motionController.executeInstructions is shorter than 1 ns",
            "period=\"20.0\" delay=\"-1\" execDuration=\"6.0\"|delay -1 ms of motionControl/motionController.executeInstructions is negative" })
    void unrepresentableTimesAreRefusedNotCrashedOn(String timing, String expected, @TempDir Path tmp) throws Exception {
        String text = Files.readString(Tools.example("exp3-task-interpreter.rsaml"));
        String edited = text.replace(FUNCTION_TIMING, timing.contains("delay") ? timing + " execType=\"periodic\" schedPolicy=\"RM\""
                : FUNCTION_TIMING.replace("period=\"20.0\"", timing));
        assertFalse(edited.equals(text), "the model edit did not apply");
        Path model = Files.writeString(tmp.resolve("arm.rsaml"), edited);
        Path out = tmp.resolve("out");
        for (Target target : List.of(Target.CPP, Target.ROS2)) {
            GenerationException e = assertThrows(GenerationException.class, () -> new RsamlGenerator().generate(model, target, out, true), target + ": an unrepresentable time is refused with a located error, not a crash");
            assertEquals(model.toString(), e.file(), target + ": the error names the model file");
            assertEquals(27, e.line(), "the message points at the function's start tag");
            if (timing.contains("Infinity") && !e.getMessage().startsWith("no code generated: ")) {
                assertTrue(e.getMessage().contains("Infinity"), e.getMessage()); // refused when loading: also fine
            } else {
                assertTrue(e.getMessage().startsWith("no code generated: " + expected), e.getMessage());
            }
            assertFalse(Files.exists(out), "nothing may be written");
        }
    }

    /**
     * The longest period the generated code can count (just under 2^60 ns, as period and delay)
     * builds under the undefined-behaviour sanitizer and runs: no overflow, no busy loop, one release;
     * and a run longer than the program's clock can count is refused.
     */
    @Test
    void longestCountablePeriodBuildsAndRuns(@TempDir Path tmp) throws Exception {
        String text = Files.readString(Tools.example("exp3-task-interpreter.rsaml"));
        String edited = text.replace(FUNCTION_TIMING, FUNCTION_TIMING.replace("period=\"20.0\" delay=\"20.0\"",
                "period=\"1152921504606\" delay=\"1152921504606\""));
        assertFalse(edited.equals(text), "the model edit did not apply");
        Path model = Files.writeString(tmp.resolve("arm.rsaml"), edited);
        Path out = tmp.resolve("out");
        new RsamlGenerator().generate(model, Target.CPP, out, true);
        Path exe = Tools.cmakeBuild(out, "pick_and_place_arm", "-fsanitize=undefined -fno-sanitize-recover=all");
        RunTrace trace = new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", "200"));
        assertEquals(1, trace.count("release motionControl/motionController.executeInstructions"), trace.output);
        assertFalse(trace.output.contains("runtime error"), trace.output);

        // A run longer than the clock can count is refused, not overflowed.
        Tools.Result tooLong = Tools.run(out, 60, exe.toString(), "--run-for-ms", "9223372036854775807");
        assertEquals(2, tooLong.exit(), tooLong.output());
        assertTrue(tooLong.output().contains("--run-for-ms needs a number of milliseconds from 0 to 1152921504606, not '9223372036854775807'"),
                tooLong.output());
    }

    /** A model name too long for a file name is refused with the file concerned, before anything is written. */
    @Test
    void fileNamesTooLongForTheFileSystemAreRefused(@TempDir Path tmp) throws Exception {
        String name = "m".repeat(300);
        Path model = Files.writeString(tmp.resolve("arm.rsaml"),
                Files.readString(Tools.example("exp3-task-interpreter.rsaml")).replace("taskInterpreter", name));
        Path out = tmp.resolve("out");
        for (Target target : List.of(Target.CPP, Target.ROS2)) {
            GenerationException e = assertThrows(GenerationException.class, () -> new RsamlGenerator().generate(model, target, out, true), target + ": a file name too long for the file system is refused before anything is written");
            assertTrue(e.file().startsWith(out.toString()) && e.file().contains(name.substring(1)), e.file());
            assertTrue(e.getMessage().matches("a file name made from a model name is 30\\d bytes long, more than the 255 file systems allow; "
                    + "shorten that name \\(nothing was written\\)"), e.getMessage());
            assertFalse(Files.exists(out), "nothing may be written");
        }
    }

    /** A crafted manifest and links in the output never make stale-file removal touch anything outside it. */
    @Test
    void staleRemovalNeverFollowsLinksNorLeavesTheOutput(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false);
        Path outside = Files.createDirectories(tmp.resolve("outside"));
        String generatedLooking = "// Generated by RsaML from architecture 'x'. Do not edit: regenerated on every run.\n";
        Path victim = Files.writeString(outside.resolve("victim.hpp"), generatedLooking);
        Path sibling = Files.writeString(tmp.resolve("sibling.hpp"), generatedLooking);
        Files.createSymbolicLink(out.resolve("gen/linked"), outside);
        Files.createSymbolicLink(out.resolve("gen/link.hpp"), victim);
        Path manifest = out.resolve(".rsaml-generated");
        Files.writeString(manifest, Files.readString(manifest) + "generated gen/linked/victim.hpp\ngenerated gen/link.hpp\n"
                + "generated ../sibling.hpp\ngenerated gen/../../sibling.hpp\ngenerated " + victim + "\ngenerated gen\\..\\..\\sibling.hpp\n"
                + "hooks ../sibling.hpp x\nkeep project ../../evil\n");

        GenerationResult again = generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false);
        assertEquals(List.of(), again.deleted(), "stale-file removal deletes nothing through links or outside the output");
        assertEquals(generatedLooking, Files.readString(victim), "the file outside the output, reached through a link, is untouched");
        assertEquals(generatedLooking, Files.readString(sibling), "the file beside the output, named by the crafted manifest, is untouched");
        assertTrue(Files.isSymbolicLink(out.resolve("gen/linked")) && Files.isSymbolicLink(out.resolve("gen/link.hpp")), "the links in the output are left as they are, not followed");
        String rewritten = Files.readString(manifest);
        assertFalse(rewritten.contains("victim") || rewritten.contains("sibling") || rewritten.contains("evil"), rewritten);
    }

    /** After a rename the project keeps its namespace, says so, and the architect's files still build and run. */
    @Test
    void renamedArchitectureKeepsTheArchitectsFilesBuilding(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("exp3-task-interpreter.rsaml"), tmp.resolve("arm.rsaml"));
        Path out = tmp.resolve("out");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(model, Target.CPP, out, false);
        Path cpp = out.resolve("src/interpretation/TaskInterpreter.cpp");
        Files.writeString(cpp, Files.readString(cpp).replace("void TaskInterpreter::parseTask() {}",
                "void TaskInterpreter::parseTask() { trace(\"user: parsed\"); }"));

        Files.writeString(model, Files.readString(model).replace("name=\"pickAndPlaceArm\"", "name=\"pickAndPlaceCell\""));
        GenerationResult again = generator.generate(model, Target.CPP, out, false);
        assertEquals(List.of("architecture 'pickAndPlaceCell' would be named pick_and_place_cell in code, but this output was generated as "
                + "pick_and_place_arm: the C++ namespace, the CMake project and the program keep the name pick_and_place_arm so that your "
                + "files keep building; to use pick_and_place_cell, generate into a new directory and move your code there"), again.warnings(), "regenerating a renamed architecture says the code keeps its old name, and how to take the new one");
        assertTrue(Files.readString(out.resolve("gen/Architecture.cpp")).contains("pickAndPlaceCell"), "the trace speaks the new name");
        RunTrace trace = new RunTrace(Tools.ok(out, 60, Tools.cmakeBuild(out, "pick_and_place_arm").toString(), "--run-for-ms", "100"));
        assertTrue(trace.lines.contains("run pickAndPlaceCell for 100 ms"), trace.output);
        assertTrue(trace.count("user: parsed") >= 1, trace.output);

        // A fresh output takes the new name.
        GenerationResult fresh = generator.generate(model, Target.CPP, tmp.resolve("fresh"), false);
        assertEquals(List.of(), fresh.warnings(), "a fresh output takes the new name without a warning");
        assertTrue(Files.readString(tmp.resolve("fresh/CMakeLists.txt")).contains("project(pick_and_place_cell "), "a fresh output's CMake project has the new name");
    }

    /** The ROS 2 package keeps its directory, so the architect's node files stay the ones built. */
    @Test
    void renamedArchitectureKeepsTheRosPackage(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("exp3-task-interpreter.rsaml"), tmp.resolve("arm.rsaml"));
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model, Target.ROS2, out, false);
        Files.writeString(model, Files.readString(model).replace("name=\"pickAndPlaceArm\"", "name=\"pickAndPlaceCell\""));
        GenerationResult again = new RsamlGenerator().generate(model, Target.ROS2, out, false);
        assertTrue(again.warnings().stream().anyMatch(w -> w.contains("the ROS package, the interfaces package and the C++ namespace "
                + "keep the name pick_and_place_arm")), again.warnings()::toString);
        assertTrue(again.preserved().contains(Path.of("pick_and_place_arm/src/interpretation/TaskInterpreter.cpp")), "the architect's node file in the kept package is preserved");
        assertFalse(Files.exists(out.resolve("pick_and_place_cell")), "no second package is created under the new name");
    }
}
