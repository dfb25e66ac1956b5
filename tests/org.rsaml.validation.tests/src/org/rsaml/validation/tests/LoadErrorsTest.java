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
import java.util.List;

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
        return assertThrows(ModelLoadException.class, () -> ModelLoader.load(file, name), name + " is refused with a located load error, not loaded nor a stack trace");
    }

    private ModelLoadException fails(String name, String content) throws Exception {
        return fails(name, content.getBytes(java.nio.charset.StandardCharsets.UTF_8));
    }

    @Test
    void missingFile() throws Exception {
        ModelLoadException e = fails("missing.rsaml", (byte[]) null);
        assertEquals("missing.rsaml: error: no such file", e.toString(), "a missing file is one compiler-style line naming it");
    }

    @Test
    void emptyFile() throws Exception {
        assertTrue(fails("empty.rsaml", "").getMessage().startsWith("the file is empty"), "an empty file is said to be empty");
    }

    @Test
    void binaryFile() throws Exception {
        assertTrue(fails("image.rsaml", new byte[] { (byte) 0x89, 'P', 'N', 'G', 0, 0, 0, 13 }).getMessage().contains("binary"), "a binary file is said to be binary");
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
        assertEquals(4, e.line(), "the error is at the line where the XML breaks");
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
        assertEquals(6, e.line(), "the error is at the connection's line");
        // Both ends are missing: both are reported, not the first alone.
        assertEquals(List.of("dangling.rsaml:6:3: error: reference source points to '//@layers[name='a']/@modules[name='m']/@ports[name='nope']', which does not exist",
                "dangling.rsaml:6:3: error: reference target points to '//@layers[name='a']/@modules[name='m']/@ports[name='none']', which does not exist"),
                e.problems().stream().map(ModelLoadException.Problem::toString).toList(), "both missing ends of the connection are reported, each located");
    }

    @Test
    void everyProblemOfTheFileIsKeptInTheOrderOfTheFile() throws Exception {
        ModelLoadException e = fails("many.rsaml", """
                <?xml version="1.0" encoding="UTF-8"?>
                <rsaml:Architecture xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:rsaml="http://www.rsaml.org/rsaml/1.0" name="r" declaredLayers="1">
                  <layers name="a">
                    <modules name="m1" execType="weekly"/>
                    <modules name="m2" period="50ms"/>
                    <modules name="m3" colour="red"/>
                  </layers>
                </rsaml:Architecture>
                """);
        List<ModelLoadException.Problem> problems = e.problems();
        assertEquals(List.of(4, 5, 6), problems.stream().map(p -> p.location().line()).toList(), e::toString);
        assertEquals(new ModelLoadException.Problem(e.location(), e.getMessage()), problems.get(0), "the first problem is the exception's own message and location");
        assertTrue(problems.get(1).message().startsWith("'50ms' is not a number"), e::toString);
        assertTrue(problems.get(2).message().startsWith("'colour' is not a feature of Module"), e::toString);
        assertEquals(3, e.toString().lines().count(), e::toString);
        assertTrue(e.toString().lines().allMatch(l -> l.startsWith("many.rsaml:")), e::toString);
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

    private static final String HEAD = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
            + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"r\" declaredLayers=\"1\">\n";

    @Test
    void aMultiByteCharacterAcrossByte8192Loads() throws Exception {
        String layer = "  <layers name=\"a\" description=\"";
        int pad = 8191 - (HEAD + layer).getBytes(java.nio.charset.StandardCharsets.UTF_8).length;
        String text = HEAD + layer + "x".repeat(pad) + "\u20AC\"/>\n</rsaml:Architecture>\n";
        Path file = dir.resolve("straddle.rsaml");
        Files.writeString(file, text);
        byte[] bytes = Files.readAllBytes(file);
        assertEquals((byte) 0xE2, bytes[8191], "the euro sign must start at byte 8191 and end after byte 8192");
        assertTrue(ModelLoader.load(file, "straddle.rsaml").architecture().getLayers().get(0).getDescription().endsWith("\u20AC"), "the euro sign across the 8 KiB buffer boundary is read whole");
    }

    @Test
    void utf16IsTextNotBinary() throws Exception {
        String text = "\uFEFF" + HEAD.replace("UTF-8", "UTF-16") + "  <layers name=\"a\"/>\n</rsaml:Architecture>\n";
        Path file = dir.resolve("utf16.rsaml");
        Files.write(file, text.getBytes(java.nio.charset.StandardCharsets.UTF_16LE));
        var model = ModelLoader.load(file, "utf16.rsaml");
        assertEquals("a", model.architecture().getLayers().get(0).getName(), "a UTF-16 model with a byte order mark loads");
        assertEquals(3, model.locate(model.architecture().getLayers().get(0))[0], "its layer is located on line 3");
    }

    @Test
    void invalidUtf8AfterTheFirstKilobytesIsLocatedWithoutAnAbsolutePath() throws Exception {
        byte[] bytes = (HEAD + "  <layers name=\"" + "a".repeat(9000) + "\"/>\n  <layers name=\"b\" description=\"X\"/>\n"
                + "</rsaml:Architecture>\n").getBytes(java.nio.charset.StandardCharsets.UTF_8);
        bytes[new String(bytes, java.nio.charset.StandardCharsets.ISO_8859_1).lastIndexOf('X')] = (byte) 0xC3;
        ModelLoadException e = fails("bad.rsaml", bytes);
        assertEquals(4, e.line(), e.toString());
        assertTrue(e.toString().startsWith("bad.rsaml:4:"), e.toString());
        assertTrue(e.getMessage().contains("not valid UTF-8"), e.getMessage());
        assertTrue(!e.getMessage().contains(dir.toString()), e.getMessage());
    }

    @Test
    void aReferencedFileWithADoctypeIsNotRead() throws Exception {
        Files.writeString(dir.resolve("devices.rsaml"), "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY s \"x\">]>\n"
                + "<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&s;\"><sensors name=\"s\"/></rsaml:Architecture>\n");
        ModelLoadException e = fails("uses.rsaml", HEAD + "  <layers name=\"a\">\n    <modules name=\"m\" sensors=\"devices.rsaml#//@sensors.0\"/>\n"
                + "  </layers>\n</rsaml:Architecture>\n");
        assertEquals("uses.rsaml:4:5: error: reference sensors points to 'devices.rsaml#//@sensors.0', which cannot be loaded:"
                + " devices.rsaml:2:10: DOCTYPE declarations are not allowed in .rsaml files (DTDs and external entities are never loaded)",
                e.toString(), "the reference names the referenced file and why it cannot be loaded, with that file's location");
    }

    @Test
    void aNetworkReferenceIsRefusedWithItsLocation() throws Exception {
        ModelLoadException e = fails("net.rsaml", HEAD + "  <layers name=\"a\">\n    <modules name=\"m\" sensors=\"http://127.0.0.1:9/x.rsaml#//@sensors.0\"/>\n"
                + "  </layers>\n</rsaml:Architecture>\n");
        assertTrue(e.toString().startsWith("net.rsaml:4:5: error: reference to 'http://127.0.0.1:9/x.rsaml' refused"), e.toString());
    }
}
