/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.eclipse.emf.ecore.EValidator;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.FrameworkUtil;
import org.rsaml.model.RsamlPackage;
import org.rsaml.text.RsamlTextStandaloneSetup;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The textual syntax adds no validator to the RsaML package: making the language's injector (which
 * makes Xtext's validator of the language) leaves RsaML's validator the package's only one while
 * org.rsaml.validation is active, and the package without any while it is not.
 */
class OneValidatorWithTextTest {

    /** RsaML's validator, as {@link #registeredBy()} names it. */
    private static final String VALIDATION = "org.rsaml.validation RuleEValidator";

    @Test
    void theTextualSyntaxRegistersNoValidatorForTheRsamlPackageInEitherStartOrder() throws Exception {
        Bundle validation = FrameworkUtil.getBundle(RsamlModelValidator.class);
        assertNotNull(validation, "the test runs inside OSGi");
        validation.start();
        awaitRsamlsValidator();
        new RsamlTextStandaloneSetup().createInjectorAndDoEMFRegistration();
        assertEquals(VALIDATION, registeredBy(), "the RsaML package's validator once the textual syntax's injector is made");

        validation.stop();
        try {
            assertNull(EValidator.Registry.INSTANCE.get(RsamlPackage.eINSTANCE), "a validator while org.rsaml.validation is stopped");
            new RsamlTextStandaloneSetup().createInjectorAndDoEMFRegistration();
            Object registered = EValidator.Registry.INSTANCE.get(RsamlPackage.eINSTANCE);
            assertNull(registered, "the textual syntax registered a validator for the RsaML package: " + registered);
        } finally {
            validation.start();
        }
        awaitRsamlsValidator();
        assertEquals(VALIDATION, registeredBy(), "the RsaML package's validator once org.rsaml.validation is active again");
    }

    /** Felix SCR may register the validation bundle's component on a thread of its own once the bundle has started. */
    private static void awaitRsamlsValidator() throws InterruptedException {
        for (int i = 0; i < 3000 && EValidator.Registry.INSTANCE.get(RsamlPackage.eINSTANCE) == null; i++) {
            Thread.sleep(10);
        }
    }

    /**
     * The bundle and class of the validator the registry holds for the RsaML package
     * ({@code org.eclipse.xtext CompositeEValidator} when several share it).
     */
    private static String registeredBy() {
        Object registered = EValidator.Registry.INSTANCE.getEValidator(RsamlPackage.eINSTANCE);
        assertNotNull(registered, "no validator for the RsaML package");
        Bundle bundle = FrameworkUtil.getBundle(registered.getClass());
        return bundle == null ? registered.getClass().getName() : bundle.getSymbolicName() + " " + registered.getClass().getSimpleName();
    }
}
