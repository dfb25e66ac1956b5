/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;

import org.eclipse.xtext.resource.XtextResource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.rsaml.model.Architecture;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.text.RsamlTextStandaloneSetup;
import org.rsaml.text.convert.ModelConverter;
import org.rsaml.text.formatting2.RsamlTextFormatter;
import org.rsaml.text.formatting2.RsamlTextFormatting;
import org.rsaml.text.grammar.Constructs;
import org.rsaml.text.services.RsamlTextGrammarAccess;
import org.rsaml.validation.ModelLoader;

/**
 * The formatter lays text out as the writer writes it: formatting the writer's text changes nothing,
 * formatting the same text with its layout spoiled gives it back, comments are kept.
 */
class FormatterTest {

    private static final int RANDOM_MODELS = 60;

    @TempDir
    Path temp;

    private String format(String text) throws Exception {
        XtextResource resource = (XtextResource) Models.read(temp, "f.rsa", text).resource();
        return RsamlTextStandaloneSetup.injector().getInstance(RsamlTextFormatting.class).format(resource);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = { "exp1-hybrid.rsaml", "exp2-defects.rsaml", "exp3-task-interpreter.rsaml",
            "hierarchical-nasrem.rsaml", "mobile-base-latency.rsaml", "subsumption-brooks.rsaml" })
    void formatsAsTheWriterWrites(String example) throws Exception {
        String canonical = ModelConverter.toText(ModelLoader.load(TestRepository.example(example), example).architecture());
        assertEquals(canonical, format(canonical), example + ": formatting the written text changes it");
        String spoiled = spoil(canonical);
        assertNotEquals(canonical, spoiled, "the layout is spoiled");
        assertEquals(canonical, format(spoiled), example + ": formatting does not restore the layout");
    }

    @Test
    void keepsCommentsAndIsStable() throws Exception {
        String text = "// the robot\narchitecture robot {\n      layer  control { /* lowest */ level 0 }\n}\n";
        String formatted = format(text);
        assertTrue(formatted.startsWith("// the robot\narchitecture robot {\n  layer control {"), "the head is laid out:\n" + formatted);
        assertTrue(formatted.contains("/* lowest */"), "the block comment is kept:\n" + formatted);
        assertTrue(formatted.contains("\n    level 0\n  }\n}\n"), "the attribute on its own line:\n" + formatted);
        assertEquals(formatted, format(formatted), "formatting again changes nothing");
    }

    /**
     * Every attribute keyword of the grammar starts a line of its own, as the writer writes it: seeded random models,
     * which between them write every attribute the grammar has (checked), are written, their layout spoiled, and
     * formatted back. A keyword the formatter did not know would stay on the line before it.
     */
    @Test
    void formatsRandomModelsAsTheWriterWrites() throws Exception {
        Set<String> lineStarts = new TreeSet<>();
        for (long seed = 1; seed <= RANDOM_MODELS; seed++) {
            Architecture model = Models.random(seed);
            // In a resource, as a loaded model is: the writer names references within it.
            Resource resource = RsamlStandaloneSetup.newResourceSet().createResource(URI.createFileURI(temp.resolve("m.rsaml").toString()));
            resource.getContents().add(model);
            String canonical = ModelConverter.toText(model);
            canonical.lines().map(String::strip).filter(l -> !l.isEmpty()).forEach(l -> lineStarts.add(l.split(" ", 2)[0]));
            assertEquals(canonical, format(spoil(canonical)), "seed " + seed + ": formatting does not restore the writer's layout");
        }
        Set<String> unwritten = new TreeSet<>(RsamlTextFormatter.lineStarts(new Constructs(
                RsamlTextStandaloneSetup.injector().getInstance(RsamlTextGrammarAccess.class).getGrammar())));
        unwritten.removeAll(lineStarts);
        assertEquals(Set.of(), unwritten, "attribute keywords of the grammar that no random model wrote, so their layout is not checked");
    }

    /** Every run of white space outside string literals becomes one space or three line breaks, in turn. */
    private static String spoil(String text) {
        StringBuilder out = new StringBuilder();
        boolean inString = false;
        int runs = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (inString) {
                out.append(c);
                if (c == '\\') {
                    out.append(text.charAt(++i));
                } else if (c == '"') {
                    inString = false;
                }
            } else if (Character.isWhitespace(c)) {
                while (i + 1 < text.length() && Character.isWhitespace(text.charAt(i + 1))) {
                    i++;
                }
                out.append(runs++ % 2 == 0 ? " " : "\n\n\n   ");
            } else {
                inString = c == '"';
                out.append(c);
            }
        }
        return out.toString();
    }
}
