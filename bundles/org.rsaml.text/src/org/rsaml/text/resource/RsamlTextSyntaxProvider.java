/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.resource;

import org.eclipse.emf.ecore.resource.Resource;
import org.rsaml.model.resource.ModelFormats;

/** Announces the textual syntax to {@link org.rsaml.model.resource.RsamlStandaloneSetup} outside OSGi. */
public class RsamlTextSyntaxProvider implements ModelFormats.Syntax {

    @Override
    public String fileExtension() {
        return ModelFormats.TEXT_EXTENSION;
    }

    @Override
    public Resource.Factory resourceFactory() {
        return new RsamlTextResourceFactory();
    }
}
