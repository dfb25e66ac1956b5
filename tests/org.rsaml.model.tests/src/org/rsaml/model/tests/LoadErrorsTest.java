/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.rsaml.model.tests.XmiFiles.errors;
import static org.rsaml.model.tests.XmiFiles.model;
import static org.rsaml.model.tests.XmiFiles.open;
import static org.rsaml.model.tests.XmiFiles.write;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.RsamlPackage;

/**
 * A model that is well-formed XML but not a valid RsaML model is refused with one located sentence per fault that
 * says what is wrong and what to write instead, in the metamodel's words.
 */
class LoadErrorsTest {

    @TempDir
    Path dir;

    @Test
    void nonFiniteNumbersAreLocatedErrorsNamingTheAttribute() throws Exception {
        for (String value : List.of("NaN", "Infinity", "-Infinity", "1e999")) {
            Path file = write(dir, "nan.rsaml", model("  <layers name=\"a\" maxExecTime=\"2\">\n    <modules name=\"m\" period=\"" + value + "\"/>\n  </layers>\n"));
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
        Path file = write(dir, "port.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\">\n      <ports name=\"p\"/>\n    </modules>\n  </layers>\n"));
        Resource r = open(file);
        Resource.Diagnostic d = r.getErrors().get(0);
        assertEquals("<ports name=\"p\"> does not say which kind of Port it is, so it cannot be read: add xsi:type=\"rsaml:EntryPort\""
                + " or xsi:type=\"rsaml:OutputPort\" to it", d.getMessage(), "an untyped port's error names the port and the types to choose from");
        assertEquals("5:7", d.getLine() + ":" + d.getColumn(), "the error points at the port's start tag");
    }

