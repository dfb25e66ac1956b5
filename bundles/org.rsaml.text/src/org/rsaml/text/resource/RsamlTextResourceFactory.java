/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.resource;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.resource.IResourceFactory;
import org.rsaml.text.RsamlTextStandaloneSetup;

/**
 * The factory of {@code .rsa} resources that EMF clients find by extension (plugin.xml inside
 * Eclipse, {@link org.rsaml.model.resource.ModelFormats.Syntax} outside): the language's injector
 * is made on first use.
 */
public class RsamlTextResourceFactory implements Resource.Factory {

    @Override
    public Resource createResource(URI uri) {
        return RsamlTextStandaloneSetup.injector().getInstance(IResourceFactory.class).createResource(uri);
    }
}
