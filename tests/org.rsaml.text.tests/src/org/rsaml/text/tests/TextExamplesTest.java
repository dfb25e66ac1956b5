/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The examples in textual form ({@code examples-text/NAME.rsa}) are the models of {@code examples/NAME.rsaml}: each
 * XMI example has its textual twin and each twin its XMI example, both load to equal models, and both validate to the
 * same findings.
 */
class TextExamplesTest {

    static Path xmiFolder() {
        return TestRepository.root().resolve("examples");
    }

    static Path textFolder() {
        return TestRepository.root().resolve("examples-text");
    }

    static Stream<String> examples() throws IOException {
        try (Stream<Path> files = Files.list(xmiFolder())) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rsaml"))
                    .map(n -> n.substring(0, n.length() - ".rsaml".length())).sorted().toList().stream();
        }
    }

    @Test
    void everyExampleHasItsTextualTwinAndNothingElseIsThere() throws IOException {
        List<String> xmi = examples().map(n -> n + ".rsa").sorted().toList();
        List<String> text;
        try (Stream<Path> files = Files.list(textFolder())) {
            text = files.map(p -> p.getFileName().toString()).sorted().toList();
        }
        assertFalse(xmi.isEmpty(), "examples/ holds models");
        assertEquals(xmi, text, "examples-text/ holds exactly one NAME.rsa for each examples/NAME.rsaml");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("examples")
    void theTextualFormIsTheSameModel(String name) throws Exception {
        LoadedModel xmi = ModelLoader.load(xmiFolder().resolve(name + ".rsaml"), name + ".rsaml");
        LoadedModel text = ModelLoader.load(textFolder().resolve(name + ".rsa"), name + ".rsa");
        assertNull(Models.difference(xmi.architecture(), text.architecture()),
                "examples-text/" + name + ".rsa is the model of examples/" + name
                        + ".rsaml (after changing one, convert it: ./rsaml convert examples/" + name + ".rsaml examples-text/" + name + ".rsa)");
        List<String> xmiFindings = RsamlModelValidator.validate(xmi).stream().map(TextExamplesTest::finding).toList();
        List<String> textFindings = RsamlModelValidator.validate(text).stream().map(TextExamplesTest::finding).toList();
        assertEquals(xmiFindings, textFindings, name + ": the same findings from either form");
    }

    private static String finding(Finding f) {
        return f.ruleId() + " " + f.severity() + " " + f.qualifiedName() + ": " + f.message();
    }
}
