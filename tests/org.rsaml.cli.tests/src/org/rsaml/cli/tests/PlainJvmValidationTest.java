/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlValidationSetup;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The validation API outside OSGi, on a plain class path: the same rules from rsaml.ecore give the
 * same findings as inside OSGi (tests/org.rsaml.validation.tests runs the same models there).
 */
class PlainJvmValidationTest {

    private static final Path RULE_MODELS = Cli.ROOT.resolve("tests/org.rsaml.validation.tests/resources/rules");

    @Test
    void runsOnAPlainClassPath() {
        assertFalse(RsamlModelValidator.class.getClassLoader().getClass().getName().contains("osgi"),
                "this test must run outside OSGi");
    }

    @Test
    void experimentTwoGivesThePapersFindings() throws Exception {
        List<Finding> findings = RsamlModelValidator.validate(Cli.ROOT.resolve("examples/exp2-defects.rsaml"), "exp2-defects.rsaml");
        List<ExpectedFinding> got = findings.stream().map(f -> new ExpectedFinding(f.ruleId(), f.severity().label(),
                f.qualifiedName(), f.line(), f.column(), f.message())).toList();
        List<ExpectedFinding> expected = ExpectedFinding.of(Cli.ROOT.resolve("examples/exp2-defects.rsaml"));
        assertFalse(expected.isEmpty(), "exp2-defects.rsaml states the paper's findings in its expect comments");
        assertEquals(expected, got, "outside OSGi, validation finds exactly what exp2's expect comments state, where they state it");
    }

    static Stream<Path> ruleModels() throws IOException {
        try (Stream<Path> files = Files.list(RULE_MODELS)) {
            return files.filter(p -> p.toString().endsWith(".rsaml")).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("ruleModels")
    void ruleModelGivesTheFindingsItStates(Path model) throws Exception {
        List<String> expected = new ArrayList<>(ExpectedFinding.of(model).stream().map(ExpectedFinding::what).toList());
        List<String> actual = new ArrayList<>(RsamlModelValidator.validate(model).stream()
                .map(f -> f.ruleId() + " " + f.severity().label() + " " + f.qualifiedName()).toList());
        expected.sort(null);
        actual.sort(null);
        assertEquals(expected, actual, model.getFileName().toString());
    }

    /**
     * After the standalone setup, EMF's stock Diagnostician reports exactly what {@code rsaml validate}
     * reports: findings, elements, severities, rule ids and messages.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("ruleModels")
    void stockDiagnosticianReportsWhatRsamlValidateReports(Path model) throws Exception {
        RsamlValidationSetup.init();
        LoadedModel loaded = ModelLoader.load(model, model.toString());
        List<Finding> findings = RsamlModelValidator.validate(loaded);
        List<String> expected = new ArrayList<>(findings.stream()
                .map(f -> f.severity().diagnosticSeverity() + " " + f.qualifiedName() + ": " + f.text())
                .toList());
        List<String> actual = new ArrayList<>();
        List<Diagnostic> others = new ArrayList<>();
        for (EObject root : loaded.resource().getContents()) {
            collect(Diagnostician.INSTANCE.validate(root), actual, others);
        }
        expected.sort(null);
        actual.sort(null);
        assertEquals(expected, actual, model.getFileName().toString());
        // Nothing else: EMF's own structural checks are RSA-00's, in RsaML's words.
        assertEquals(List.of(), others, "findings not in RsaML's words");
    }

    private static void collect(Diagnostic diagnostic, List<String> out, List<Diagnostic> others) {
        for (Diagnostic child : diagnostic.getChildren()) {
            if (child.getSeverity() != Diagnostic.OK && "org.rsaml.validation".equals(child.getSource())) {
                out.add(child.getSeverity() + " " + RsamlLabels.qualifiedName((EObject) child.getData().get(0)) + ": "
                        + child.getMessage());
            } else if (child.getSeverity() != Diagnostic.OK && !child.getData().isEmpty() && child.getData().get(0) instanceof EObject) {
                others.add(child);
            }
            collect(child, out, others);
        }
    }
}