    /** References to an element without a type are told in its error, not each as dangling; others still are. */
    @Test
    void referencesToAnUntypedPortAreCountedInItsErrorOnly() throws Exception {
        String m = "//@layers[name='a']/@modules[name='m']/@ports";
        Path file = write(dir, "refs.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\">\n"
                + "      <ports xsi:type=\"rsaml:OutputPort\" name=\"out\"/>\n      <ports name=\"p\"/>\n    </modules>\n  </layers>\n"
                + "  <connections source=\"" + m + "[name='out']\" target=\"" + m + "[name='p']\"/>\n"
                + "  <connections source=\"" + m + "[name='out']\" target=\"" + m + "[name='gone']\"/>\n"));
        Resource r = open(file);
        assertEquals(List.of("6:7: <ports name=\"p\"> does not say which kind of Port it is, so it cannot be read: add"
                + " xsi:type=\"rsaml:EntryPort\" or xsi:type=\"rsaml:OutputPort\" to it; the reference to it (line 9) will resolve once it has one",
                "10:3: reference target points to '" + m + "[name='gone']', which does not exist"),
                r.getErrors().stream().map(d -> d.getLine() + ":" + d.getColumn() + ": " + d.getMessage()).toList(), "the untyped port is one error that counts the reference to it; a dangling reference is another, each located");
    }

    @Test
    void aWrongEnumValueListsTheLiteralsOfTheMetamodel() throws Exception {
        Path file = write(dir, "enum.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\" execType=\"weekly\"/>\n  </layers>\n"));
        Resource r = open(file);
        String literals = RsamlPackage.Literals.REAL_TIME_ELEMENT__EXEC_TYPE.getEType() instanceof org.eclipse.emf.ecore.EEnum e
                ? e.getELiterals().stream().map(l -> l.getLiteral()).collect(Collectors.joining(", ")) : "";
        Resource.Diagnostic d = r.getErrors().get(0);
        assertTrue(d.getMessage().startsWith("'weekly' is not a value of execType; write one of "), d.getMessage());
        for (String literal : literals.split(", ")) {
            assertTrue(d.getMessage().contains(literal), d.getMessage());
        }
        assertEquals("4:5", d.getLine() + ":" + d.getColumn(), "the error points at the module's start tag");
    }

    @Test
    void aTimeWrittenWithItsUnitPointsToTimeUnit() throws Exception {
        Path file = write(dir, "ms.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\" period=\"50ms\"/>\n  </layers>\n"));
        Resource.Diagnostic d = open(file).getErrors().get(0);
        assertEquals("'50ms' is not a number: write the number alone and the unit apart, period=\"50\" timeUnit=\"ms\"", d.getMessage(), "a time written with its unit says how to write it");
        assertEquals("4:5", d.getLine() + ":" + d.getColumn(), "the error points at the module's start tag");
    }

    @Test
    void aReversedConnectionIsLocated() throws Exception {
        Path file = write(dir, "reversed.rsaml", model("""
                  <layers name="a">
                    <modules name="m"><ports xsi:type="rsaml:EntryPort" name="e"/><ports xsi:type="rsaml:OutputPort" name="o"/></modules>
                  </layers>
                  <connections source="//@layers.0/@modules.0/@ports.0" target="//@layers.0/@modules.0/@ports.1"/>
                """));
        Resource r = open(file);
        Resource.Diagnostic d = r.getErrors().get(0);
        assertEquals("reference source must name an OutputPort, but 'e' is an EntryPort", d.getMessage(), "a connection from an entry port is refused, saying which kind it must name");
        assertEquals("6:3", d.getLine() + ":" + d.getColumn(), "the error points at the connection");
    }

    @Test
    void anElementNamedTwiceInAReferenceThatHoldsEachOnceIsSaidSo() throws Exception {
        Path file = write(dir, "via.rsaml", model("""
                  <layers name="a">
                    <modules name="detector"/>
                  </layers>
                  <latencyRequirements name="r" maxLatency="10.0" via="//@layers.0/@modules.0 //@layers.0/@modules.0"/>
                """));
        Resource.Diagnostic d = open(file).getErrors().get(0);
        assertEquals("reference via names 'detector' twice: name each element once", d.getMessage(),
                "the duplicate is the problem, not the kind of element");
        assertEquals("6:3", d.getLine() + ":" + d.getColumn(), "the error points at the requirement");
    }

    @Test
    void aRootInNoNamespaceIsNamed() throws Exception {
        Resource r = open(write(dir, "plain.rsaml", "<?xml version=\"1.0\"?>\n<Architecture name=\"r\"/>\n"));
        assertEquals("2:1: element 'Architecture' is in no namespace, so this is not an RsaML model; an RsaML model's root is"
                + " rsaml:Architecture with xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\"", errors(r).lines().findFirst().orElse(""), "a root in no namespace is said not to be an RsaML model, with the root RsaML expects");
    }

    @Test
    void aTypeWithoutPrefixListsTheTypesOfTheMetamodel() throws Exception {
        Path file = write(dir, "type.rsaml", model("  <layers name=\"a\">\n    <modules name=\"m\">\n      <ports xsi:type=\"EntryPort\" name=\"p\"/>\n"
                + "    </modules>\n  </layers>\n"));
        Resource.Diagnostic d = open(file).getErrors().get(0);
        assertEquals("xsi:type=\"EntryPort\" names a type without RsaML's namespace prefix; write xsi:type=\"rsaml:EntryPort\""
                + " or xsi:type=\"rsaml:OutputPort\"", d.getMessage(), "a type without the rsaml: prefix is named, with the types to write");
        assertEquals("5:7", d.getLine() + ":" + d.getColumn(), "the error points at the port's start tag");
    }

    @Test
    void aParserMessageQuotingSeveralLinesIsOneLine() throws Exception {
        Resource r = open(write(dir, "version.rsaml", model("").replace("version=\"1.0\"", "version=\"1.0\n  and more\n\"")));
        String message = r.getErrors().get(0).getMessage();
        assertTrue(message.startsWith("malformed XML: ") && message.contains("1.0 and more"), message);
        assertFalse(message.contains("\n"), message);
    }
}
