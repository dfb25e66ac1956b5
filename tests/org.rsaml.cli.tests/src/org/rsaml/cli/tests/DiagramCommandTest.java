/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.tests.support.ExpectedFinding;

/** {@code rsaml diagram}: every example in both views and formats, the README's image, bad input. */
class DiagramCommandTest {

    /** The examples' names, read from the folder the command is given, so that an example added is drawn too. */
    private static List<String> examples() throws IOException {
        try (Stream<Path> files = Files.list(Cli.ROOT.resolve("examples"))) {
            return files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".rsaml"))
                    .map(n -> n.substring(0, n.length() - ".rsaml".length())).sorted().toList();
        }
    }

    @Test
    void everyExampleInEveryViewAndFormat(@TempDir Path dir) throws Exception {
        List<String> names = examples();
        assertFalse(names.isEmpty(), "the examples folder holds models to draw");
        for (String view : List.of("architecture", "mission")) {
            for (String format : List.of("svg", "html")) {
                Cli.Result r = Cli.runIn(Cli.ROOT, "diagram", "--view", view, "--format", format, "-o", dir.toString(), "examples/");
                assertEquals(0, r.code(), r::toString);
                for (String example : names) {
                    Path file = dir.resolve(example + "-" + view + "." + format);
                    assertTrue(r.outLines().contains("wrote " + file.toString().replace('\\', '/')), r::toString);
                    String text = Files.readString(file);
                    if (format.equals("svg")) {
                        var document = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());
                        assertEquals("svg", document.getDocumentElement().getTagName(), file.toString());
                    } else {
                        assertTrue(text.startsWith("<!DOCTYPE html>") && text.contains("<svg "), file.toString());
                    }
                    assertTrue(text.contains("data-view=\"" + view + "\""), file.toString());
                }
            }
        }
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(names.size() * 4, files.count(), "one file per model, view and format, no leftovers");
        }
    }

    @Test
    void theReadmeCommandGivesTheReadmeImage(@TempDir Path dir) throws Exception {
        // The README's image is written by this very command, into docs/images instead of dir.
        Cli.Result r = Cli.runIn(Cli.ROOT, "diagram", "-o", dir.toString(), "examples/exp1-hybrid.rsaml");
        assertEquals(0, r.code(), r::toString);
        assertEquals(Files.readString(Cli.ROOT.resolve("docs/images/exp1-hybrid-architecture.svg")),
                Files.readString(dir.resolve("exp1-hybrid-architecture.svg")),
                "docs/images/exp1-hybrid-architecture.svg is out of date: run ./rsaml diagram -o docs/images examples/exp1-hybrid.rsaml");
    }

    @Test
    void timingIsDrawnWhenTheModelAsksForItOrWhenAsked(@TempDir Path dir) throws Exception {
        String missed = Cli.ROOT.resolve("examples/mobile-base-latency-missed.rsaml").toString();
        String plain = Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString();
        Cli.Result auto = Cli.runIn(dir, "diagram", "-o", "auto", missed, plain);
        assertEquals(0, auto.code(), auto::toString);
        String drawn = Files.readString(dir.resolve("auto/mobile-base-latency-missed-architecture.svg"));
        assertTrue(drawn.contains("latency scanToWheels (reaction time at most 50 ms): worst 57 ms: MISSES"), "drawn by default: the model has processors");
        assertTrue(drawn.contains("class=\"el module latency-misses latency-path realtime\""), "the worst path is drawn");
        assertFalse(Files.readString(dir.resolve("auto/exp1-hybrid-architecture.svg")).contains("utilisation"), "no timing question, no timing");

        Cli.Result on = Cli.runIn(dir, "diagram", "--timing", "-o", "on", plain);
        assertEquals(0, on.code(), on::toString);
        assertTrue(Files.readString(dir.resolve("on/exp1-hybrid-architecture.svg")).contains("processor default (preemptive fixed priority): utilisation "),
                "the timing overlay shows the processor's utilisation");

        Cli.Result off = Cli.runIn(dir, "diagram", "--no-timing", "-o", "off", missed);
        assertEquals(0, off.code(), off::toString);
        String none = Files.readString(dir.resolve("off/mobile-base-latency-missed-architecture.svg"));
        assertFalse(none.contains("utilisation") || none.contains("latency-path\""), "--no-timing draws none");
    }

    @Test
    void theRunnableJarDrawsWithElksAlgorithms(@TempDir Path dir) throws Exception {
        Cli.Result r = Cli.process(dir, Cli.java(List.of(), "diagram", "--format", "html", "-o", "out",
                Cli.ROOT.resolve("examples/exp2-defects.rsaml").toString()));
        assertEquals(0, r.code(), r::toString);
        assertEquals(List.of("wrote out/exp2-defects-architecture.html"), r.outLines(), "the command says which diagram it wrote");
        String overBudget = ExpectedFinding.of(Cli.ROOT.resolve("examples/exp2-defects.rsaml")).stream()
                .filter(e -> e.ruleId().equals("RSA-08")).findFirst()
                .orElseThrow(() -> new AssertionError("exp2 states an RSA-08 finding")).qualifiedName();
        assertTrue(Files.readString(dir.resolve("out/exp2-defects-architecture.html")).contains("data-qname=\"" + overBudget + "\""),
                "the diagram shows exp2's module over its layer's budget, by its qualified name");
    }

    @Test
    void anUnreadableModelIsNamedAndTheOthersAreStillDrawn(@TempDir Path dir) throws Exception {
        Path broken = dir.resolve("broken.rsaml");
        Files.writeString(broken, "<?xml version=\"1.0\"?>\n<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml\"\n");
        Cli.Result r = Cli.runIn(dir, "diagram", "-o", "out", "broken.rsaml", Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString(),
                "missing.rsaml");
        assertEquals(2, r.code(), r::toString);
        assertTrue(r.err().startsWith("broken.rsaml:"), r::toString);
        assertTrue(r.err().contains("missing.rsaml: error: no such file or directory"), r::toString);
        assertFalse(r.err().contains("\tat "), "no stack trace");
        assertEquals(List.of("wrote out/exp1-hybrid-architecture.svg"), r.outLines(), "the command says which diagram it wrote");
        try (Stream<Path> files = Files.list(dir.resolve("out"))) {
            assertEquals(List.of("exp1-hybrid-architecture.svg"), files.map(p -> p.getFileName().toString()).toList(),
                    "nothing written for the broken model, no temporary file left");
        }
    }

    @Test
    void usageErrorsWriteNothing(@TempDir Path dir) throws Exception {
        String model = Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString();
        Cli.Result view = Cli.runIn(dir, "diagram", "--view", "deployment", "-o", "out", model);
        assertEquals(2, view.code(), view::toString);
        assertTrue(view.err().contains("'deployment' is not a view; it is one of architecture, mission"), view::toString);

        Cli.Result format = Cli.runIn(dir, "diagram", "--format", "png", "-o", "out", model);
        assertEquals(2, format.code(), format::toString);
        assertTrue(format.err().contains("'png' is not a format; it is one of svg, html"), format::toString);

        Files.writeString(dir.resolve("afile"), "mine");
        Cli.Result file = Cli.runIn(dir, "diagram", "-o", "afile", model);
        assertEquals(2, file.code(), file::toString);
        assertTrue(file.err().contains("afile is a file; name the directory the diagrams are written to"), file::toString);
        assertEquals("mine", Files.readString(dir.resolve("afile")), "the file in the way of the output directory is left as it was");

        Files.createDirectories(dir.resolve("a"));
        Files.createDirectories(dir.resolve("b"));
        Files.copy(Path.of(model), dir.resolve("a/robot.rsaml"));
        Files.copy(Path.of(model), dir.resolve("b/robot.rsaml"));
        Cli.Result same = Cli.runIn(dir, "diagram", "-o", "out", "a", "b");
        assertEquals(2, same.code(), same::toString);
        assertTrue(same.err().contains("a/robot.rsaml and b/robot.rsaml would both be drawn to out/robot-architecture.svg"), same::toString);
        assertFalse(Files.exists(dir.resolve("out")), "nothing written");
    }

    @Test
    void anUnwritableOutputIsNamed(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("afile"), "mine");
        Cli.Result r = Cli.runIn(dir, "diagram", "-o", "afile/diagrams", Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString());
        assertEquals(2, r.code(), r::toString);
        assertTrue(r.err().contains("afile/diagrams/exp1-hybrid-architecture.svg: cannot write the diagram"), r::toString);
        assertFalse(r.err().contains("\tat "), "no stack trace");
    }
}
