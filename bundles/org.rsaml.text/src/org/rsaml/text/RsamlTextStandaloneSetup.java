/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text;

import org.rsaml.model.resource.RsamlStandaloneSetup;

import com.google.inject.Injector;

/**
 * Sets the textual syntax up outside an IDE: the RsaML package first (the grammar refers to it), then
 * the language, registered for {@code .rsa}.
 */
public class RsamlTextStandaloneSetup extends RsamlTextStandaloneSetupGenerated {

    private static Injector injector;

    /** The language's injector, made and registered once. */
    public static synchronized Injector injector() {
        if (injector == null) {
            injector = doSetup();
        }
        return injector;
    }

    public static Injector doSetup() {
        return new RsamlTextStandaloneSetup().createInjectorAndDoEMFRegistration();
    }

    @Override
    public Injector createInjectorAndDoEMFRegistration() {
        RsamlStandaloneSetup.init();
        return super.createInjectorAndDoEMFRegistration();
    }
}
