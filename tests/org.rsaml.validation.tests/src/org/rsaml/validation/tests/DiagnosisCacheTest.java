/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Module;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.DiagnosisCache;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;

/** What diagrams ask for each element they draw: its own findings, validated once per model change. */
class DiagnosisCacheTest {

    private static List<String> messages(List<Diagnostic> diagnostics) {
        return diagnostics.stream().map(Diagnostic::getMessage).collect(Collectors.toList());
    }

    @Test
    void findingsAreComputedOncePerModelChangeAndFollowTheModel() throws Exception {
        LoadedModel model = ModelLoader.load(TestRepository.example("exp2-defects.rsaml"), "exp2.rsaml");
        Module checker = (Module) model.resource().getEObject("//@layers[name='control']/@modules[name='resourceChecker']");
        List<Diagnostic> first = DiagnosisCache.on(checker);
        assertEquals(List.of("RSA-08: Module 'resourceChecker' takes 2.5 ms but layer 'control' allows at most 2.0 ms"),
                messages(first));
        assertEquals(List.of(), DiagnosisCache.on(checker.getLayer()), "only the element's own findings");
        assertEquals(1, DiagnosisCache.on(model.architecture()).size(), "RSA-01 is the architecture's");
        assertSame(first, DiagnosisCache.on(checker), "no new validation while the model is unchanged");

        checker.setExecDuration(1.5);
        List<Diagnostic> fixed = DiagnosisCache.on(checker);
        assertEquals(List.of(), fixed, "a change of the model is seen at once");

        checker.setExecDuration(3.0);
        List<Diagnostic> again = DiagnosisCache.on(checker);
        assertNotSame(first, again);
        assertEquals(List.of("RSA-08: Module 'resourceChecker' takes 3.0 ms but layer 'control' allows at most 2.0 ms"),
                messages(again));
        assertSame(again, DiagnosisCache.on(checker));
    }
}
