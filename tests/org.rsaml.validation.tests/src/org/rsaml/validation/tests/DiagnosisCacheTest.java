/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Module;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.DiagnosisCache;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;

/** What diagrams ask for each element they draw: its own findings, validated once per model change. */
class DiagnosisCacheTest {

    private static List<String> messages(List<Diagnostic> diagnostics) {
        return diagnostics.stream().map(Diagnostic::getMessage).collect(Collectors.toList());
    }

    private static List<String> messagesOn(List<ExpectedFinding> expected, String qualifiedName) {
        return expected.stream().filter(e -> e.qualifiedName().equals(qualifiedName)).map(ExpectedFinding::diagnosticMessage)
                .collect(Collectors.toList());
    }

    @Test
    void findingsAreComputedOncePerModelChangeAndFollowTheModel() throws Exception {
        Path exp2 = TestRepository.example("exp2-defects.rsaml");
        LoadedModel model = ModelLoader.load(exp2, "exp2.rsaml");
        Module checker = (Module) model.resource().getEObject("//@layers[name='control']/@modules[name='resourceChecker']");
        String architecture = model.architecture().getName();
        List<ExpectedFinding> expected = ExpectedFinding.of(exp2);
        List<Diagnostic> first = DiagnosisCache.on(checker);
        assertEquals(messagesOn(expected, architecture + "/control/resourceChecker"), messages(first), "the module's own findings");
        assertEquals(messagesOn(expected, architecture + "/control"), messages(DiagnosisCache.on(checker.getLayer())),
                "only the element's own findings, not those of what it contains");
        assertEquals(messagesOn(expected, architecture), messages(DiagnosisCache.on(model.architecture())),
                "the architecture's own findings");
        assertSame(first, DiagnosisCache.on(checker), "no new validation while the model is unchanged");

        checker.setExecDuration(1.5);
        List<Diagnostic> fixed = DiagnosisCache.on(checker);
        assertEquals(List.of(), fixed, "a change of the model is seen at once");

        checker.setExecDuration(3.0);
        List<Diagnostic> again = DiagnosisCache.on(checker);
        assertNotSame(first, again, "a change of the model is validated again");
        assertEquals(1, again.size(), "the budget is exceeded again: " + messages(again));
        String rule = ExpectedFinding.on(exp2, architecture + "/control/resourceChecker").ruleId();
        assertTrue(again.get(0).getMessage().startsWith(rule + ": ") && again.get(0).getMessage().contains("takes 3.0 ms"),
                "the new finding gives the new duration: " + messages(again));
        assertSame(again, DiagnosisCache.on(checker), "no new validation while the model is unchanged");
    }
}
