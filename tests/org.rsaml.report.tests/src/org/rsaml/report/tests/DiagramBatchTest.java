/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.TimingMode;
import org.rsaml.report.DiagramBatch;
import org.rsaml.report.ExitCodes;
import org.rsaml.report.ModelFiles;
import org.rsaml.tests.support.ChainModels;
import org.rsaml.tests.support.TestRepository;

/** What {@code rsaml diagram} and the diagram goal run: the clash check first, then every model, view and format. */
class DiagramBatchTest {

    private static final DiagramBatch BOTH_VIEWS = new DiagramBatch(List.of(DiagramView.ARCHITECTURE, DiagramView.MISSION),
            List.of(DiagramFormat.SVG, DiagramFormat.HTML), TimingMode.AUTO);

    /** What a front end is told, in order. */
    private static final class Heard implements DiagramBatch.Listener {
        final List<Path> written = new ArrayList<>();
        final List<String> failures = new ArrayList<>();

        @Override
        public void written(Path file) {
            written.add(file);
        }

        @Override
        public void failed(List<String> lines, Throwable cause) {
            failures.addAll(lines);
        }
    }

    @Test
    void twoModelsThatWouldWriteOneFileAreNamedBeforeAnythingIsDrawn(@TempDir Path dir) throws Exception {
        Files.createDirectories(dir.resolve("a"));
        Files.createDirectories(dir.resolve("b"));
        Files.copy(TestRepository.example("exp1-hybrid.rsaml"), dir.resolve("a/robot.rsaml"));
        Files.copy(TestRepository.example("exp1-hybrid.rsaml"), dir.resolve("b/robot.rsaml"));
        List<ModelFiles.Input> inputs = ModelFiles.select(dir, List.of(Path.of("a"), Path.of("b")));

        Optional<String> clash = BOTH_VIEWS.clash(inputs, Path.of("out"));

        assertEquals(Optional.of("a/robot.rsaml and b/robot.rsaml would both be drawn to out/robot-architecture.svg"), clash,
                "the first clash names both models and the file, in the directory as the user spelt it");
        assertFalse(Files.exists(dir.resolve("out")), "checking for clashes writes nothing");
    }

    @Test
    void aFileWhereTheDirectoryShouldBeAndAClashAreRefusedWithWhatToDo(@TempDir Path dir) throws Exception {
        Files.copy(TestRepository.example("exp1-hybrid.rsaml"), dir.resolve("robot.rsaml"));
        Files.writeString(dir.resolve("out"), "mine");
        List<ModelFiles.Input> inputs = ModelFiles.select(dir, List.of(Path.of("robot.rsaml")));

        assertEquals(Optional.of("out is a file; name the directory the diagrams are written to"),
                BOTH_VIEWS.refusal(inputs, dir.resolve("out"), Path.of("out")), "a file is not drawn into");
        assertEquals("mine", Files.readString(dir.resolve("out")), "the file is left as it was");
        assertEquals(Optional.empty(), BOTH_VIEWS.refusal(inputs, dir.resolve("diagrams"), Path.of("diagrams")),
                "a directory still to be made is fine");
        List<ModelFiles.Input> twice = List.of(inputs.get(0), inputs.get(0));
        assertEquals(Optional.of("robot.rsaml and robot.rsaml would both be drawn to diagrams/robot-architecture.svg; draw them into different directories"),
                BOTH_VIEWS.refusal(twice, dir.resolve("diagrams"), Path.of("diagrams")), "a clash is refused with what to do");
    }

    @Test
    void everyModelIsDrawnInEveryViewAndFormatAndAFailingOneCostsOnlyItself(@TempDir Path dir) throws Exception {
        Files.copy(TestRepository.example("exp1-hybrid.rsaml"), dir.resolve("hybrid.rsaml"));
        Files.writeString(dir.resolve("broken.rsaml"), "<not a model");
        List<ModelFiles.Input> inputs = ModelFiles.select(dir, List.of(Path.of("broken.rsaml"), Path.of("hybrid.rsaml"),
                Path.of("missing.rsaml")));
        assertEquals(Optional.empty(), BOTH_VIEWS.clash(inputs, Path.of("out")), "models with different names do not clash");
        Heard heard = new Heard();

        DiagramBatch.Outcome outcome = BOTH_VIEWS.draw(inputs, dir.resolve("out"), heard);

        assertEquals(2, outcome.failed(), "the unparsable and the missing model fail: " + heard.failures);
        assertEquals(ExitCodes.INPUT_ERROR, outcome.exitCode(), "rsaml diagram exits with 2 when a model could not be drawn");
        assertEquals("could not draw 2 models; see the errors above", outcome.failure(), "what the diagram goal fails the build with");
        assertTrue(heard.failures.stream().anyMatch(l -> l.startsWith("broken.rsaml:")), "the unparsable model is named: " + heard.failures);
        assertTrue(heard.failures.stream().anyMatch(l -> l.startsWith("missing.rsaml:")), "the missing model is named: " + heard.failures);
        List<String> names = heard.written.stream().map(p -> p.getFileName().toString()).sorted().toList();
        assertEquals(List.of("hybrid-architecture.html", "hybrid-architecture.svg", "hybrid-mission.html", "hybrid-mission.svg"), names,
                "the readable model is drawn in both views and both formats, after the model that failed");
        for (Path file : heard.written) {
            assertEquals(dir.resolve("out"), file.getParent(), "every diagram goes into the directory asked for");
            assertTrue(Files.size(file) > 0, file + " is written");
        }
    }

    @Test
    void aModelTooDeepToLayOutIsNamedWithWhatToDoAndTheNextModelIsStillDrawn(@TempDir Path dir) throws Exception {
        // A chain of 2,500 modules recurses past the 1 MiB stack asked for here (it is drawn with the stack sized for it).
        ChainModels.write(dir.resolve("chain.rsaml"), 2_500, false);
        Files.copy(TestRepository.example("exp1-hybrid.rsaml"), dir.resolve("hybrid.rsaml"));
        List<ModelFiles.Input> inputs = ModelFiles.select(dir, List.of(Path.of("chain.rsaml"), Path.of("hybrid.rsaml")));
        DiagramBatch architecture = new DiagramBatch(List.of(DiagramView.ARCHITECTURE), List.of(DiagramFormat.SVG), TimingMode.AUTO);
        Heard heard = new Heard();

        DiagramBatch.Outcome outcome;
        System.setProperty("rsaml.diagram.stackMiB", "1");
        try {
            outcome = architecture.draw(inputs, dir.resolve("out"), heard);
        } finally {
            System.clearProperty("rsaml.diagram.stackMiB");
        }

        assertEquals(1, outcome.failed(), "only the chain fails: " + heard.failures);
        assertEquals(ExitCodes.INPUT_ERROR, outcome.exitCode(), "rsaml diagram exits with 2, not with the code of findings");
        assertEquals(1, heard.failures.size(), "one line says what went wrong: " + heard.failures);
        String failure = heard.failures.get(0);
        assertTrue(failure.startsWith("chain.rsaml: error: too deep to lay out: "), "the model is named and the failure said: " + failure);
        assertTrue(failure.contains("-Drsaml.diagram.stackMiB=64"), "the line says how to draw it anyway: " + failure);
        assertFalse(failure.contains("\tat "), "no stack trace: " + failure);
        assertEquals(List.of(dir.resolve("out/hybrid-architecture.svg")), heard.written, "the model after the deep one is still drawn");
        assertFalse(Files.exists(dir.resolve("out/chain-architecture.svg")), "nothing half-drawn is left of the deep model");
    }
}
