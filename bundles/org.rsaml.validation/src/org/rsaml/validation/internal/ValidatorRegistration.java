/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import org.eclipse.emf.ecore.EValidator;
import org.rsaml.model.RsamlPackage;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * The OSGi component ({@code OSGI-INF/validator.xml}) that registers RsaML's validator for the
 * RsaML package in EMF's registry while the bundle is active: EMF has no extension point for
 * validators, and the generated package registers none.
 */
public final class ValidatorRegistration {

    /** Whether the component ran: the OSGi tests tell it from {@link RsamlValidationSetup#init()}. */
    private static volatile boolean activated;

    public void activate() {
        RsamlValidationSetup.registerValidator();
        activated = true;
    }

    /**
     * A stopped bundle leaves no validator of its own behind in EMF's global registry: the descriptor,
     * or the validator the registry put in its place when it was first asked.
     */
    public void deactivate() {
        activated = false;
        EValidator.Registry registry = EValidator.Registry.INSTANCE;
        if (!registry.remove(RsamlPackage.eINSTANCE, RuleEValidator.DESCRIPTOR)
                && registry.get(RsamlPackage.eINSTANCE) instanceof RuleEValidator) {
            registry.remove(RsamlPackage.eINSTANCE);
        }
    }

    public static boolean activated() {
        return activated;
    }
}
