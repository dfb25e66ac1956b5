/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.resource.RsamlResourceFactory;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.model.resource.SourceLocation;

/**
 * Any EMF client that opens a .rsaml file in the ordinary way (a plain resource set, the
 * registered factory) gets RsaML's resource: no DTD, no entity, located errors.
 */
class LoadingTest {

    static final String ROOT = "<rsaml:Architecture xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\""
            + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\""
            + " name=\"robot\" declaredLayers=\"1\">";

    @TempDir
    Path dir;

    /** A model whose root holds {@code body}, with an XML declaration. */
    static String model(String body) {
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + ROOT + "\n" + body + "</rsaml:Architecture>\n";
    }

    Path write(String name, String content) throws Exception {
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

    @Test
    void theRegisteredFactoryIsRsamlsInEveryRegistry() {
        URI uri = URI.createFileURI(dir.resolve("x.rsaml").toString());
        assertInstanceOf(RsamlResourceFactory.class, Resource.Factory.Registry.INSTANCE.getFactory(uri));
        assertInstanceOf(RsamlResource.class, new ResourceSetImpl().createResource(uri));
        assertInstanceOf(RsamlResource.class, RsamlStandaloneSetup.newResourceSet().createResource(uri));
    }

    @Test
    void aPlainResourceSetRefusesADoctypeWithItsLocation() throws Exception {
        Path file = write("xxe.rsaml", "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY s \"EXPANDED\">]>\n"
                + "<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&s;\"/>\n");
        Resource r = open(file);
        assertInstanceOf(RsamlResource.class, r);
        assertEquals(1, r.getErrors().size(), () -> errors(r));
        Resource.Diagnostic d = r.getErrors().get(0);
        assertEquals("DOCTYPE declarations are not allowed in .rsaml files (DTDs and external entities are never loaded)", d.getMessage());
        assertEquals(2, d.getLine());
        assertEquals(10, d.getColumn());
        assertTrue(r.getContents().isEmpty() || !String.valueOf(((Architecture) r.getContents().get(0)).getName()).contains("EXPANDED"));
    }

    @Test
    void aCallersOwnParserOptionsCannotSwitchTheProtectionOff() throws Exception {
        Path file = write("xxe.rsaml", "<?xml version=\"1.0\"?>\n<!DOCTYPE r [<!ENTITY s \"EXPANDED\">]>\n"
                + "<rsaml:Architecture xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"&s;\"/>\n");
        ResourceSet set = new ResourceSetImpl();
        set.getLoadOptions().put(org.eclipse.emf.ecore.xmi.XMLResource.OPTION_PARSER_FEATURES,
                java.util.Map.of("http://apache.org/xml/features/disallow-doctype-decl", Boolean.FALSE));
        Resource r = open(set, file);
        assertTrue(errors(r).contains("DOCTYPE declarations are not allowed"), () -> errors(r));
    }

    @Test
    void elementsAreLocatedAtTheirStartTags() throws Exception {
        Path file = write("m.rsaml", model("  <layers name=\"a\">\n    <!-- c --><modules name=\"m\"/>\n  </layers>\n"));
        RsamlResource r = (RsamlResource) open(file);
        assertEquals("", errors(r));
        Architecture a = (Architecture) r.getContents().get(0);
        assertEquals(new SourceLocation(file.toString(), 2, 1), r.locate(a));
        assertEquals(new SourceLocation(file.toString(), 3, 3), r.locate(a.getLayers().get(0)));
        assertEquals(new SourceLocation(file.toString(), 4, 15), r.locate(a.getLayers().get(0).getModules().get(0)));
    }

    @Test
    void nameKeyedReferencesResolve() throws Exception {
        Path file = write("refs.rsaml", model("""
                  <layers name="a">
                    <modules name="m1"><ports xsi:type="rsaml:OutputPort" name="o"/></modules>
                    <modules name="m2"><ports xsi:type="rsaml:EntryPort" name="e"/></modules>
                  </layers>
                  <connections source="//@layers[name='a']/@modules[name='m1']/@ports[name='o']" target="//@layers[name='a']/@modules[name='m2']/@ports[name='e']"/>
                """));
        Resource r = open(file);
        assertEquals("", errors(r));
        Architecture a = (Architecture) r.getContents().get(0);
        assertEquals("m1", ((Module) a.getConnections().get(0).getSource().eContainer()).getName());
        assertEquals("m2", ((Module) a.getConnections().get(0).getTarget().eContainer()).getName());
    }

    /** The positions of the layers of {@code text}, computed by counting '\n' before each '<layers'. */
    static List<String> expectedLayerPositions(String text) {
        List<String> out = new ArrayList<>();
        for (int at = text.indexOf("<layers"); at >= 0; at = text.indexOf("<layers", at + 1)) {
            String before = text.substring(0, at);
            int line = (int) before.chars().filter(c -> c == '\n').count() + 1;
            out.add(line + ":" + (at - before.lastIndexOf('\n')));
        }
        return out;
    }

    static List<String> layerPositions(RsamlResource r) {
        return ((Architecture) r.getContents().get(0)).getLayers().stream().map(r::locate)
                .map(l -> l.line() + ":" + l.column()).toList();
    }

    static final String LINES = "<?xml version=\"VERSION\" encoding=\"UTF-8\"?>\n" + ROOT + "\n  <layers name=\"a\"/>\n"
            + "  <layers name=\"b\" description=\"two\nlines\"/>\n\n    <layers name=\"c\"/>  <layers name=\"d\"/>\n"
            + "  <!-- a\ncomment --><layers name=\"e\"/>\n</rsaml:Architecture>\n";

    void assertLocatedWithLineEnd(String name, String version, String... ends) throws Exception {
        String template = LINES.replace("VERSION", version);
        StringBuilder text = new StringBuilder();
        int n = 0;
        for (char c : template.toCharArray()) {
            text.append(c == '\n' ? ends[n++ % ends.length] : String.valueOf(c));
        }
        Path file = dir.resolve(name + ".rsaml");
        Files.write(file, text.toString().getBytes(StandardCharsets.UTF_8));
        RsamlResource r = (RsamlResource) open(file);
        assertEquals("", errors(r), name);
        assertEquals(expectedLayerPositions(template), layerPositions(r), name);
        assertEquals(2, r.locate(r.getContents().get(0)).line(), name);
        // A line break inside an attribute value counts as one line, as the parser counts it.
        assertEquals("two lines", ((Architecture) r.getContents().get(0)).getLayers().get(1).getDescription().replace('\n', ' '));
    }

    @Test
    void linesEndingInLineFeed() throws Exception {
        assertLocatedWithLineEnd("lf", "1.0", "\n");
    }

    @Test
    void linesEndingInCarriageReturnLineFeed() throws Exception {
        assertLocatedWithLineEnd("crlf", "1.0", "\r\n");
    }

    @Test
    void linesEndingInCarriageReturnOnly() throws Exception {
        assertLocatedWithLineEnd("cr", "1.0", "\r");
    }

    @Test
    void mixedLineEnds() throws Exception {
        assertLocatedWithLineEnd("mixed", "1.0", "\r", "\n", "\r\n", "\r\n", "\n", "\r");
    }

    @Test
    void nextLineAndLineSeparatorEndLinesInXml11() throws Exception {
        assertLocatedWithLineEnd("nel", "1.1", "\u0085", "\n", "\u2028", "\r\u0085");
    }

    @Test
    void utf16WithByteOrderMarkLoadsAndIsLocated() throws Exception {
        String template = LINES.replace("VERSION", "1.0").replace("UTF-8", "UTF-16");
        for (var charset : List.of(StandardCharsets.UTF_16LE, StandardCharsets.UTF_16BE)) {
            Path file = dir.resolve("utf16-" + charset.name() + ".rsaml");
            // Lone carriage returns too, which are two bytes wide here.
            Files.write(file, ("\uFEFF" + template.replace("\n", charset == StandardCharsets.UTF_16LE ? "\r" : "\r\n")).getBytes(charset));
            RsamlResource r = (RsamlResource) open(file);
            assertEquals("", errors(r), charset.name());
            assertEquals(expectedLayerPositions(template), layerPositions(r), charset.name());
        }
    }

    @Test
    void utf8ByteOrderMarkTakesNoColumn() throws Exception {
        String text = ROOT + "<layers name=\"a\"/></rsaml:Architecture>";
        Path file = dir.resolve("bom.rsaml");
        Files.write(file, ("\uFEFF" + text).getBytes(StandardCharsets.UTF_8));
        RsamlResource r = (RsamlResource) open(file);
        assertEquals("", errors(r));
        assertEquals(1, r.locate(r.getContents().get(0)).column());
        assertEquals(List.of("1:" + (text.indexOf("<layers") + 1)), layerPositions(r));
    }

    @Test
    void multiByteCharacterAcrossAnyBufferBoundaryLoads() throws Exception {
        // A three-byte character at every offset around 8 KiB and 16 KiB.
        StringBuilder layers = new StringBuilder();
        String head = model("");
        int fill = 8192 - head.getBytes(StandardCharsets.UTF_8).length - 40;
        for (int i = 0; i < 12; i++) {
            layers.append("  <layers name=\"l").append(i).append("\" description=\"").append("x".repeat(i == 0 ? fill : 700 + i))
                    .append("\u20AC\u00E9\"/>\n");
        }
        Path file = write("big.rsaml", model(layers.toString()));
        Resource r = open(file);
        assertEquals("", errors(r));
        List<Layer> loaded = ((Architecture) r.getContents().get(0)).getLayers();
        assertEquals(12, loaded.size());
        assertTrue(loaded.stream().allMatch(l -> l.getDescription().endsWith("\u20AC\u00E9")));
    }

    @Test
    void invalidUtf8IsOneLocatedSentenceWithoutTheAbsolutePath() throws Exception {
        byte[] good = model("  <layers name=\"" + "a".repeat(9000) + "\"/>\n  <layers name=\"b\" description=\"X\"/>\n").getBytes(StandardCharsets.UTF_8);
        int x = new String(good, StandardCharsets.ISO_8859_1).lastIndexOf('X');
        good[x] = (byte) 0xff;
        Path file = dir.resolve("bad-utf8.rsaml");
        Files.write(file, good);
        Resource r = open(file);
        Resource.Diagnostic d = r.getErrors().get(0);
        assertTrue(d.getMessage().contains("not valid UTF-8"), d.getMessage());
        assertFalse(d.getMessage().contains(dir.toString()), d.getMessage());
        assertEquals(4, d.getLine());
        assertTrue(d.getColumn() > 0);
    }

    @Test
    void unknownEncodingIsNamed() throws Exception {
        Path file = write("enc.rsaml", model("").replace("UTF-8", "klingon-1"));
        Resource r = open(file);
        assertEquals("1:1: the XML declaration names the encoding 'klingon-1', which is not known here; save the file as UTF-8"
                + " and declare encoding=\"UTF-8\"", errors(r));
    }

    @Test
    void nonFiniteNumbersAreLocatedErrorsNamingTheAttribute() throws Exception {
        for (String value : List.of("NaN", "Infinity", "-Infinity", "1e999")) {
            Path file = write("nan.rsaml", model("  <layers name=\"a\" maxExecTime=\"2\">\n    <modules name=\"m\" period=\"" + value + "\"/>\n  </layers>\n"));
            Resource r = open(file);
            assertEquals(1, r.getErrors().size(), () -> errors(r));
            Resource.Diagnostic d = r.getErrors().get(0);
            assertTrue(d.getMessage().startsWith("period=\"" + value + "\" is not a finite number"), d.getMessage());
            assertEquals(4, d.getLine(), value);
            assertEquals(5, d.getColumn(), value);
        }
    }

    @Test
    void aPortWithoutTypeListsTheTypesOfTheMetamodel() throws Exception {
        Path file = write("port.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\">\n      <ports name=\"p\"/>\n    </modules>\n  </layers>\n"));
        Resource r = open(file);
        Resource.Diagnostic d = r.getErrors().get(0);
        assertEquals("<ports name=\"p\"> does not say which kind of Port it is, so it cannot be read: add xsi:type=\"rsaml:EntryPort\""
                + " or xsi:type=\"rsaml:OutputPort\" to it", d.getMessage());
        assertEquals("5:7", d.getLine() + ":" + d.getColumn());
    }

