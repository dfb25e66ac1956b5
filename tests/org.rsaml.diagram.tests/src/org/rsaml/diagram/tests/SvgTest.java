/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/** The SVG files themselves: well-formed SVG, repeatable, the same as the one the README shows. */
class SvgTest {

    /** The SVG 1.1 elements the writer uses; anything else would be a mistake. */
    private static final Set<String> SVG_ELEMENTS = Set.of("svg", "title", "style", "defs", "linearGradient", "stop", "marker",
            "path", "g", "rect", "ellipse", "circle", "text");

    @ParameterizedTest(name = "{0}")
    @MethodSource("org.rsaml.diagram.tests.Examples#names")
    void wellFormedSvgOfKnownElementsWithResolvableReferences(String name) throws Exception {
        for (DiagramView view : DiagramView.values()) {
            String text = Examples.draw(name, view).svg();
            SvgDocument svg = new SvgDocument(text);
            Element root = svg.document.getDocumentElement();
            assertEquals(SvgDocument.SVG_NS, root.getNamespaceURI(), name + " " + view + ": the root is in the SVG namespace");
            assertEquals("svg", root.getLocalName(), name + " " + view + ": the root element is svg");
            NodeList all = root.getElementsByTagName("*");
            Set<String> ids = new java.util.HashSet<>();
            for (int i = 0; i < all.getLength(); i++) {
                Element e = (Element) all.item(i);
                assertEquals(SvgDocument.SVG_NS, e.getNamespaceURI(), e.getTagName());
                assertTrue(SVG_ELEMENTS.contains(e.getLocalName()), "unexpected element " + e.getLocalName());
                if (e.hasAttribute("id")) {
                    assertTrue(ids.add(e.getAttribute("id")), "duplicate id " + e.getAttribute("id"));
                }
            }
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("url\\(#([^)]+)\\)").matcher(text);
            while (m.find()) {
                assertTrue(ids.contains(m.group(1)), "url(#" + m.group(1) + ") names a defined element");
            }
            assertTrue(root.getAttribute("viewBox").matches("0 0 \\d+ \\d+"), name + " " + view + ": the viewBox starts at the origin and has whole-number size");
        }
    }

    @Test
    void sameModelSameBytesWithoutPathsOrDates(@TempDir Path dir) throws Exception {
        for (DiagramFormat format : DiagramFormat.values()) {
            Path first = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(TestRepository.example("exp2-defects.rsaml"), "examples/exp2-defects.rsaml",
                    format, dir.resolve("a"));
            Path second = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(TestRepository.example("exp2-defects.rsaml"), "examples/exp2-defects.rsaml",
                    format, dir.resolve("b"));
            assertEquals(Files.readString(first), Files.readString(second), "the same model gives the same " + format.id() + " bytes twice");
            String text = Files.readString(first);
            assertFalse(text.contains(TestRepository.root().toString()), "no absolute path in the " + format.id());
            assertFalse(text.matches("(?s).*20\\d\\d-\\d\\d-\\d\\d.*"), "no date in the " + format.id());
            assertEquals("exp2-defects-architecture." + format.id(), first.getFileName().toString(), "the " + format.id() + " file is named after the model and the view");
        }
    }

    @Test
    void readmeShowsTheCurrentDiagramOfExperimentOne() throws Exception {
        Path image = TestRepository.root().resolve("docs/images/exp1-hybrid-architecture.svg");
        String current = Examples.draw("exp1-hybrid.rsaml", DiagramView.ARCHITECTURE).svg();
        assertTrue(Files.exists(image), image + " exists");
        assertEquals(current, Files.readString(image),
                "docs/images/exp1-hybrid-architecture.svg is out of date: run ./rsaml diagram -o docs/images examples/exp1-hybrid.rsaml");
        assertTrue(Files.readString(TestRepository.root().resolve("README.md")).contains("docs/images/exp1-hybrid-architecture.svg"), "README.md shows the exported architecture diagram of experiment 1");
    }

    @Test
    void overlayNotesAndEmphasisAreDrawnOnTheirElements() throws Exception {
        LoadedModel model = ModelLoader.load(TestRepository.example("exp1-hybrid.rsaml"), "exp1-hybrid.rsaml");
        String module = "hybridMobileRobot/control/resourceChecker";
        DiagramOverlay overlay = architecture -> DiagramOverlay.Notes.of(Map.of(module, List.of("utilisation 42 %")), Set.of(module));
        String svgText = new RsamlDiagrams(DiagramView.ARCHITECTURE).overlay(overlay).svg(model.architecture(),
                RsamlModelValidator.validate(model));
        SvgDocument svg = new SvgDocument(svgText);
        SvgDocument.Shape shape = svg.byQname(module);
        assertTrue(shape.classes().contains("emphasis"), "the emphasised module is drawn emphasised");
        assertTrue(shape.texts().stream().anyMatch(t -> t.text().equals("utilisation 42 %")), "the overlay's note is drawn on its module");
        assertTrue(shape.box().contains(shape.texts().stream().filter(t -> t.text().equals("utilisation 42 %")).findFirst().orElseThrow().box(), 0.5), "the overlay's note lies inside its module's box");
    }
}
