/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.rsaml.model.tests.XmiFiles.errors;
import static org.rsaml.model.tests.XmiFiles.model;
import static org.rsaml.model.tests.XmiFiles.open;
import static org.rsaml.model.tests.XmiFiles.write;

import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.Module;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.resource.RsamlResourceFactory;
import org.rsaml.model.resource.RsamlStandaloneSetup;

/**
 * Any EMF client that opens a .rsaml file in the ordinary way (a plain resource set, the
 * registered factory) gets RsaML's resource: no DTD, no entity, bounded nesting, one file's failure its own;
 * where elements and errors are placed is {@link LocationsTest}, what a malformed model's errors say
 * {@link LoadErrorsTest}.
 */
class LoadingTest {

    @TempDir
    Path dir;

    @Test
    void theRegisteredFactoryIsRsamlsInEveryRegistry() {
        URI uri = URI.createFileURI(dir.resolve("x.rsaml").toString());
        assertInstanceOf(RsamlResourceFactory.class, Resource.Factory.Registry.INSTANCE.getFactory(uri), "the global registry gives RsaML's factory for .rsaml files");
        assertInstanceOf(RsamlResource.class, new ResourceSetImpl().createResource(uri), "a plain EMF resource set opens .rsaml files with RsaML's resource");
        assertInstanceOf(RsamlResource.class, RsamlStandaloneSetup.newResourceSet().createResource(uri), "RsaML's standalone resource set opens .rsaml files with RsaML's resource");
    }

    @Test
    void aPlainResourceSetRefusesADoctypeWithItsLocation() throws Exception {
        Path file = write(dir, "xxe.rsaml", "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY s \"EXPANDED\">]>\n"
                + "<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&s;\"/>\n");
        Resource r = open(file);
        assertInstanceOf(RsamlResource.class, r, "a plain resource set opens the file with RsaML's resource");
        assertEquals(1, r.getErrors().size(), () -> errors(r));
        Resource.Diagnostic d = r.getErrors().get(0);
        assertEquals("DOCTYPE declarations are not allowed in .rsaml files (DTDs and external entities are never loaded)", d.getMessage(), "the refusal says why a DOCTYPE is not read");
        assertEquals(2, d.getLine(), "the refusal points at the DOCTYPE's line");
        assertEquals(10, d.getColumn(), "the refusal points at the DOCTYPE's column");
        assertTrue(r.getContents().isEmpty() || !String.valueOf(((Architecture) r.getContents().get(0)).getName()).contains("EXPANDED"), "the entity is never expanded into the model");
    }

    @Test
    void aCallersOwnParserOptionsCannotSwitchTheProtectionOff() throws Exception {
        Path file = write(dir, "xxe.rsaml", "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY s \"EXPANDED\">]>\n"
                + "<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&s;\"/>\n");
        ResourceSet set = new ResourceSetImpl();
        set.getLoadOptions().put(org.eclipse.emf.ecore.xmi.XMLResource.OPTION_PARSER_FEATURES,
                java.util.Map.of("http://apache.org/xml/features/disallow-doctype-decl", Boolean.FALSE));
        Resource r = open(set, file);
        assertTrue(errors(r).contains("DOCTYPE declarations are not allowed"), () -> errors(r));
    }

    @Test
    void nameKeyedReferencesResolve() throws Exception {
        Path file = write(dir, "refs.rsaml", model("""
                  <layers name="a">
                    <modules name="m1"><ports xsi:type="rsaml:OutputPort" name="o"/></modules>
                    <modules name="m2"><ports xsi:type="rsaml:EntryPort" name="e"/></modules>
                  </layers>
                  <connections source="//@layers[name='a']/@modules[name='m1']/@ports[name='o']" target="//@layers[name='a']/@modules[name='m2']/@ports[name='e']"/>
                """));
        Resource r = open(file);
        assertEquals("", errors(r), "a model with name-keyed references loads without errors");
        Architecture a = (Architecture) r.getContents().get(0);
        assertEquals("m1", ((Module) a.getConnections().get(0).getSource().eContainer()).getName(), "the connection's source resolves to port o of m1");
        assertEquals("m2", ((Module) a.getConnections().get(0).getTarget().eContainer()).getName(), "the connection's target resolves to port e of m2");
    }

