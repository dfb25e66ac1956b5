/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * The architect's code in src/ survives regeneration when the model changes, and the project still
 * builds and runs with it; what the model no longer calls, or newly offers, is reported.
 */
class GenerationGapTest {

    static final String USER_ACTION = """
            void TaskInterpreter::parseTask() {
              trace("user: parsed task after instruction " + std::to_string(in_e1_taskInterpreter.value()));
            }""";

    static final String USER_FUNCTION = """

            void TaskInterpreter::interpretTask() {
              trace("user: interpretTask");
              parseTask();
            }
            """;

    @Test
    void userCodeSurvivesAddedPortAndRenamedFunction(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("exp3-task-interpreter.rsaml"), tmp.resolve("arm.rsaml"));
        Path out = tmp.resolve("out");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(model, Target.CPP, out, false);

        // The architect implements an action and overrides the function.
        Path cpp = out.resolve("src/interpretation/TaskInterpreter.cpp");
        Path hpp = out.resolve("src/interpretation/TaskInterpreter.hpp");
        String source = Files.readString(cpp);
        assertTrue(source.contains("void TaskInterpreter::parseTask() {}"), "the architect's implementation file starts with an empty body for each action");
        Files.writeString(cpp, source.replace("void TaskInterpreter::parseTask() {}", USER_ACTION)
                .replace("}  // namespace", USER_FUNCTION + "\n}  // namespace"));
        String header = Files.readString(hpp);
        assertTrue(header.contains("  void parseTask() override;"), "the architect's header does not declare the action with override:\n" + header);
        Files.writeString(hpp, header.replace("  void parseTask() override;", "  void parseTask() override;\n  void interpretTask();"));
        Map<String, byte[]> userFiles = userFiles(out);

        // The model changes: a new output port and a new entry port, connected; the function is renamed.
        String text = Files.readString(model).replace("interpretTask", "interpretProgram")
                .replace("messageType=\"MotionInstruction\"/>\n    </modules>",
                        "messageType=\"MotionInstruction\"/>\n      <ports xsi:type=\"rsaml:OutputPort\" name=\"s1_taskInterpreter\" dataType=\"boolean\"/>\n    </modules>")
                .replace("<ports xsi:type=\"rsaml:OutputPort\" name=\"s0_motionController\"",
                        "<ports xsi:type=\"rsaml:EntryPort\" name=\"e1_motionController\" dataType=\"boolean\"/>\n      <ports xsi:type=\"rsaml:OutputPort\" name=\"s0_motionController\"")
                .replace("  <sensors ", "  <connections source=\"//@layers[name='interpretation']/@modules[name='taskInterpreter']/@ports[name='s1_taskInterpreter']\" "
                        + "target=\"//@layers[name='motionControl']/@modules[name='motionController']/@ports[name='e1_motionController']\"/>\n  <sensors ");
        assertTrue(text.contains("s1_taskInterpreter") && text.contains("e1_motionController\" dataType"), "the model edit did not apply");
        Files.writeString(model, text);

        GenerationResult again = generator.generate(model, Target.CPP, out, false);
        assertTrue(Tools.sameFiles(userFiles, userFiles(out)), "the architect's files changed");
        assertTrue(again.preserved().containsAll(List.of(Path.of("src/interpretation/TaskInterpreter.cpp"),
                Path.of("src/interpretation/TaskInterpreter.hpp"))), "the architect's implementation and header are preserved on regeneration: " + again.preserved());
        assertTrue(again.written().contains(Path.of("gen/interpretation/TaskInterpreterBase.hpp")), "the generated base class is rewritten with the model's changes");
        String base = Files.readString(out.resolve("gen/interpretation/TaskInterpreterBase.hpp"));
        assertTrue(base.contains("virtual void interpretProgram();") && !base.contains("interpretTask"), "the base class calls the renamed function and no longer the old one");
        assertTrue(base.contains("::rsaml::Output<bool> out_s1_taskInterpreter;"), "the base class has the new output port");
        assertEquals(List.of(
                "src/motion_control/MotionController.hpp: new in the model: on_e1_motionController (the generated base class runs a default; "
                        + "declare and define it here to give it behaviour)",
                "src/interpretation/TaskInterpreter.hpp: interpretTask is no longer in the model, so the generated code does not call it any more; "
                        + "move the code to the renamed method or delete it"), again.warnings(), "regeneration warns about the new entry port's hook and the renamed function's orphaned code");

