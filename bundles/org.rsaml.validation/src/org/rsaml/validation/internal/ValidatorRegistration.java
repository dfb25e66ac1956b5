/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import org.rsaml.validation.RsamlValidationSetup;

/**
 * The OSGi component ({@code OSGI-INF/validator.xml}) that registers RsaML's validator for the
 * RsaML package in EMF's registry: EMF has no extension point for validators, and the generated
 * package registers its own, generic one.
 */
public final class ValidatorRegistration {

    /** Whether the component ran: the OSGi tests tell it from {@link RsamlValidationSetup#init()}. */
    private static volatile boolean activated;

    public void activate() {
        RsamlValidationSetup.registerValidator();
        activated = true;
    }

    public static boolean activated() {
        return activated;
    }
}
