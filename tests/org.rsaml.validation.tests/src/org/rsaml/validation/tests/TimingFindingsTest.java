/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rule;

/**
 * How the timing rules meet the others: another rule's warning does not stop the analysis, an error
 * that leaves the architecture without a task set silences it; the same through EMF's stock
 * {@link Diagnostician} as through {@code rsaml validate}.
 */
class TimingFindingsTest {

    @ParameterizedTest
    @ValueSource(strings = { "deadline-shorter-than-execution.rsaml", "overload-with-error.rsaml" })
    void findingsAreExactlyTheExpectedOnes(String name) throws Exception {
        Path file = TestRepository.resource("org.rsaml.validation.tests", "timing").resolve(name);
        List<String> expected = new ArrayList<>(ExpectedFinding.of(file).stream().map(ExpectedFinding::what).toList());
        expected.sort(null);
        LoadedModel model = ModelLoader.load(file, name);
        assertEquals(expected, RsamlModelValidator.validate(model).stream()
                .map(f -> f.ruleId() + " " + f.severity().label() + " " + f.qualifiedName()).sorted().collect(Collectors.toList()),
                name + " gives the findings its expect comments state");

        List<String> stock = new ArrayList<>();
        collect(Diagnostician.INSTANCE.validate(model.architecture()), stock);
        stock.sort(null);
        assertEquals(expected, stock, "EMF's stock Diagnostician");
    }

    private static void collect(Diagnostic diagnostic, List<String> out) {
        for (Diagnostic child : diagnostic.getChildren()) {
            if (child.getData().size() >= 2 && child.getData().get(0) instanceof EObject element && child.getData().get(1) instanceof Rule rule) {
                out.add(rule.id() + " " + (child.getSeverity() == Diagnostic.ERROR ? "error" : "warning") + " "
                        + RsamlLabels.qualifiedName(element));
            }
            collect(child, out);
        }
    }
}