    /** References to an element without a type are told in its error, not each as dangling; others still are. */
    @Test
    void referencesToAnUntypedPortAreCountedInItsErrorOnly() throws Exception {
        String m = "//@layers[name='a']/@modules[name='m']/@ports";
        Path file = write("refs.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\">\n"
                + "      <ports xsi:type=\"rsaml:OutputPort\" name=\"out\"/>\n      <ports name=\"p\"/>\n    </modules>\n  </layers>\n"
                + "  <connections source=\"" + m + "[name='out']\" target=\"" + m + "[name='p']\"/>\n"
                + "  <connections source=\"" + m + "[name='out']\" target=\"" + m + "[name='gone']\"/>\n"));
        Resource r = open(file);
        assertEquals(List.of("6:7: <ports name=\"p\"> does not say which kind of Port it is, so it cannot be read: add"
                + " xsi:type=\"rsaml:EntryPort\" or xsi:type=\"rsaml:OutputPort\" to it; the reference to it (line 9) will resolve once it has one",
                "10:3: reference target points to '" + m + "[name='gone']', which does not exist"),
                r.getErrors().stream().map(d -> d.getLine() + ":" + d.getColumn() + ": " + d.getMessage()).toList());
    }

    @Test
    void aWrongEnumValueListsTheLiteralsOfTheMetamodel() throws Exception {
        Path file = write("enum.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\" execType=\"weekly\"/>\n  </layers>\n"));
        Resource r = open(file);
        String literals = RsamlPackage.Literals.REAL_TIME_ELEMENT__EXEC_TYPE.getEType() instanceof org.eclipse.emf.ecore.EEnum e
                ? e.getELiterals().stream().map(l -> l.getLiteral()).collect(Collectors.joining(", ")) : "";
        Resource.Diagnostic d = r.getErrors().get(0);
        assertTrue(d.getMessage().startsWith("'weekly' is not a value of execType; write one of "), d.getMessage());
        for (String literal : literals.split(", ")) {
            assertTrue(d.getMessage().contains(literal), d.getMessage());
        }
        assertEquals("4:5", d.getLine() + ":" + d.getColumn());
    }

    @Test
    void aTimeWrittenWithItsUnitPointsToTimeUnit() throws Exception {
        Path file = write("ms.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\" period=\"50ms\"/>\n  </layers>\n"));
        Resource.Diagnostic d = open(file).getErrors().get(0);
        assertEquals("'50ms' is not a number: write the number alone and the unit apart, period=\"50\" timeUnit=\"ms\"", d.getMessage());
        assertEquals("4:5", d.getLine() + ":" + d.getColumn());
    }

    @Test
    void aReversedConnectionIsLocated() throws Exception {
        Path file = write("reversed.rsaml", model("""
                  <layers name="a">
                    <modules name="m"><ports xsi:type="rsaml:EntryPort" name="e"/><ports xsi:type="rsaml:OutputPort" name="o"/></modules>
                  </layers>
                  <connections source="//@layers.0/@modules.0/@ports.0" target="//@layers.0/@modules.0/@ports.1"/>
                """));
        Resource r = open(file);
        Resource.Diagnostic d = r.getErrors().get(0);
        assertEquals("reference source must name an OutputPort, but 'e' is an EntryPort", d.getMessage());
        assertEquals("6:3", d.getLine() + ":" + d.getColumn());
    }

    @Test
    void binaryAndEmptyFilesAreSaidSo() throws Exception {
        Path empty = write("empty.rsaml", "");
        assertTrue(open(empty).getErrors().get(0).getMessage().startsWith("the file is empty"));
        Path binary = dir.resolve("image.rsaml");
        Files.write(binary, new byte[] { (byte) 0x89, 'P', 'N', 'G', 0, 0, 0, 13 });
        assertTrue(open(binary).getErrors().get(0).getMessage().startsWith("the file is binary"));
        // About the whole file: no line or column that would send the user looking at line 1.
        assertEquals(0, open(empty).getErrors().get(0).getLine());
        assertEquals(0, open(binary).getErrors().get(0).getLine());
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
        RsamlResource deep = (RsamlResource) open(write("deep.rsaml", nestedGoals(RsamlResource.MAX_DEPTH - 2)));
        assertEquals("", errors(deep));
        assertEquals(RsamlResource.MAX_DEPTH, deep.locatedElementCount());

        Resource tooDeep = open(write("too-deep.rsaml", nestedGoals(RsamlResource.MAX_DEPTH - 1)));
        assertEquals((RsamlResource.MAX_DEPTH + 2) + ":1: elements are nested more than " + RsamlResource.MAX_DEPTH
                + " levels deep here; RsaML reads models up to that depth", errors(tooDeep));
    }

    @Test
    void deeplyNestedExtensionsAreRefusedToo() throws Exception {
        int levels = 50_000;
        String body = "  <xmi:Extension extender=\"x\">" + "<a>".repeat(levels) + "</a>".repeat(levels) + "</xmi:Extension>\n";
        Resource r = open(write("extensions.rsaml", model(body)));
        assertEquals(1, r.getErrors().size(), () -> errors(r));
        assertTrue(errors(r).startsWith("3:"), () -> errors(r));
        assertTrue(errors(r).contains("nested more than " + RsamlResource.MAX_DEPTH + " levels"), () -> errors(r));
    }

    @Test
    void aRootInNoNamespaceIsNamed() throws Exception {
        Resource r = open(write("plain.rsaml", "<?xml version=\"1.0\"?>\n<Architecture name=\"r\"/>\n"));
        assertEquals("2:1: element 'Architecture' is in no namespace, so this is not an RsaML model; an RsaML model's root is"
                + " rsaml:Architecture with xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\"", errors(r).lines().findFirst().orElse(""));
    }

    @Test
    void aTypeWithoutPrefixListsTheTypesOfTheMetamodel() throws Exception {
        Path file = write("type.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\">\n      <ports xsi:type=\"EntryPort\" name=\"p\"/>\n"
                + "    </modules>\n  </layers>\n"));
        Resource.Diagnostic d = open(file).getErrors().get(0);
        assertEquals("xsi:type=\"EntryPort\" names a type without RsaML's namespace prefix; write xsi:type=\"rsaml:EntryPort\""
                + " or xsi:type=\"rsaml:OutputPort\"", d.getMessage());
        assertEquals("5:7", d.getLine() + ":" + d.getColumn());
    }

    @Test
    void aFileCutShortIsSaidSo() throws Exception {
        String whole = model("  <layers name=\"a\">\n    <modules name=\"m\"/>\n  </layers>\n");
        Resource r = open(write("cut.rsaml", whole.substring(0, whole.indexOf("<modules"))));
        assertEquals("the file ends before its elements are closed; it may have been cut short", r.getErrors().get(0).getMessage());
        assertTrue(r.getErrors().get(0).getLine() >= 3, () -> errors(r));
    }

    @Test
    void anUnexpectedExceptionIsAnErrorOfThatFileOnly() throws Exception {
        Path file = write("faulty.rsaml", model("  <layers name=\"a\"/>\n"));
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
                + " please report it together with the file", errors(r));
        Resource other = open(set, write("fine.rsaml", model("  <layers name=\"a\"/>\n")));
        assertEquals("", errors(other));
    }

    @Test
    void aParserMessageQuotingSeveralLinesIsOneLine() throws Exception {
        Resource r = open(write("version.rsaml", model("").replace("version=\"1.0\"", "version=\"1.0\n  and more\n\"")));
        String message = r.getErrors().get(0).getMessage();
        assertTrue(message.startsWith("malformed XML: ") && message.contains("1.0 and more"), message);
        assertFalse(message.contains("\n"), message);
    }

    @Test
    void everyLoadedElementHasAPosition() throws Exception {
        Path file = write("all.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\"/>\n  </layers>\n"));
        RsamlResource r = (RsamlResource) open(file);
        for (var it = EcoreUtil.<EObject>getAllContents(r, false); it.hasNext();) {
            EObject o = it.next();
            assertTrue(r.locate(o).line() > 0, o.toString());
        }
        assertNotNull(r.locate(r.getContents().get(0)));
    }
}
