/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.rsaml.report.FileResult;
import org.rsaml.report.ModelBatch;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.ReportOptions;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The report bundle as Eclipse runs it (OSGi, its own class loader, Gson and StAX as bundles): the batch over the
 * examples and an unreadable input, written in every format, each saying the same findings as experiment 2 states in
 * its {@code <!-- expect: -->} comments.
 */
class ReportFormatsInOsgiTest {

    private static final String EXP2 = "examples/exp2-defects.rsaml";
    private static final String MISSING = "examples/no-such-model.rsaml";

    private static Report report;
    private static List<ExpectedFinding> expected;
    private static ReportOptions options;

    @BeforeAll
    static void checkTheExamples() throws Exception {
        Path root = TestRepository.root();
        report = ModelBatch.validate(root, List.of(Path.of("examples"), Path.of(MISSING)), Severity.ERROR);
        expected = ExpectedFinding.of(root.resolve(EXP2));
        options = new ReportOptions("0.0.0-test", root, false);
    }

    private static String write(ReportFormat format) throws Exception {
        StringWriter out = new StringWriter();
        format.write(report, out, options);
        return out.toString();
    }

    private static FileResult exp2() {
        return report.results().stream().filter(r -> r.file().equals(EXP2)).findFirst()
                .orElseThrow(() -> new AssertionError("the batch has no result for " + EXP2 + ": " + report.results()));
    }

    @Test
    void theBatchChecksEveryExampleAndReportsTheUnreadableInputWithoutHidingTheOthers() {
        List<ExpectedFinding> found = exp2().findings().stream()
                .map(f -> new ExpectedFinding(f.ruleId(), f.severity().label(), f.qualifiedName(), f.line(), f.column(), f.message()))
                .toList();
        assertEquals(expected, found, "exp2's findings are those its expect comments state");
        FileResult missing = report.results().stream().filter(r -> !r.readable()).findFirst()
                .orElseThrow(() -> new AssertionError("the missing model is reported: " + report.results()));
        assertTrue(missing.error().getMessage().contains("no-such-model.rsaml") || missing.file().contains("no-such-model.rsaml"),
                "the unreadable input is named: " + missing);
        assertEquals(1, report.unreadable(), "one input could not be read");
        assertEquals(2, report.exitCode(), "an unreadable input decides the exit code");
    }

    @Test
    void theTextReportHasALinePerFindingAndTheSummary() throws Exception {
        List<String> lines = write(ReportFormat.TEXT).lines().toList();
        for (Finding f : exp2().findings()) {
            String line = EXP2 + ":" + f.line() + ":" + f.column() + ": " + f.severity().label() + " " + f.ruleId() + ": " + f.message();
            assertTrue(lines.contains(line), "the text report has the line " + line + ":\n" + String.join("\n", lines));
        }
        assertEquals(report.summary(), lines.get(lines.size() - 1), "the last line is the summary");
    }

    @Test
    void theJsonReportListsEveryFileWithItsFindings() throws Exception {
        JsonObject doc = JsonParser.parseString(write(ReportFormat.JSON)).getAsJsonObject();
        assertEquals("0.0.0-test", doc.getAsJsonObject("tool").get("version").getAsString(), "the tool's version");
        JsonArray files = doc.getAsJsonArray("files");
        assertEquals(report.results().size(), files.size(), "one entry per input");
        JsonObject exp2 = null;
        for (var file : files) {
            if (file.getAsJsonObject().get("file").getAsString().equals(EXP2)) {
                exp2 = file.getAsJsonObject();
            }
        }
        assertNotNull(exp2, "exp2 is listed: " + files);
        List<String> rules = new ArrayList<>();
        exp2.getAsJsonArray("findings").forEach(f -> rules.add(f.getAsJsonObject().get("ruleId").getAsString()));
        assertEquals(expected.stream().map(ExpectedFinding::ruleId).toList(), rules, "exp2's findings in the model's order");
        assertEquals(report.exitCode(), doc.getAsJsonObject("summary").get("exitCode").getAsInt(), "the summary's exit code");
    }

    @Test
    void theSarifReportHasAResultPerFindingWithItsRule() throws Exception {
        JsonObject run = JsonParser.parseString(write(ReportFormat.SARIF)).getAsJsonObject().getAsJsonArray("runs").get(0)
                .getAsJsonObject();
        JsonArray rules = run.getAsJsonObject("tool").getAsJsonObject("driver").getAsJsonArray("rules");
        assertEquals(report.rules().size(), rules.size(), "every rule of the catalogue is described");
        long findings = report.results().stream().mapToLong(r -> r.findings().size()).sum();
        JsonArray results = run.getAsJsonArray("results");
        assertEquals(findings, results.size(), "one SARIF result per finding");
        for (var r : results) {
            JsonObject result = r.getAsJsonObject();
            String id = rules.get(result.get("ruleIndex").getAsInt()).getAsJsonObject().get("id").getAsString();
            assertEquals(id, result.get("ruleId").getAsString(), "ruleIndex points at the result's rule");
        }
        assertFalse(run.getAsJsonArray("invocations").get(0).getAsJsonObject().get("executionSuccessful").getAsBoolean(),
                "an unreadable input makes the run unsuccessful");
    }

    @Test
    void theJUnitReportFailsATestPerFailingFindingAndErrsOnTheUnreadableInput() throws Exception {
        byte[] xml = write(ReportFormat.JUNIT).getBytes(StandardCharsets.UTF_8);
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new ByteArrayInputStream(xml));
        Element suites = doc.getDocumentElement();
        assertEquals("testsuites", suites.getTagName(), "the root element");
        long failing = report.results().stream().flatMap(r -> r.findings().stream()).filter(report::fails).count();
        NodeList failures = doc.getElementsByTagName("failure");
        assertEquals(failing, failures.getLength(), "one failed test per finding at or above the threshold");
        assertEquals(Long.toString(failing), suites.getAttribute("failures"), "the total of failures");
        assertEquals(1, doc.getElementsByTagName("error").getLength(), "the unreadable input is an erroring test");
        List<String> types = new ArrayList<>();
        for (int i = 0; i < failures.getLength(); i++) {
            types.add(((Element) failures.item(i)).getAttribute("type"));
        }
        for (ExpectedFinding e : expected) {
            if (e.severity().equals("error")) {
                assertTrue(types.contains(e.ruleId()), e.what() + " fails a test: " + types);
            }
        }
    }

    @Test
    void theThresholdDecidesTheExitCode() {
        Path root = TestRepository.root();
        List<Path> exp2 = List.of(Path.of(EXP2));
        assertEquals(1, ModelBatch.validate(root, exp2, Severity.ERROR).exitCode(), "errors fail the run");
        assertEquals(0, ModelBatch.validate(root, exp2, null).exitCode(), "findings never fail the run when told so");
        assertEquals(0, ModelBatch.validate(root, List.of(Path.of("examples/exp3-task-interpreter.rsaml")), Severity.INFO).exitCode(),
                "a clean model passes at any threshold");
        List<Path> exp1 = List.of(Path.of("examples/exp1-hybrid.rsaml"));
        assertEquals(0, ModelBatch.validate(root, exp1, Severity.ERROR).exitCode(), "experiment 1's one warning (RSA-24) passes by default");
        assertEquals(1, ModelBatch.validate(root, exp1, Severity.WARNING).exitCode(), "and fails the run at the warning threshold");
    }
}
