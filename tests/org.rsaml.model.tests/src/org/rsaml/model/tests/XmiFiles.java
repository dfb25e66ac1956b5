/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;

/** .rsaml files written for a test and opened the way any EMF client opens them, with their errors as text. */
final class XmiFiles {

    static final String ROOT = "<rsaml:Architecture xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\""
            + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\""
            + " name=\"robot\" declaredLayers=\"1\">";

    private XmiFiles() {
    }

    /** A model whose root holds {@code body}, with an XML declaration. */
    static String model(String body) {
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + ROOT + "\n" + body + "</rsaml:Architecture>\n";
    }

    /** Writes {@code content} to {@code name} under {@code dir}, making the folders it needs. */
    static Path write(Path dir, String name, String content) throws Exception {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        Files.writeString(file, content);
        return file;
    }

    /** Loads the way any EMF client does, and returns the resource whatever happened. */
    static Resource open(ResourceSet set, Path file) {
        URI uri = URI.createFileURI(file.toAbsolutePath().toString());
        try {
            set.getResource(uri, true);
        } catch (RuntimeException e) {
            // errors are on the resource
        }
        return set.getResource(uri, false);
    }

    static Resource open(Path file) {
        return open(new ResourceSetImpl(), file);
    }

    static String errors(Resource r) {
        return r.getErrors().stream().map(d -> d.getLine() + ":" + d.getColumn() + ": " + d.getMessage())
                .collect(Collectors.joining("\n"));
    }
}
