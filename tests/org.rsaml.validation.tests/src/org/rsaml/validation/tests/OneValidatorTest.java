/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EValidator;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.wiring.BundleWiring;
import org.rsaml.model.RsamlPackage;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.Rule;
import org.rsaml.validation.internal.RuleEValidator;
import org.rsaml.validation.internal.ValidatorRegistration;

/**
 * The RsaML package has one validator, RsaML's, in every start order: the model bundle brings none
 * (the generated package registers none, and declares no validation delegate through which EMF's
 * dynamic validation would judge the invariants), so before org.rsaml.validation is active nothing
 * judges RsaML's rules, and while it is active its validator does, with the catalogue's words.
 */
class OneValidatorTest {

    private static final Path EXP2 = TestRepository.root().resolve("examples/exp2-defects.rsaml");

    @Test
    void theModelBundleHoldsNoValidator() throws Exception {
        Bundle model = FrameworkUtil.getBundle(RsamlPackage.class);
        assertNotNull(model, "the test runs inside OSGi");
        List<String> validators = new ArrayList<>();
        for (String resource : model.adapt(BundleWiring.class).listResources("/", "*.class",
                BundleWiring.LISTRESOURCES_RECURSE | BundleWiring.LISTRESOURCES_LOCAL)) {
            Class<?> type;
            try {
                type = model.loadClass(resource.substring(0, resource.length() - ".class".length()).replace('/', '.'));
            } catch (LinkageError e) {
                continue; // needs an optional bundle that is not here, so it cannot register anything either
            }
            if (EValidator.class.isAssignableFrom(type) || EValidator.Descriptor.class.isAssignableFrom(type)) {
                validators.add(type.getName());
            }
        }
        assertEquals(List.of(), validators, "org.rsaml.model holds a validator of its own, which its package can register");
    }

    @Test
    void rsamlsValidatorJudgesWhileItsBundleIsActiveAndNothingElseBefore() throws Exception {
        Bundle validation = FrameworkUtil.getBundle(RuleEValidator.class);
        List<String> expected = ExpectedFinding.of(EXP2).stream().map(e -> e.ruleId() + " " + e.message()).sorted().toList();
        assertFalse(expected.isEmpty(), EXP2 + " states no expected finding");
        LoadedModel model = ModelLoader.load(EXP2, "examples/exp2-defects.rsaml");

        assertTrue(ValidatorRegistration.activated(), "the component OSGI-INF/validator.xml did not run");
        assertEquals(expected, rsamlFindings(model), "the stock Diagnostician while org.rsaml.validation is active");

        validation.stop();
        try {
            assertEquals(Bundle.RESOLVED, validation.getState(), "org.rsaml.validation stopped");
            assertSame(RsamlPackage.eINSTANCE, EPackage.Registry.INSTANCE.getEPackage(RsamlPackage.eNS_URI),
                    "the RsaML package stays initialised and registered");
            assertNull(EValidator.Registry.INSTANCE.get(RsamlPackage.eINSTANCE),
                    "a validator for the RsaML package while RsaML's is not there");
            List<String> judged = new ArrayList<>();
            for (EObject root : model.resource().getContents()) {
                describe(Diagnostician.INSTANCE.validate(root), judged);
            }
            assertEquals(List.of(), judged, "something other than RsaML's validator judged " + EXP2);
            assertEquals(Bundle.RESOLVED, validation.getState(), "validating started org.rsaml.validation");
        } finally {
            validation.start();
        }
        awaitRegistration();
        assertEquals(expected, rsamlFindings(model), "the stock Diagnostician once org.rsaml.validation is active again");
    }

    /** Felix SCR may activate the component on a thread of its own once the bundle has started. */
    private static void awaitRegistration() throws InterruptedException {
        for (int i = 0; i < 3000 && EValidator.Registry.INSTANCE.get(RsamlPackage.eINSTANCE) == null; i++) {
            Thread.sleep(10);
        }
        // EMF's registry hands out (and keeps) the validator its descriptor makes.
        Object registered = EValidator.Registry.INSTANCE.get(RsamlPackage.eINSTANCE);
        assertEquals(RuleEValidator.class, registered == null ? null : registered.getClass(),
                "the component registers RsaML's validator when the bundle starts again");
    }

    /** The findings EMF's stock Diagnostician reports, as {@code RSA-nn message}, sorted; nothing but RsaML's. */
    private static List<String> rsamlFindings(LoadedModel model) {
        List<String> findings = new ArrayList<>();
        List<String> other = new ArrayList<>();
        for (EObject root : model.resource().getContents()) {
            for (Diagnostic d : Diagnostician.INSTANCE.validate(root).getChildren()) {
                if (d.getData().size() > 2 && d.getData().get(1) instanceof Rule rule) {
                    findings.add(rule.id() + " " + d.getData().get(2));
                } else {
                    other.add(d.getSource() + ": " + d.getMessage());
                }
            }
        }
        assertEquals(List.of(), other, "diagnostics that are not RsaML's findings");
        findings.sort(null);
        return findings;
    }

    private static void describe(Diagnostic diagnostic, List<String> out) {
        for (Diagnostic d : diagnostic.getChildren()) {
            out.add(d.getSource() + ": " + d.getMessage());
            describe(d, out);
        }
    }
}