        // The project still builds with the architect's code, which still runs where the model still calls it.
        RunTrace trace = new RunTrace(Tools.ok(out, 60, Tools.cmakeBuild(out, "pick_and_place_arm").toString(), "--run-for-ms", "200"));
        assertTrue(trace.lines.stream().anyMatch(l -> l.startsWith("user: parsed task after instruction")), trace.output);
        assertTrue(trace.count("action interpretation/taskInterpreter.interpretProgram.parseTask") >= 2, trace.output);
        assertEquals(0, trace.count("user: interpretTask"), "the architect's orphaned method is no longer called");
        assertFalse(trace.received("motionControl/motionController.e1_motionController", "interpretation/taskInterpreter.s1_taskInterpreter", false).isEmpty(),
                "no data on the new connection:\n" + trace.output);
    }

    @Test
    void removedModuleLosesItsGeneratedFilesButNotTheArchitects(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("exp3-task-interpreter.rsaml"), tmp.resolve("arm.rsaml"));
        Path out = tmp.resolve("out");
        new RsamlGenerator().generate(model, Target.CPP, out, false);
        Files.writeString(model, Files.readString(model).replace("motionController", "motionCtl"));

        GenerationResult again = new RsamlGenerator().generate(model, Target.CPP, out, false);
        assertEquals(List.of(Path.of("gen/motion_control/MotionControllerBase.cpp"), Path.of("gen/motion_control/MotionControllerBase.hpp")),
                again.deleted(), "the removed module's generated files are deleted, and only those");
        assertTrue(Files.exists(out.resolve("src/motion_control/MotionController.cpp")), "the architect's file of the removed module is kept");
        assertTrue(again.written().contains(Path.of("src/motion_control/MotionCtl.cpp")), "the renamed module gets a new implementation file");
        assertTrue(again.warnings().contains("src/motion_control/MotionController.hpp: its module is no longer in the model; "
                + "your files for it are kept but no longer built"), again.warnings()::toString);
        assertFalse(Files.readString(out.resolve("CMakeLists.txt")).contains("MotionController.cpp"), "the kept file of the removed module is no longer built");
    }

    /**
     * The C++ project's README is the architect's (created once), and what a generation made of the
     * model is in GENERATED.md, regenerated every time, which the README links: after a module is
     * renamed, the README is as the architect left it and GENERATED.md names the module as it is now. A
     * README that does not link GENERATED.md (written by an earlier RsaML, or by hand) is kept and named
     * in a warning.
     */
    @Test
    void theCppReadmeIsTheArchitectsAndLinksTheRegeneratedFacts(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("exp3-task-interpreter.rsaml"), tmp.resolve("arm.rsaml"));
        Path out = tmp.resolve("out");
        GenerationResult first = new RsamlGenerator().generate(model, Target.CPP, out, false);
        Path readme = out.resolve("README.md");
        Path generated = out.resolve("GENERATED.md");
        assertTrue(Files.readString(readme).contains("[GENERATED.md](GENERATED.md)"), "the README links GENERATED.md:\n" + Files.readString(readme));
        assertTrue(first.warnings().stream().noneMatch(w -> w.startsWith("README.md")), "a new README links GENERATED.md: " + first.warnings());
        String facts = Files.readString(generated);
        assertTrue(facts.startsWith("<!-- Generated by RsaML") && facts.contains("`motion_control::MotionController` (`src/motion_control/MotionController.hpp`"),
                "GENERATED.md says it is regenerated and names each module's class and files:\n" + facts);
        Files.writeString(readme, Files.readString(readme) + "\nOur arm's notes.\n");
        String notes = Files.readString(readme);
        Files.writeString(model, Files.readString(model).replace("motionController", "motionCtl"));

        GenerationResult again = new RsamlGenerator().generate(model, Target.CPP, out, false);
        assertEquals(notes, Files.readString(readme), "the README is kept as the architect left it");
        facts = Files.readString(generated);
        assertTrue(facts.contains("`motion_control::MotionCtl`") && !facts.contains("MotionController"),
                "GENERATED.md names the renamed module as it is now, and no longer the old one:\n" + facts);
        assertTrue(again.written().contains(Path.of("GENERATED.md")), "GENERATED.md is rewritten: " + again.written());

        Files.writeString(readme, "# arm\n\nWritten by an earlier RsaML.\n");
        GenerationResult old = new RsamlGenerator().generate(model, Target.CPP, out, false);
        assertEquals(1, old.warnings().stream().filter(w -> w.startsWith("README.md") && w.contains("does not link GENERATED.md")).count(),
                "a README without the link is named: " + old.warnings());
        assertEquals("# arm\n\nWritten by an earlier RsaML.\n", Files.readString(readme), "and kept");
    }

    private static Map<String, byte[]> userFiles(Path out) throws Exception {
        return Tools.snapshot(out.resolve("src"));
    }
}
