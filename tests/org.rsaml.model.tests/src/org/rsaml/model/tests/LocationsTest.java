/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.rsaml.model.tests.XmiFiles.errors;
import static org.rsaml.model.tests.XmiFiles.model;
import static org.rsaml.model.tests.XmiFiles.open;
import static org.rsaml.model.tests.XmiFiles.write;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.resource.SourceLocation;

/**
 * Every loaded element and every error is placed at the line and column a user sees in an editor, whatever the
 * file's line ends and encoding.
 */
class LocationsTest {

    @TempDir
    Path dir;

    @Test
    void elementsAreLocatedAtTheirStartTags() throws Exception {
        Path file = write(dir, "m.rsaml", model("  <layers name=\"a\">\n    <!-- c --><modules name=\"m\"/>\n  </layers>\n"));
        RsamlResource r = (RsamlResource) open(file);
        assertEquals("", errors(r), "the model loads without errors");
        Architecture a = (Architecture) r.getContents().get(0);
        assertEquals(new SourceLocation(file.toString(), 2, 1), r.locate(a), "the architecture is located at its start tag (line 2, column 1)");
        assertEquals(new SourceLocation(file.toString(), 3, 3), r.locate(a.getLayers().get(0)), "the layer is located at its start tag (line 3, column 3)");
        assertEquals(new SourceLocation(file.toString(), 4, 15), r.locate(a.getLayers().get(0).getModules().get(0)), "the module is located at its start tag, after the comment on its line (line 4, column 15)");
    }

