/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.parser.IEncodingProvider;
import org.eclipse.xtext.resource.IContainer;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.IResourceFactory;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.validation.IResourceValidator;
import org.rsaml.model.resource.ModelFormats;

/**
 * A document the editor has not saved yet ({@code untitled:Untitled-1}, VS Code's and others' name for it) has no
 * file extension to choose its language by; this server speaks only RsaML text, so such a document is read as
 * RsaML text ({@code .rsa}) and checked like a saved one.
 */
final class UntitledDocuments {

    /** The scheme of an unsaved document's URI. */
    static final String SCHEME = "untitled";

    private UntitledDocuments() {
    }

    static void register(IResourceServiceProvider.Registry languages) {
        IResourceServiceProvider text = languages.getResourceServiceProvider(URI.createURI("model." + ModelFormats.TEXT_EXTENSION));
        if (text == null) {
            throw new IllegalStateException("the textual syntax (." + ModelFormats.TEXT_EXTENSION + ") is not registered");
        }
        languages.getProtocolToFactoryMap().put(SCHEME, new Untitled(text));
        Resource.Factory.Registry.INSTANCE.getProtocolToFactoryMap().put(SCHEME, text.get(IResourceFactory.class));
    }

    /** The textual syntax's services, for every URI of the scheme (Xtext's would take only those ending {@code .rsa}). */
    private record Untitled(IResourceServiceProvider text) implements IResourceServiceProvider {

        @Override
        public boolean canHandle(URI uri) {
            return SCHEME.equals(uri.scheme()) || text.canHandle(uri);
        }

        @Override
        public IResourceValidator getResourceValidator() {
            return text.getResourceValidator();
        }

        @Override
        public IResourceDescription.Manager getResourceDescriptionManager() {
            return text.getResourceDescriptionManager();
        }

        @Override
        public IContainer.Manager getContainerManager() {
            return text.getContainerManager();
        }

        @Override
        public IEncodingProvider getEncodingProvider() {
            return text.getEncodingProvider();
        }

        @Override
        public <T> T get(Class<T> type) {
            return text.get(type);
        }
    }
}
