/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide.tests;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.jar.Manifest;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;

import org.eclipse.core.runtime.IExtensionPoint;
import org.eclipse.core.runtime.Platform;
import org.eclipse.osgi.util.ManifestElement;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleException;
import org.osgi.framework.Constants;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.SAXException;

/**
 * Checks that every extension point a bundle's plugin.xml uses belongs to the bundle itself or to a
 * bundle its manifest requires (directly, or re-exported by a required bundle). Without that, the
 * declaring bundle may be missing where the bundle is installed and the extension silently does
 * nothing. Works for bundles that are not in the running platform (UI, Sirius): the declaring bundle
 * comes from the extension registry when the point is there, else from the convention that a point's
 * id is {@code <declaring bundle>.<simple id>}.
 */
final class ExtensionPointDependencies {

    private ExtensionPointDependencies() {
    }

    /**
     * The problems of the bundle in {@code bundleDir}, one message each, naming the plugin.xml (relative
     * to {@code base}), the extension point and the bundle to add to Require-Bundle.
     */
    static List<String> check(Path bundleDir, Path base) throws IOException {
        Path pluginXml = bundleDir.resolve("plugin.xml");
        Path manifestFile = bundleDir.resolve("META-INF/MANIFEST.MF");
        Manifest manifest;
        try (InputStream in = Files.newInputStream(manifestFile)) {
            manifest = new Manifest(in);
        }
        String self = names(manifest.getMainAttributes().getValue(Constants.BUNDLE_SYMBOLICNAME), manifestFile).get(0);
        Set<String> required = new LinkedHashSet<>(names(manifest.getMainAttributes().getValue(Constants.REQUIRE_BUNDLE), manifestFile));
        required.addAll(names(manifest.getMainAttributes().getValue(Constants.FRAGMENT_HOST), manifestFile));
        required.addAll(reexportedBy(required));

        Element plugin = parse(pluginXml);
        Set<String> ownPoints = new LinkedHashSet<>();
        for (Element point : children(plugin, "extension-point")) {
            String id = point.getAttribute("id");
            ownPoints.add(id.contains(".") ? id : self + "." + id);
        }
        List<String> problems = new ArrayList<>();
        for (Element extension : children(plugin, "extension")) {
            String point = extension.getAttribute("point");
            String declaring = declaringBundle(point, self, ownPoints);
            if (!declaring.equals(self) && !required.contains(declaring)) {
                problems.add(base.relativize(pluginXml) + ": extension point '" + point + "' belongs to bundle '" + declaring
                        + "', which " + base.relativize(manifestFile) + " does not require; add '" + declaring
                        + "' to its Require-Bundle");
            }
        }
        return problems;
    }

    /** The bundle that declares {@code point}, for a bundle {@code self} that declares {@code ownPoints}. */
    static String declaringBundle(String point, String self, Set<String> ownPoints) {
        if (!point.contains(".") || ownPoints.contains(point)) {
            return self; // a simple id names a point of the bundle itself
        }
        IExtensionPoint registered = Platform.getExtensionRegistry().getExtensionPoint(point);
        if (registered != null) {
            return registered.getContributor().getName();
        }
        return point.substring(0, point.lastIndexOf('.'));
    }

    /** Bundles re-exported, transitively, by the installed ones among {@code required}. */
    private static Set<String> reexportedBy(Set<String> required) {
        Set<String> found = new LinkedHashSet<>();
        Deque<String> todo = new ArrayDeque<>(required);
        while (!todo.isEmpty()) {
            Bundle bundle = Platform.getBundle(todo.pop());
            String header = bundle == null ? null : bundle.getHeaders("").get(Constants.REQUIRE_BUNDLE);
            if (header == null) {
                continue;
            }
            try {
                for (ManifestElement element : ManifestElement.parseHeader(Constants.REQUIRE_BUNDLE, header)) {
                    if (Constants.VISIBILITY_REEXPORT.equals(element.getDirective(Constants.VISIBILITY_DIRECTIVE))
                            && !required.contains(element.getValue()) && found.add(element.getValue())) {
                        todo.push(element.getValue());
                    }
                }
            } catch (BundleException e) {
                throw new IllegalStateException("installed bundle " + bundle.getSymbolicName() + " has a bad Require-Bundle", e);
            }
        }
        return found;
    }

    private static List<String> names(String header, Path manifestFile) {
        List<String> names = new ArrayList<>();
        if (header == null) {
            return names;
        }
        try {
            for (ManifestElement element : ManifestElement.parseHeader("header", header)) {
                names.add(element.getValue());
            }
        } catch (BundleException e) {
            throw new IllegalArgumentException(manifestFile + ": cannot parse '" + header + "': " + e.getMessage(), e);
        }
        return names;
    }

    private static Element parse(Path pluginXml) throws IOException {
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            return factory.newDocumentBuilder().parse(pluginXml.toFile()).getDocumentElement();
        } catch (ParserConfigurationException | SAXException e) {
            throw new IOException(pluginXml + ": not a well-formed plugin.xml: " + e.getMessage(), e);
        }
    }

    private static List<Element> children(Element parent, String name) {
        List<Element> elements = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(name)) {
                elements.add(e);
            }
        }
        return elements;
    }
}
