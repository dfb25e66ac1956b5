/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.resource.impl.URIHandlerImpl;
import org.rsaml.model.RsamlPackage;

/**
 * Outside Eclipse, registers what reading {@code .rsaml} files needs (inside Eclipse, plugin.xml
 * does): the RsaML package and the {@link RsamlResourceFactory}, and the factories of the other
 * syntaxes on the class path ({@link ModelFormats.Syntax}, such as the textual {@code .rsa}). {@link #newResourceSet()} gives
 * a resource set that can open local files only, whatever asks it to.
 */
public final class RsamlStandaloneSetup {

    private RsamlStandaloneSetup() {
    }

    /** Idempotent. */
    public static synchronized void init() {
        if (EPackage.Registry.INSTANCE.get(RsamlPackage.eNS_URI) != RsamlPackage.eINSTANCE) {
            EPackage.Registry.INSTANCE.put(RsamlPackage.eNS_URI, RsamlPackage.eINSTANCE);
        }
        Map<String, Object> factories = Resource.Factory.Registry.INSTANCE.getExtensionToFactoryMap();
        Object registered = factories.get("rsaml");
        if (!(registered instanceof RsamlResourceFactory) && !(registered instanceof Resource.Factory.Descriptor)) {
            factories.put("rsaml", new RsamlResourceFactory());
        }
        ModelFormats.registerSyntaxes(factories);
    }

    /**
     * A resource set for reading models: the RsaML package and factory, and a URI converter that
     * refuses (without opening anything) every address that is not a local or workspace file.
     */
    public static ResourceSet newResourceSet() {
        init();
        ResourceSetImpl resourceSet = new ResourceSetImpl();
        resourceSet.getPackageRegistry().put(RsamlPackage.eNS_URI, RsamlPackage.eINSTANCE);
        resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put("rsaml", new RsamlResourceFactory());
        resourceSet.getURIConverter().getURIHandlers().add(0, new LocalOnly());
        return resourceSet;
    }

    /** Handles every address that is not local by refusing it. */
    private static final class LocalOnly extends URIHandlerImpl {
        @Override
        public boolean canHandle(URI uri) {
            return !LoadPolicy.isLocal(uri);
        }

        private static IOException refused(URI uri) {
            return new IOException("'" + uri + "' is not a local file; RsaML never opens network or other addresses");
        }

        @Override
        public InputStream createInputStream(URI uri, Map<?, ?> options) throws IOException {
            throw refused(uri);
        }

        @Override
        public OutputStream createOutputStream(URI uri, Map<?, ?> options) throws IOException {
            throw refused(uri);
        }

        @Override
        public void delete(URI uri, Map<?, ?> options) throws IOException {
            throw refused(uri);
        }

        @Override
        public Map<String, ?> contentDescription(URI uri, Map<?, ?> options) throws IOException {
            throw refused(uri);
        }

        @Override
        public boolean exists(URI uri, Map<?, ?> options) {
            return false;
        }

        @Override
        public Map<String, ?> getAttributes(URI uri, Map<?, ?> options) {
            return Map.of();
        }

        @Override
        public void setAttributes(URI uri, Map<String, ?> attributes, Map<?, ?> options) throws IOException {
            throw refused(uri);
        }
    }
}
