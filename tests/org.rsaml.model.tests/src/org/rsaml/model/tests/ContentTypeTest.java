/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.content.IContentType;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.util.RsamlResourceImpl;

/** Inside Eclipse, .rsaml files open with the RsaML package through the registered content type. */
class ContentTypeTest {

    @TempDir
    Path dir;

    @Test
    void rsamlExtensionHasTheRsamlContentType() {
        IContentType type = Platform.getContentTypeManager().findContentTypeFor("robot.rsaml");
        assertNotNull(type, ".rsaml has no content type");
        assertEquals("org.rsaml.model.rsaml", type.getId(), ".rsaml files have RsaML's content type");
    }

    @Test
    void rsamlFileOpensWithTheRsamlPackage() throws Exception {
        Path file = dir.resolve("tiny.rsaml");
        Files.writeString(file, """
                <?xml version="1.0" encoding="UTF-8"?>
                <rsaml:Architecture xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI"
                    xmlns:rsaml="http://www.rsaml.org/rsaml/1.0" name="tiny" declaredLayers="1">
                  <layers name="functional"/>
                </rsaml:Architecture>
                """);
        Resource resource = new ResourceSetImpl().getResource(URI.createFileURI(file.toString()), true);
        assertInstanceOf(RsamlResourceImpl.class, resource, "the RsaML resource factory must handle .rsaml");
        EObject root = resource.getContents().get(0);
        assertSame(RsamlPackage.eINSTANCE, root.eClass().getEPackage(), "the root is an element of RsaML's package");
        assertEquals("Architecture", root.eClass().getName(), "the root is an Architecture");
    }
}
