/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide;

import org.eclipse.xtext.util.Modules2;
import org.rsaml.text.RsamlTextRuntimeModule;
import org.rsaml.text.RsamlTextStandaloneSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;

/** The textual syntax with its editor services; the language server finds it through META-INF/services. */
public class RsamlTextIdeSetup extends RsamlTextStandaloneSetup {

    @Override
    public Injector createInjector() {
        return Guice.createInjector(Modules2.mixin(new RsamlTextRuntimeModule(), new RsamlTextIdeModule()));
    }
}
