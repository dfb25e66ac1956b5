/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;

/** Every way a file can be unfit is one clear message naming the file, and the location when there is one. */
class LoadErrorsTest {

    @TempDir
    Path dir;

    private ModelLoadException fails(String name, byte[] content) throws Exception {
        Path file = dir.resolve(name);
        if (content != null) {
            Files.write(file, content);
        }
        return assertThrows(ModelLoadException.class, () -> ModelLoader.load(file, name));
    }

    private ModelLoadException fails(String name, String content) throws Exception {
        return fails(name, content.getBytes(java.nio.charset.StandardCharsets.UTF_8));
    }

    @Test
    void missingFile() throws Exception {
        ModelLoadException e = fails("missing.rsaml", (byte[]) null);
        assertEquals("missing.rsaml: error: no such file", e.toString());
    }

    @Test
    void emptyFile() throws Exception {
        assertTrue(fails("empty.rsaml", "").getMessage().startsWith("the file is empty"));
    }

    @Test
    void binaryFile() throws Exception {
        assertTrue(fails("image.rsaml", new byte[] { (byte) 0x89, 'P', 'N', 'G', 0, 0, 0, 13 }).getMessage().contains("binary"));
    }

    @Test
    void malformedXmlIsLocated() throws Exception {
        ModelLoadException e = fails("broken.rsaml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <rsaml:Architecture xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:rsaml="http://www.rsaml.org/rsaml/1.0" name="r">
                  <layers name="a">
                </rsaml:Architecture>
                """);
        assertTrue(e.getMessage().startsWith("malformed XML"), e.getMessage());
        assertEquals(4, e.line());
        assertTrue(e.toString().startsWith("broken.rsaml:4:"), e.toString());
    }

    @Test
    void xmlOfAnotherLanguage() throws Exception {
        ModelLoadException e = fails("other.rsaml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <x:Model xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:x="http://example.org/other/1.0" name="r"/>
                """);
        assertTrue(e.getMessage().contains("namespace 'http://example.org/other/1.0' is not RsaML's"), e.getMessage());
    }

    @Test
    void plainXmlWithoutNamespace() throws Exception {
        ModelLoadException e = fails("plain.rsaml", "<?xml version=\"1.0\"?>\n<project><name>x</name></project>\n");
        assertTrue(e.getMessage().contains("not an RsaML"), e.getMessage());
    }

    @Test
    void rootThatIsNotAnArchitecture() throws Exception {
        ModelLoadException e = fails("layer.rsaml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <rsaml:Layer xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:rsaml="http://www.rsaml.org/rsaml/1.0" name="l"/>
                """);
        assertTrue(e.getMessage().contains("root element is a Layer"), e.getMessage());
    }

    @Test
    void referenceToAMissingElementIsLocated() throws Exception {
        ModelLoadException e = fails("dangling.rsaml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <rsaml:Architecture xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:rsaml="http://www.rsaml.org/rsaml/1.0" name="r" declaredLayers="1">
                  <layers name="a">
                    <modules name="m"/>
                  </layers>
                  <connections source="//@layers[name='a']/@modules[name='m']/@ports[name='nope']" target="//@layers[name='a']/@modules[name='m']/@ports[name='none']"/>
                </rsaml:Architecture>
                """);
        assertTrue(e.getMessage().contains("nope") && e.getMessage().contains("does not exist"), e.getMessage());
        assertEquals(6, e.line());
    }

    @Test
    void referenceToAMissingFile() throws Exception {
        ModelLoadException e = fails("other-file.rsaml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <rsaml:Architecture xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:rsaml="http://www.rsaml.org/rsaml/1.0" name="r" declaredLayers="1">
                  <layers name="a">
                    <modules name="m">
                      <ports xsi:type="rsaml:EntryPort" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" name="e"/>
                    </modules>
                  </layers>
                  <connections>
                    <source href="missing.rsaml#//@layers.0/@modules.0/@ports.0"/>
                    <target href="#//@layers.0/@modules.0/@ports.0"/>
                  </connections>
                </rsaml:Architecture>
                """);
        assertTrue(e.getMessage().contains("missing.rsaml"), e.getMessage());
    }

    @Test
    void externalEntitiesAreNeverResolved() throws Exception {
        Path secret = dir.resolve("secret.txt");
        Files.writeString(secret, "TOP-SECRET-CONTENT");
        ModelLoadException e = fails("xxe.rsaml", "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY s SYSTEM \""
                + secret.toUri() + "\">]>\n<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&s;\"/>\n");
        assertTrue(e.getMessage().contains("DOCTYPE declarations are not allowed"), e.getMessage());
        assertTrue(!e.toString().contains("TOP-SECRET"), e.toString());
    }

    @Test
    void entityExpansionIsRefused() throws Exception {
        StringBuilder lol = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY a \"lol\">");
        for (int i = 1; i < 10; i++) {
            lol.append("<!ENTITY ").append((char) ('a' + i)).append(" \"");
            lol.append(("&" + (char) ('a' + i - 1) + ";").repeat(10)).append("\">");
        }
        lol.append("]>\n<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&j;\"/>\n");
        ModelLoadException e = fails("bomb.rsaml", lol.toString());
        assertTrue(e.getMessage().contains("DOCTYPE"), e.getMessage());
    }
}