    @Test
    void everyLoadedElementHasAPosition() throws Exception {
        Path file = write(dir, "all.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\"/>\n  </layers>\n"));
        RsamlResource r = (RsamlResource) open(file);
        for (var it = EcoreUtil.<EObject>getAllContents(r, false); it.hasNext();) {
            EObject o = it.next();
            assertTrue(r.locate(o).line() > 0, o.toString());
        }
        assertNotNull(r.locate(r.getContents().get(0)), "the root element has a position");
    }

    /** The positions of the layers of {@code text}, computed by counting '\n' before each '<layers'. */
    static List<String> expectedLayerPositions(String text) {
        List<String> out = new ArrayList<>();
        for (int at = text.indexOf("<layers"); at >= 0; at = text.indexOf("<layers", at + 1)) {
            String before = text.substring(0, at);
            int line = (int) before.chars().filter(c -> c == '\n').count() + 1;
            out.add(line + ":" + (at - before.lastIndexOf('\n')));
        }
        return out;
    }

    static List<String> layerPositions(RsamlResource r) {
        return ((Architecture) r.getContents().get(0)).getLayers().stream().map(r::locate)
                .map(l -> l.line() + ":" + l.column()).toList();
    }

    static final String LINES = "<?xml version=\"VERSION\" encoding=\"UTF-8\"?>\n" + XmiFiles.ROOT + "\n  <layers name=\"a\"/>\n"
            + "  <layers name=\"b\" description=\"two\nlines\"/>\n\n    <layers name=\"c\"/>  <layers name=\"d\"/>\n"
            + "  <!-- a\ncomment --><layers name=\"e\"/>\n</rsaml:Architecture>\n";

    void assertLocatedWithLineEnd(String name, String version, String... ends) throws Exception {
        String template = LINES.replace("VERSION", version);
        StringBuilder text = new StringBuilder();
        int n = 0;
        for (char c : template.toCharArray()) {
            text.append(c == '\n' ? ends[n++ % ends.length] : String.valueOf(c));
        }
        Path file = dir.resolve(name + ".rsaml");
        Files.write(file, text.toString().getBytes(StandardCharsets.UTF_8));
        RsamlResource r = (RsamlResource) open(file);
        assertEquals("", errors(r), name);
        assertEquals(expectedLayerPositions(template), layerPositions(r), name);
        assertEquals(2, r.locate(r.getContents().get(0)).line(), name);
        // A line break inside an attribute value counts as one line, as the parser counts it.
        assertEquals("two lines", ((Architecture) r.getContents().get(0)).getLayers().get(1).getDescription().replace('\n', ' '), name + ": the attribute's line break is read as part of the value");
    }

    @Test
    void linesEndingInLineFeed() throws Exception {
        assertLocatedWithLineEnd("lf", "1.0", "\n");
    }

    @Test
    void linesEndingInCarriageReturnLineFeed() throws Exception {
        assertLocatedWithLineEnd("crlf", "1.0", "\r\n");
    }

    @Test
    void linesEndingInCarriageReturnOnly() throws Exception {
        assertLocatedWithLineEnd("cr", "1.0", "\r");
    }

    @Test
    void mixedLineEnds() throws Exception {
        assertLocatedWithLineEnd("mixed", "1.0", "\r", "\n", "\r\n", "\r\n", "\n", "\r");
    }

    @Test
    void nextLineAndLineSeparatorEndLinesInXml11() throws Exception {
        assertLocatedWithLineEnd("nel", "1.1", "\u0085", "\n", "\u2028", "\r\u0085");
    }

    @Test
    void utf16WithByteOrderMarkLoadsAndIsLocated() throws Exception {
        String template = LINES.replace("VERSION", "1.0").replace("UTF-8", "UTF-16");
        for (var charset : List.of(StandardCharsets.UTF_16LE, StandardCharsets.UTF_16BE)) {
            Path file = dir.resolve("utf16-" + charset.name() + ".rsaml");
            // Lone carriage returns too, which are two bytes wide here.
            Files.write(file, ("\uFEFF" + template.replace("\n", charset == StandardCharsets.UTF_16LE ? "\r" : "\r\n")).getBytes(charset));
            RsamlResource r = (RsamlResource) open(file);
            assertEquals("", errors(r), charset.name());
            assertEquals(expectedLayerPositions(template), layerPositions(r), charset.name());
        }
    }

    @Test
    void utf8ByteOrderMarkTakesNoColumn() throws Exception {
        String text = XmiFiles.ROOT + "<layers name=\"a\"/></rsaml:Architecture>";
        Path file = dir.resolve("bom.rsaml");
        Files.write(file, ("\uFEFF" + text).getBytes(StandardCharsets.UTF_8));
        RsamlResource r = (RsamlResource) open(file);
        assertEquals("", errors(r), "a file starting with a UTF-8 byte order mark loads without errors");
        assertEquals(1, r.locate(r.getContents().get(0)).column(), "the byte order mark takes no column: the root starts in column 1");
        assertEquals(List.of("1:" + (text.indexOf("<layers") + 1)), layerPositions(r), "the layer's column does not count the byte order mark");
    }

    @Test
    void multiByteCharacterAcrossAnyBufferBoundaryLoads() throws Exception {
        // A three-byte character at every offset around 8 KiB and 16 KiB.
        StringBuilder layers = new StringBuilder();
        String head = model("");
        int fill = 8192 - head.getBytes(StandardCharsets.UTF_8).length - 40;
        for (int i = 0; i < 12; i++) {
            layers.append("  <layers name=\"l").append(i).append("\" description=\"").append("x".repeat(i == 0 ? fill : 700 + i))
                    .append("\u20AC\u00E9\"/>\n");
        }
        Path file = write(dir, "big.rsaml", model(layers.toString()));
        Resource r = open(file);
        assertEquals("", errors(r), "a file with multi-byte characters across the read buffer's boundaries loads without errors");
        List<Layer> loaded = ((Architecture) r.getContents().get(0)).getLayers();
        assertEquals(12, loaded.size(), "all twelve layers are read");
        assertTrue(loaded.stream().allMatch(l -> l.getDescription().endsWith("\u20AC\u00E9")), "every description keeps its multi-byte characters");
    }

    @Test
    void invalidUtf8IsOneLocatedSentenceWithoutTheAbsolutePath() throws Exception {
        byte[] good = model("  <layers name=\"" + "a".repeat(9000) + "\"/>\n  <layers name=\"b\" description=\"X\"/>\n").getBytes(StandardCharsets.UTF_8);
        int x = new String(good, StandardCharsets.ISO_8859_1).lastIndexOf('X');
        good[x] = (byte) 0xff;
        Path file = dir.resolve("bad-utf8.rsaml");
        Files.write(file, good);
        Resource r = open(file);
        Resource.Diagnostic d = r.getErrors().get(0);
        assertTrue(d.getMessage().contains("not valid UTF-8"), d.getMessage());
        assertFalse(d.getMessage().contains(dir.toString()), d.getMessage());
        assertEquals(4, d.getLine(), "the invalid byte's line is named");
        assertTrue(d.getColumn() > 0, "the invalid byte's column is named");
    }

    @Test
    void unknownEncodingIsNamed() throws Exception {
        Path file = write(dir, "enc.rsaml", model("").replace("UTF-8", "klingon-1"));
        Resource r = open(file);
        assertEquals("1:1: the XML declaration names the encoding 'klingon-1', which is not known here; save the file as UTF-8"
                + " and declare encoding=\"UTF-8\"", errors(r), "the unknown encoding is named, at 1:1, with the fix");
    }
}
