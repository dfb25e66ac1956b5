/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EValidator;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.internal.RuleEValidator;
import org.rsaml.validation.internal.ValidatorRegistration;

/**
 * Inside OSGi, EMF's stock {@link Diagnostician} — what the tree editor, Sirius and any EMF client
 * run — reports exactly what {@code rsaml validate} reports: the same findings on the same
 * elements, with the same severities, rule ids and messages.
 */
class StockDiagnosticianTest {

    static Stream<String> models() throws Exception {
        List<String> names = new ArrayList<>();
        try (Stream<Path> files = Files.list(TestRepository.resource("org.rsaml.validation.tests", "rules"))) {
            files.map(p -> "rules/" + p.getFileName()).filter(n -> n.endsWith(".rsaml")).forEach(names::add);
        }
        try (Stream<Path> files = Files.list(TestRepository.root().resolve("examples"))) {
            files.map(p -> "examples/" + p.getFileName()).filter(n -> n.endsWith(".rsaml")).forEach(names::add);
        }
        return names.stream().sorted();
    }

    @Test
    void theBundleRegistersRsamlsValidatorWithEmf() {
        assertTrue(ValidatorRegistration.activated(), "the component OSGI-INF/validator.xml did not run");
        assertEquals(RuleEValidator.class, EValidator.Registry.INSTANCE.getEValidator(RsamlPackage.eINSTANCE).getClass(), "RsaML's one validator is the package's registered EValidator");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("models")
    void stockDiagnosticianReportsWhatRsamlValidateReports(String name) throws Exception {
        Path file = name.startsWith("rules/") ? TestRepository.resource("org.rsaml.validation.tests", name) : TestRepository.root().resolve(name);
        LoadedModel model = ModelLoader.load(file, name);
        List<String> expected = RsamlModelValidator.validate(model).stream()
                .map(f -> line(f.severity().diagnosticSeverity(), f.qualifiedName(), f.text()))
                .sorted().collect(Collectors.toList());

        List<String> actual = new ArrayList<>();
        int[] emf = { 0 };
        for (EObject root : model.resource().getContents()) {
            collect(Diagnostician.INSTANCE.validate(root), actual, emf);
        }
        actual.sort(null);
        assertEquals(expected, actual, name);
        // EMF's own structural findings are RSA-00's, in RsaML's words whatever labels the client would give.
        assertEquals(0, emf[0], name + ": findings not in RsaML's words");
    }

    private static void collect(Diagnostic diagnostic, List<String> out, int[] emf) {
        for (Diagnostic child : diagnostic.getChildren()) {
            if (child.getSeverity() != Diagnostic.OK && child.getData().get(0) instanceof EObject element) {
                if (RuleEValidator.SOURCE.equals(child.getSource())) {
                    out.add(line(child.getSeverity(), RsamlLabels.qualifiedName(element), child.getMessage()));
                } else {
                    emf[0]++;
                }
            }
            collect(child, out, emf);
        }
    }

    private static String line(int severity, String element, String message) {
        return (severity == Diagnostic.ERROR ? "error" : severity == Diagnostic.WARNING ? "warning" : "info") + " "
                + element + ": " + message;
    }

    /** A finding's severity as EMF spells it, so a warning rule stays a warning in Eclipse. */
    @Test
    void warningsStayWarnings() throws Exception {
        LoadedModel model = ModelLoader.load(TestRepository.resource("org.rsaml.validation.tests", "rules").resolve("rule-RSA-11-violated.rsaml"), "rsa11");
        Diagnostic d = Diagnostician.INSTANCE.validate(model.architecture());
        assertEquals(Diagnostic.WARNING, d.getSeverity(), d.toString());
        List<Finding> findings = RsamlModelValidator.validate(model);
        assertEquals(1, findings.size(), "the RSA-11 model has exactly one finding");
        assertEquals("RSA-11", findings.get(0).ruleId(), "the finding is RSA-11");
    }
}
