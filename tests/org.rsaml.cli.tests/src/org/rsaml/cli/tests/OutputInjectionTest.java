/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.xml.sax.InputSource;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Names from a model, and file names, reach terminals and CI logs: they must not forge lines,
 * escape sequences or workflow commands there, while JSON, SARIF and JUnit keep them faithfully.
 */
class OutputInjectionTest {

    /** A module name with a newline, a CI workflow command, a carriage return and NEL. */
    static final String HOSTILE = "planner&#10;::error file=x.rsaml,line=1::forged&#13;&#133;##vso[task.complete]";
    static final String HOSTILE_DECODED = "planner\n::error file=x.rsaml,line=1::forged\r\u0085##vso[task.complete]";

    static String model(String moduleName, String xmlVersion) {
        return "<?xml version=\"" + xmlVersion + "\" encoding=\"UTF-8\"?>\n"
                + "<rsaml:Architecture xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\"\n"
                + "    xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"rover\" declaredLayers=\"2\">\n"
                + "  <layers name=\"functional\" level=\"0\" maxExecTime=\"5.0\">\n"
                + "    <modules name=\"odometry\" execType=\"periodic\" period=\"10.0\" delay=\"10.0\" execDuration=\"2.0\"/>\n"
                + "  </layers>\n"
                + "  <layers name=\"decision\" level=\"1\" maxExecTime=\"2.0\">\n"
                + "    <modules name=\"" + moduleName + "\" execType=\"periodic\" period=\"100.0\" delay=\"100.0\" execDuration=\"20.0\"/>\n"
                + "  </layers>\n"
                + "</rsaml:Architecture>\n";
    }

    /** Every line is one line of RsaML's: no control character, no line a CI runner takes as a command. */
    static void assertSafeLines(String output, Cli.Result r) {
        for (int i = 0; i < output.length(); i++) {
            char c = output.charAt(i);
            assertFalse(c != '\n' && (c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == '\u2028' || c == '\u2029'),
                    () -> "control character U+" + Integer.toHexString(c) + " printed\n" + r);
        }
        for (String line : output.split("\n")) {
            assertFalse(line.stripLeading().startsWith("::"), () -> "workflow command printed: " + line + "\n" + r);
            assertFalse(line.contains("##vso["), () -> "Azure logging command printed: " + line + "\n" + r);
        }
    }

    @Test
    void textEscapesNamesThatWouldForgeLines(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("rover.rsaml"), model(HOSTILE, "1.0"));
        Cli.Result r = Cli.runIn(dir, "validate", "rover.rsaml");
        assertEquals(1, r.code(), r::toString);
        assertSafeLines(r.out(), r);
        assertSafeLines(r.err(), r);
        assertTrue(r.out().contains("Module 'planner\\n::error file=x.rsaml,line=1::forged\\r\\x85\\x23#vso[task.complete]' takes 20.0 ms"),
                r::toString);
    }

    @Test
    void xml11EscapeSequencesDoNotReachTheTerminal(@TempDir Path dir) throws Exception {
        // XML 1.1 allows C0 characters as references: an ANSI sequence that would recolour or clear a terminal.
        Files.writeString(dir.resolve("rover.rsaml"), model("planner&#x1b;[2J&#x1b;]0;title&#x7;&#x9b;31m", "1.1"));
        Cli.Result r = Cli.runIn(dir, "validate", "rover.rsaml");
        assertSafeLines(r.out(), r);
        assertSafeLines(r.err(), r);
        assertFalse(r.out().contains("\u001b") || r.err().contains("\u001b"), r::toString);
    }

    @Test
    void fileNamesAreEscapedToo(@TempDir Path dir) throws Exception {
        Path models = Files.createDirectories(dir.resolve("m"));
        Files.writeString(models.resolve("::error title=forged::x\n.rsaml"), "not a model");
        Files.writeString(models.resolve("rover.rsaml"), model(HOSTILE, "1.0"));
        Cli.Result r = Cli.runIn(models, "validate", ".");
        assertEquals(2, r.code(), r::toString);
        assertSafeLines(r.out(), r);
        assertTrue(r.out().startsWith("\\x3a:error title=forged::x\\n.rsaml:"), r::toString);

        Cli.Result json = Cli.runIn(models, "validate", "--format", "json", ".");
        assertSafeLines(json.err(), json);
    }

    @Test
    void structuredReportsStayWellFormedAndFaithful(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("rover.rsaml"), model(HOSTILE, "1.0"));
        Cli.Result json = Cli.runIn(dir, "validate", "--format", "json", "rover.rsaml");
        JsonObject finding = JsonParser.parseString(json.out()).getAsJsonObject().getAsJsonArray("files").get(0)
                .getAsJsonObject().getAsJsonArray("findings").asList().stream().map(e -> e.getAsJsonObject())
                .filter(f -> f.get("ruleId").getAsString().equals("RSA-08")).findFirst().orElseThrow();
        assertTrue(finding.get("message").getAsString().contains(HOSTILE_DECODED), json::toString);

        Cli.Result sarif = Cli.runIn(dir, "validate", "--format", "sarif", "rover.rsaml");
        assertEquals(List.of(), List.copyOf(ReportFormatsTest.sarifProblems(sarif.out())), sarif::toString);
        assertTrue(JsonParser.parseString(sarif.out()).getAsJsonObject().getAsJsonArray("runs").get(0).getAsJsonObject()
                .getAsJsonArray("results").asList().stream()
                .anyMatch(e -> e.getAsJsonObject().getAsJsonObject("message").get("text").getAsString().contains(HOSTILE_DECODED)),
                sarif::toString);

        Cli.Result junit = Cli.runIn(dir, "validate", "--format", "junit", "rover.rsaml");
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new InputSource(new StringReader(junit.out())));
        assertTrue(doc.getDocumentElement().getTextContent().contains("planner\\n::error"), junit::toString);
        assertSafeLines(junit.out(), junit);
    }
}
