/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.rsaml.model.tests.XmiFiles.errors;
import static org.rsaml.model.tests.XmiFiles.model;
import static org.rsaml.model.tests.XmiFiles.write;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.Module;
import org.rsaml.model.resource.RsamlStandaloneSetup;

/**
 * What a hostile model file can make any EMF client do when it opens it: never reach the network,
 * never parse a DTD in a referenced file, never read outside the model's folder, never hang.
 */
class UntrustedFilesTest {

    @TempDir
    Path dir;

    /** A model whose module m uses the sensors {@code reference} names. */
    static String referring(String reference) {
        return model("  <layers name=\"a\">\n    <modules name=\"m\" sensors=\"" + reference + "\"/>\n  </layers>\n");
    }

    /** Loads as any client does, then resolves every reference, as editors and validators do. */
    static Resource openAndResolve(Path file) {
        ResourceSet set = new ResourceSetImpl();
        Resource r = XmiFiles.open(set, file);
        EcoreUtil.resolveAll(set);
        return r;
    }

    /** The first error must be located on module m's start tag (line 4, column 5) and say {@code what}. */
    static void assertRefusedOnModule(Resource r, String what) {
        assertFalse(r.getErrors().isEmpty(), "nothing refused");
        Resource.Diagnostic d = r.getErrors().get(0);
        assertTrue(d.getMessage().contains(what), () -> errors(r));
        assertEquals("4:5", d.getLine() + ":" + d.getColumn(), () -> errors(r));
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void nothingConnectsToTheNetwork() throws Exception {
        try (ServerSocket listener = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            AtomicInteger connections = new AtomicInteger();
            listener.setSoTimeout(200);
            Thread acceptor = new Thread(() -> {
                while (!listener.isClosed()) {
                    try (Socket s = listener.accept()) {
                        connections.incrementAndGet();
                    } catch (SocketTimeoutException e) {
                        // keep listening
                    } catch (Exception e) {
                        return;
                    }
                }
            });
            acceptor.setDaemon(true);
            acceptor.start();
            String base = "http://127.0.0.1:" + listener.getLocalPort() + "/";

            assertRefusedOnModule(openAndResolve(write(dir, "http-ref.rsaml", referring(base + "x.rsaml#//@sensors.0"))),
                    "RsaML never opens network");
            assertRefusedOnModule(openAndResolve(write(dir, "https-ref.rsaml", referring("https://127.0.0.1:" + listener.getLocalPort()
                    + "/x.rsaml#//@sensors.0"))), "RsaML never opens network");
            assertRefusedOnModule(openAndResolve(write(dir, "jar-ref.rsaml", referring("jar:" + base + "x.jar!/x.rsaml#//@sensors.0"))),
                    "RsaML never opens network");
            Resource href = openAndResolve(write(dir, "href-ref.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\">\n"
                    + "      <sensors href=\"" + base + "x.rsaml#//@sensors.0\"/>\n    </modules>\n  </layers>\n")));
            assertTrue(errors(href).startsWith("5:7: reference to '" + base + "x.rsaml' refused"), () -> errors(href));
            Resource namespace = openAndResolve(write(dir, "http-ns.rsaml", "<?xml version=\"1.0\"?>\n<x:Architecture xmlns:x=\""
                    + base + "x.ecore\" name=\"r\"/>\n"));
            assertTrue(namespace.getErrors().get(0).getMessage().startsWith("namespace '" + base + "x.ecore' is not RsaML's"),
                    () -> errors(namespace));
            assertEquals(2, namespace.getErrors().get(0).getLine(), "the foreign namespace is refused on the root's line");
            Resource schema = openAndResolve(write(dir, "schema.rsaml", "<?xml version=\"1.0\"?>\n<x:Architecture"
                    + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns:x=\"urn:other\""
                    + " xsi:schemaLocation=\"urn:other " + base + "x.ecore\" name=\"r\"/>\n"));
            assertFalse(schema.getErrors().isEmpty(), "a schema location pointing elsewhere is an error, not followed");
            ResourceSet safe = RsamlStandaloneSetup.newResourceSet();
            assertThrows(RuntimeException.class, () -> safe.getResource(URI.createURI(base + "other.xml"), true), "RsaML's resource set refuses to fetch a remote resource");

            TimeUnit.MILLISECONDS.sleep(500);
            assertEquals(0, connections.get(), "a model made RsaML connect to " + base);
            // The listener does see a connection when there is one.
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), listener.getLocalPort())) {
                for (int i = 0; i < 50 && connections.get() == 0; i++) {
                    TimeUnit.MILLISECONDS.sleep(100);
                }
            }
            assertEquals(1, connections.get(), "the listener counts a real connection, so its zero above means something");
        }
    }

    @Test
    void aReferencedFileIsReadAsSafelyAsTheFirst() throws Exception {
        write(dir, "other.rsaml", "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY s \"EXPANDED\">]>\n"
                + "<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&s;\"><sensors name=\"&s;\"/></rsaml:Architecture>\n");
        ResourceSet set = new ResourceSetImpl();
        Resource main = XmiFiles.open(set, write(dir, "main.rsaml", referring("other.rsaml#//@sensors.0")));
        assertEquals("", errors(main), "the referring model loads without errors");
        EcoreUtil.resolveAll(set);
        Module m = ((Architecture) main.getContents().get(0)).getLayers().get(0).getModules().get(0);
        assertTrue(m.getSensors().get(0).eIsProxy(), "the DOCTYPE file was read");
        Resource other = set.getResource(URI.createFileURI(dir.resolve("other.rsaml").toString()), false);
        assertTrue(errors(other).startsWith("2:10: DOCTYPE declarations are not allowed"), () -> errors(other));
    }

    @Test
    void aReferenceInTheModelsFolderTreeResolves() throws Exception {
        write(dir, "sub/devices.rsaml", model("  <sensors name=\"lidar\"/>\n"));
        ResourceSet set = new ResourceSetImpl();
        Resource main = XmiFiles.open(set, write(dir, "main.rsaml", referring("sub/devices.rsaml#//@sensors.0")));
        EcoreUtil.resolveAll(set);
        assertEquals("", errors(main), "the referring model loads without errors");
        Module m = ((Architecture) main.getContents().get(0)).getLayers().get(0).getModules().get(0);
        assertEquals("lidar", m.getSensors().get(0).getName(), "the referenced sensor in a subfolder resolves");
    }

    @Test
    void referencesLeavingTheModelsFolderAreRefused() throws Exception {
        Path outside = Files.createDirectories(dir.resolve("outside"));
        Files.writeString(outside.resolve("secret.rsaml"), model("  <sensors name=\"secret\"/>\n"));
        Path models = Files.createDirectories(dir.resolve("models"));
        Files.writeString(models.resolve("devices.xml"), model("  <sensors name=\"xml\"/>\n"));
        assertRefusedOnModule(openAndResolve(write(dir, "models/up.rsaml", referring("../outside/secret.rsaml#//@sensors.0"))), "'..'");
        assertRefusedOnModule(openAndResolve(write(dir, "models/encoded.rsaml", referring("sub/%2e%2e/%2e%2e/outside/secret.rsaml#//@sensors.0"))),
                "refused");
        assertRefusedOnModule(openAndResolve(write(dir, "models/absolute.rsaml", referring(outside.resolve("secret.rsaml").toUri()
                + "#//@sensors.0"))), "refused");
        assertRefusedOnModule(openAndResolve(write(dir, "models/rooted.rsaml", referring(outside.resolve("secret.rsaml")
                + "#//@sensors.0"))), "absolute paths are not followed");
        assertRefusedOnModule(openAndResolve(write(dir, "models/xml.rsaml", referring("devices.xml#//@sensors.0"))), "does not name an .rsaml file");
        try {
            Files.createSymbolicLink(models.resolve("link.rsaml"), outside.resolve("secret.rsaml"));
        } catch (UnsupportedOperationException | java.io.IOException e) {
            Assumptions.abort("no symbolic links here: " + e);
        }
        assertRefusedOnModule(openAndResolve(write(dir, "models/link-ref.rsaml", referring("link.rsaml#//@sensors.0"))), "symbolic link");
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void specialFilesAreNeverOpened() throws Exception {
        Files.createDirectories(dir.resolve("folder.rsaml"));
        Resource directory = openAndResolve(write(dir, "dir-ref.rsaml", referring("folder.rsaml#//@sensors.0")));
        Resource folder = directory.getResourceSet().getResource(URI.createFileURI(dir.resolve("folder.rsaml").toString()), false);
        assertEquals("0:0: is a directory, not an .rsaml file", errors(folder), "a directory named like a model is an error of that path, about the whole file");
        assertRefusedOnModule(openAndResolve(write(dir, "zero-ref.rsaml", referring("/dev/zero#//@sensors.0"))), "refused");
        if (Files.exists(Path.of("/dev/zero"))) {
            // Named by the user (through a link in the folder), still not read.
            Path link = Files.createSymbolicLink(dir.resolve("zero.rsaml"), Path.of("/dev/zero"));
            Resource zero = XmiFiles.open(new ResourceSetImpl(), link);
            assertTrue(errors(zero).contains("not a regular file"), () -> errors(zero));
            Files.delete(link);
        }

        Path fifo = dir.resolve("pipe.rsaml");
        boolean made;
        try {
            made = new ProcessBuilder("mkfifo", fifo.toString()).inheritIO().start().waitFor() == 0;
        } catch (java.io.IOException e) {
            made = false;
        }
        Assumptions.assumeTrue(made, "mkfifo is not available on this platform");
        Resource pipeRef = openAndResolve(write(dir, "pipe-ref.rsaml", referring("pipe.rsaml#//@sensors.0")));
        Resource pipe = pipeRef.getResourceSet().getResource(URI.createFileURI(fifo.toString()), false);
        assertTrue(errors(pipe).contains("is not a regular file"), () -> errors(pipe));
        String direct = errors(XmiFiles.open(fifo));
        assertTrue(direct.contains("is not a regular file"), () -> "a FIFO opened directly is refused as not a regular file: " + direct);
    }

    @Test
    void filesAboveTheSizeLimitAreNotRead() throws Exception {
        Path file = write(dir, "big.rsaml", model("  <layers name=\"a\"/>\n"));
        ResourceSet set = new ResourceSetImpl();
        set.getLoadOptions().put(org.rsaml.model.resource.RsamlResource.OPTION_MAX_FILE_SIZE, 100L);
        Resource r = XmiFiles.open(set, file);
        assertTrue(errors(r).contains("than the 100 bytes RsaML reads"), () -> errors(r));
    }
}