    @Test
    void binaryAndEmptyFilesAreSaidSo() throws Exception {
        Path empty = write(dir, "empty.rsaml", "");
        assertTrue(open(empty).getErrors().get(0).getMessage().startsWith("the file is empty"), "an empty file is said to be empty");
        Path binary = dir.resolve("image.rsaml");
        Files.write(binary, new byte[] { (byte) 0x89, 'P', 'N', 'G', 0, 0, 0, 13 });
        assertTrue(open(binary).getErrors().get(0).getMessage().startsWith("the file is binary"), "a binary file is said to be binary");
        // About the whole file: no line or column that would send the user looking at line 1.
        assertEquals(0, open(empty).getErrors().get(0).getLine(), "an empty file's error is about the whole file: no line");
        assertEquals(0, open(binary).getErrors().get(0).getLine(), "a binary file's error is about the whole file: no line");
    }

    /** Goals nested {@code goals} deep under a mission: the deepest element is at depth goals + 2, on line goals + 3. */
    static String nestedGoals(int goals) {
        StringBuilder body = new StringBuilder("  <missions name=\"m\">\n");
        for (int i = 0; i < goals; i++) {
            body.append(i == 0 ? "<goals" : "<subGoals").append(" name=\"g").append(i).append("\">\n");
        }
        for (int i = goals - 1; i >= 0; i--) {
            body.append(i == 0 ? "</goals>" : "</subGoals>").append('\n');
        }
        return model(body.append("  </missions>\n").toString());
    }

    @Test
    void nestingIsReadUpToTheLimitAndRefusedBeyondIt() throws Exception {
        RsamlResource deep = (RsamlResource) open(write(dir, "deep.rsaml", nestedGoals(RsamlResource.MAX_DEPTH - 2)));
        assertEquals("", errors(deep), "a model nested up to the limit loads without errors");
        assertEquals(RsamlResource.MAX_DEPTH, deep.locatedElementCount(), "every element up to the limit is read and located");

        Resource tooDeep = open(write(dir, "too-deep.rsaml", nestedGoals(RsamlResource.MAX_DEPTH - 1)));
        assertEquals((RsamlResource.MAX_DEPTH + 2) + ":1: elements are nested more than " + RsamlResource.MAX_DEPTH
                + " levels deep here; RsaML reads models up to that depth", errors(tooDeep), "nesting beyond the limit is refused at the line where it happens, saying the limit");
    }

    @Test
    void deeplyNestedExtensionsAreRefusedToo() throws Exception {
        int levels = 50_000;
        String body = "  <xmi:Extension extender=\"x\">" + "<a>".repeat(levels) + "</a>".repeat(levels) + "</xmi:Extension>\n";
        Resource r = open(write(dir, "extensions.rsaml", model(body)));
        assertEquals(1, r.getErrors().size(), () -> errors(r));
        assertTrue(errors(r).startsWith("3:"), () -> errors(r));
        assertTrue(errors(r).contains("nested more than " + RsamlResource.MAX_DEPTH + " levels"), () -> errors(r));
    }

    @Test
    void aFileCutShortIsSaidSo() throws Exception {
        String whole = model("  <layers name=\"a\">\n    <modules name=\"m\"/>\n  </layers>\n");
        Resource r = open(write(dir, "cut.rsaml", whole.substring(0, whole.indexOf("<modules"))));
        assertEquals("the file ends before its elements are closed; it may have been cut short", r.getErrors().get(0).getMessage(), "a file cut short is said to be cut short");
        assertTrue(r.getErrors().get(0).getLine() >= 3, () -> errors(r));
    }

    @Test
    void anUnexpectedExceptionIsAnErrorOfThatFileOnly() throws Exception {
        Path file = write(dir, "faulty.rsaml", model("  <layers name=\"a\"/>\n"));
        byte[] bytes = Files.readAllBytes(file);
        ResourceSet set = new ResourceSetImpl();
        set.getURIConverter().getURIHandlers().add(0, new org.eclipse.emf.ecore.resource.impl.URIHandlerImpl() {
            @Override
            public boolean canHandle(URI uri) {
                return "faulty.rsaml".equals(uri.lastSegment());
            }

            @Override
            public java.io.InputStream createInputStream(URI uri, java.util.Map<?, ?> options) {
                return new java.io.ByteArrayInputStream(bytes, 0, bytes.length / 2) {
                    @Override
                    public synchronized int read(byte[] b, int off, int len) {
                        int n = super.read(b, off, len);
                        if (n < 0) {
                            throw new IllegalStateException("the disk\nwent away");
                        }
                        return n;
                    }
                };
            }
        });
        Resource r = open(set, file);
        assertEquals("0:0: RsaML failed on this file with an internal error (IllegalStateException: the disk went away);"
                + " please report it together with the file", errors(r), "an internal failure is an error of that file, located at 0:0, asking for a report");
        Resource other = open(set, write(dir, "fine.rsaml", model("  <layers name=\"a\"/>\n")));
        assertEquals("", errors(other), "another file of the same resource set still loads without errors");
    }
}
