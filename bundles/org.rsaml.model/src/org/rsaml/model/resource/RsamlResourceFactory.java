/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.rsaml.model.util.RsamlResourceFactoryImpl;

/**
 * The factory registered for {@code .rsaml} (plugin.xml inside Eclipse, {@link RsamlStandaloneSetup}
 * elsewhere): every EMF client gets the {@link RsamlResource}.
 */
public class RsamlResourceFactory extends RsamlResourceFactoryImpl {

    @Override
    public Resource createResource(URI uri) {
        return new RsamlResource(uri);
    }
}
