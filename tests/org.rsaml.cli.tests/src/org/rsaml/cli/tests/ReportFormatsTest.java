/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.apache.maven.plugin.surefire.log.api.NullConsoleLogger;
import org.apache.maven.plugins.surefire.report.ReportTestCase;
import org.apache.maven.plugins.surefire.report.ReportTestSuite;
import org.apache.maven.plugins.surefire.report.TestSuiteXmlParser;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;

/** JSON, SARIF and JUnit XML reports, on standard output and in files, read back as their consumers read them. */
class ReportFormatsTest {

    private static JsonSchema sarifSchema;

    @BeforeAll
    static void loadSarifSchema() throws Exception {
        try (InputStream in = Files.newInputStream(Cli.ROOT.resolve("tests/org.rsaml.cli.tests/resources/sarif/sarif-2.1.0-rtm.5.json"))) {
            sarifSchema = JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V4).getSchema(in);
        }
    }

    /** The findings an example ({@code examples/x.rsaml}) states in its expect comments. */
    private static List<ExpectedFinding> expectations(String example) {
        try {
            return ExpectedFinding.of(Cli.ROOT.resolve(example));
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    static Set<ValidationMessage> sarifProblems(String sarif) throws Exception {
        if (sarifSchema == null) {
            loadSarifSchema();
        }
        return sarifSchema.validate(new ObjectMapper().readTree(sarif));
    }

    @Test
    void jsonListsEveryFileWithFindingsAndTotals() {
        Cli.Result r = Cli.run("validate", "--format", "json", "examples", "tests/org.rsaml.cli.tests/resources/inputs/empty.rsaml");
        assertEquals(2, r.code(), r::toString);
        JsonObject doc = JsonParser.parseString(r.out()).getAsJsonObject();
        assertEquals(System.getProperty("rsaml.version"), doc.getAsJsonObject("tool").get("version").getAsString(), "the tool's version is the build's");
        JsonArray files = doc.getAsJsonArray("files");
        List<String> examples = ValidateCommandTest.exampleModels();
        assertEquals(examples.size() + 1, files.size(), "every example and the empty file are listed: " + files);
        JsonObject exp2 = find(files, "examples/exp2-defects.rsaml");
        assertEquals("findings", exp2.get("status").getAsString(), "exp2's status");
        JsonArray findings = exp2.getAsJsonArray("findings");
        List<ExpectedFinding> expected = ValidateCommandTest.exp2();
        assertEquals(expected.size(), findings.size(), "one JSON finding per expectation of exp2: " + findings);
        for (ExpectedFinding e : expected) {
            JsonObject finding = null;
            for (var f : findings) {
                if (f.getAsJsonObject().get("element").getAsString().equals(e.qualifiedName())
                        && f.getAsJsonObject().get("ruleId").getAsString().equals(e.ruleId())) {
                    finding = f.getAsJsonObject();
                }
            }
            assertTrue(finding != null, "a finding of " + e.ruleId() + " on " + e.qualifiedName() + " in " + findings);
            assertEquals(e.ruleId(), finding.get("ruleId").getAsString(), e.what());
            assertEquals(e.severity(), finding.get("severity").getAsString(), e.what());
            assertEquals(e.line(), finding.get("line").getAsInt(), e.what() + ": line");
            assertEquals(e.column(), finding.get("column").getAsInt(), e.what() + ": column");
            assertEquals(e.message(), finding.get("message").getAsString(), e.what() + ": message");
            String fragment = finding.get("uriFragment").getAsString();
            String last = e.qualifiedName().substring(e.qualifiedName().lastIndexOf('/') + 1);
            boolean root = !e.qualifiedName().contains("/");
            assertTrue(root ? fragment.equals("/") : e.qualifiedName().contains(" -> ") || fragment.contains(last),
                    e.what() + ": the URI fragment names the element: " + fragment);
        }
        assertEquals("clean", find(files, "examples/exp3-task-interpreter.rsaml").get("status").getAsString(), "exp3 is clean");
        JsonObject empty = find(files, "tests/org.rsaml.cli.tests/resources/inputs/empty.rsaml");
        assertEquals("unreadable", empty.get("status").getAsString(), "the empty file's status");
        assertTrue(empty.getAsJsonObject("error").get("message").getAsString().startsWith("the file is empty"),
                "the empty file's error says so: " + empty);
        JsonObject summary = doc.getAsJsonObject("summary");
        assertEquals(examples.size(), summary.get("files").getAsInt(), "the summary counts the readable files");
        long errors = expected.stream().filter(e -> e.severity().equals("error")).count() + 1;
        assertEquals(errors, summary.get("errors").getAsInt(), "exp2-defects' errors and the missed latency requirement");
        assertEquals(1, summary.get("unreadable").getAsInt(), "the malformed input is counted as unreadable");
        assertEquals(2, summary.get("exitCode").getAsInt(), "an unreadable input makes the exit code 2, and the summary says so");
    }

    @Test
    void sarifConformsToTheSchemaAndLocatesEveryFinding() throws Exception {
        Cli.Result r = Cli.run("validate", "--format", "sarif", "examples", "tests/org.rsaml.cli.tests/resources/inputs/malformed.rsaml");
        assertEquals(2, r.code(), r::toString);
        assertEquals(Set.of(), sarifProblems(r.out()), "the SARIF output conforms to the SARIF 2.1.0 schema");
        JsonObject run = JsonParser.parseString(r.out()).getAsJsonObject().getAsJsonArray("runs").get(0).getAsJsonObject();
        JsonObject driver = run.getAsJsonObject("tool").getAsJsonObject("driver");
        assertEquals("rsaml", driver.get("name").getAsString(), "the driver is rsaml");
        JsonArray rules = driver.getAsJsonArray("rules");
        assertEquals(Rules.all().size(), rules.size(), "the driver lists every rule of the catalogue");
        for (var element : rules) {
            JsonObject rule = element.getAsJsonObject();
            Rule catalogued = Rules.byId(rule.get("id").getAsString()).orElseThrow(() -> new AssertionError("a driver rule of the catalogue: " + rule));
            assertFalse(rule.getAsJsonObject("help").get("text").getAsString().isBlank(), () -> catalogued.id() + " has help text");
            String level = switch (catalogued.severity()) {
                case ERROR -> "error";
                case WARNING -> "warning";
                case INFO -> "note";
            };
            assertEquals(level, rule.getAsJsonObject("defaultConfiguration").get("level").getAsString(),
                    () -> catalogued.id() + "'s default level is its severity in the catalogue");
        }

        // What the examples' expect comments state, in the order they are checked.
        List<String> expected = new ArrayList<>();
        for (String model : ValidateCommandTest.exampleModels()) {
            ExpectedFinding.of(Cli.ROOT.resolve(model)).forEach(e -> expected.add(model + " " + e.ruleId() + "@" + e.line() + ":" + e.column()));
        }
        JsonArray results = run.getAsJsonArray("results");
        List<String> seen = new ArrayList<>();
        for (var element : results) {
            JsonObject result = element.getAsJsonObject();
            String ruleId = result.get("ruleId").getAsString();
            assertEquals(ruleId, rules.get(result.get("ruleIndex").getAsInt()).getAsJsonObject().get("id").getAsString(),
                    "a result's ruleIndex points at its rule");
            JsonObject location = result.getAsJsonArray("locations").get(0).getAsJsonObject().getAsJsonObject("physicalLocation");
            assertEquals("%SRCROOT%", location.getAsJsonObject("artifactLocation").get("uriBaseId").getAsString(),
                    "locations are relative to the source root");
            seen.add(location.getAsJsonObject("artifactLocation").get("uri").getAsString() + " " + ruleId + "@"
                    + location.getAsJsonObject("region").get("startLine").getAsInt()
                    + ":" + location.getAsJsonObject("region").get("startColumn").getAsInt());
        }
        assertEquals(expected, seen, "each result in its file, located where the model's expectation says");

        JsonObject invocation = run.getAsJsonArray("invocations").get(0).getAsJsonObject();
        assertFalse(invocation.get("executionSuccessful").getAsBoolean(), "an unreadable input makes the invocation unsuccessful");
        JsonObject notification = invocation.getAsJsonArray("toolExecutionNotifications").get(0).getAsJsonObject();
        assertTrue(notification.getAsJsonObject("message").get("text").getAsString().startsWith("malformed XML"), "the notification says why the input could not be read");
        assertEquals(6, notification.getAsJsonArray("locations").get(0).getAsJsonObject().getAsJsonObject("physicalLocation")
                .getAsJsonObject("region").get("startLine").getAsInt(), "the notification points at the malformed line");
    }

    /**
     * An RSA-23 finding over a 1,000-hop path: the message (text, JSON, SARIF) names the ends of the
     * path and how many hops it has, on one readable line; JSON and SARIF keep the whole path.
     */
    @Test
    void aLongWorstPathIsSummarisedInTheMessageAndWholeInJsonAndSarif(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        int hops = 1000;
        StringBuilder xml = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\" "
                + "xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
                + "xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"robot\" declaredLayers=\"1\">\n  <layers name=\"functional\" level=\"0\">\n");
        for (int i = 0; i < hops; i++) {
            xml.append("    <modules name=\"m").append(i).append("\" execType=\"periodic\" period=\"10.0\" execDuration=\"0.001\"")
                    .append(i == 0 ? " sensors=\"//@sensors[name='laser']\"" : "")
                    .append(i == hops - 1 ? " actuators=\"//@actuators[name='wheels']\"" : "").append(">\n");
            if (i > 0) {
                xml.append("      <ports xsi:type=\"rsaml:EntryPort\" name=\"in\"/>\n");
            }
            if (i < hops - 1) {
                xml.append("      <ports xsi:type=\"rsaml:OutputPort\" name=\"out\"/>\n");
            }
            xml.append("    </modules>\n");
        }
        xml.append("  </layers>\n");
        for (int i = 1; i < hops; i++) {
            xml.append("  <connections source=\"//@layers[name='functional']/@modules[name='m").append(i - 1)
                    .append("']/@ports[name='out']\" target=\"//@layers[name='functional']/@modules[name='m").append(i)
                    .append("']/@ports[name='in']\"/>\n");
        }
        xml.append("  <sensors name=\"laser\" period=\"20.0\"/>\n  <actuators name=\"wheels\" period=\"10.0\"/>\n"
                + "  <latencyRequirements name=\"scanToWheels\" source=\"//@sensors[name='laser']\" target=\"//@actuators[name='wheels']\" maxLatency=\"50.0\"/>\n"
                + "</rsaml:Architecture>\n");
        Files.writeString(dir.resolve("long-path.rsaml"), xml);

        Cli.Result text = Cli.runIn(dir, "validate", "long-path.rsaml");
        List<String> rsa23 = text.outLines().stream().filter(l -> l.contains("RSA-23")).toList();
        assertEquals(1, rsa23.size(), text::toString);
        String line = rsa23.get(0);
        assertTrue(line.length() < 1000, () -> "one readable line, not " + line.length() + " characters: " + line);
        assertTrue(line.contains("functional/m0 +") && line.contains("functional/m999 +") && line.contains("992 more hops")
                && line.contains("1000 hops"), line);

        JsonObject finding = null;
        for (var f : JsonParser.parseString(Cli.runIn(dir, "validate", "--format", "json", "long-path.rsaml").out()).getAsJsonObject()
                .getAsJsonArray("files").get(0).getAsJsonObject().getAsJsonArray("findings")) {
            if (f.getAsJsonObject().get("ruleId").getAsString().equals("RSA-23")) {
                finding = f.getAsJsonObject();
            }
        }
        assertTrue(finding != null, "JSON has the RSA-23 finding");
        String detail = finding.get("detail").getAsString();
        for (int i = 0; i < hops; i++) {
            assertTrue(detail.contains("functional/m" + i + " +"), "JSON detail has hop " + i);
        }
        assertTrue(finding.get("message").getAsString().length() < 1000, "JSON message summarised");

        String sarif = Cli.runIn(dir, "validate", "--format", "sarif", "long-path.rsaml").out();
        assertEquals(Set.of(), sarifProblems(sarif), "the SARIF report conforms to the SARIF 2.1.0 schema");
        boolean whole = false;
        for (var r : JsonParser.parseString(sarif).getAsJsonObject().getAsJsonArray("runs").get(0).getAsJsonObject().getAsJsonArray("results")) {
            JsonObject o = r.getAsJsonObject();
            if (o.get("ruleId").getAsString().equals("RSA-23")) {
                whole = o.getAsJsonObject("properties").get("detail").getAsString().equals(detail);
            }
        }
        assertTrue(whole, "SARIF carries the whole path in the result's properties");
    }

    @Test
    void theSchemaCheckCatchesANonConformingDocument() throws Exception {
        Cli.Result r = Cli.run("validate", "--format", "sarif", "examples/exp2-defects.rsaml");
        String broken = r.out().replace("\"level\": \"error\"", "\"level\": \"fatal\"");
        assertFalse(sarifProblems(broken).isEmpty(), "an unknown level must violate the schema");
        assertFalse(sarifProblems(r.out().replace("\"version\": \"2.1.0\"", "\"version\": \"2.0\"")).isEmpty(),
                "another SARIF version must violate the schema");
    }

    @Test
    void sarifNamesFilesWithSpacesAsUris() throws Exception {
        Cli.Result r = Cli.runIn(Cli.INPUTS, "validate", "--format", "sarif", "--fail-on", "never", "dir with space", "warnings-only.rsaml");
        assertEquals(0, r.code(), r::toString);
        assertEquals(Set.of(), sarifProblems(r.out()), "the SARIF output conforms to the SARIF 2.1.0 schema");
        JsonObject result = JsonParser.parseString(r.out()).getAsJsonObject().getAsJsonArray("runs").get(0).getAsJsonObject()
                .getAsJsonArray("results").get(0).getAsJsonObject();
        assertEquals("warning", result.get("level").getAsString(), "the result has its finding's severity");
        assertEquals("RSA-11", result.get("ruleId").getAsString(), "the result names the warning's rule");
        assertTrue(r.out().contains(Cli.INPUTS.toUri().toString()), "the base URI is the working directory");
    }

    @Test
    void junitIsReadByATestReportParser(@TempDir Path dir) throws Exception {
        Path report = dir.resolve("rsaml.xml");
        Cli.Result r = Cli.run("validate", "--output", "junit=" + report, "examples", "tests/org.rsaml.cli.tests/resources/inputs/binary.rsaml");
        assertEquals(2, r.code(), r::toString);
        List<ReportTestSuite> suites;
        try (InputStreamReader in = new InputStreamReader(Files.newInputStream(report), StandardCharsets.UTF_8)) {
            suites = new TestSuiteXmlParser(new NullConsoleLogger()).parse(in);
        }
        List<String> examples = ValidateCommandTest.exampleModels();
        assertEquals(examples.size() + 1, suites.size(), "a suite per example and one for the unreadable input");
        ReportTestSuite exp2 = suites.stream().filter(s -> s.getFullClassName().equals("examples/exp2-defects.rsaml")
                || s.getName().contains("exp2-defects")).findFirst().orElseThrow(() -> new AssertionError(suites));
        assertEquals(Rules.all().size(), exp2.getNumberOfTests(), "a test case per rule");
        List<ExpectedFinding> errors = ValidateCommandTest.exp2().stream().filter(e -> e.severity().equals("error")).toList();
        assertEquals(errors.size(), exp2.getNumberOfFailures(), "a failure per error the model's expect comments state");
        List<ReportTestCase> failed = exp2.getTestCases().stream().filter(ReportTestCase::hasFailure).toList();
        assertEquals(errors.stream().map(ExpectedFinding::ruleId).sorted().toList(),
                failed.stream().map(ReportTestCase::getFailureType).sorted().toList(), "the failures are the stated rules");
        for (ExpectedFinding e : errors) {
            ReportTestCase failure = failed.stream().filter(c -> c.getName().endsWith("(" + e.qualifiedName() + ")")).findFirst()
                    .orElseThrow(() -> new AssertionError("no failure on " + e.qualifiedName() + " among " + failed));
            assertEquals(e.ruleId() + " " + Rules.byId(e.ruleId()).orElseThrow().name() + " (" + e.qualifiedName() + ")",
                    failure.getName(), e.what() + ": a case named by rule and element");
            assertEquals(e.message(), failure.getFailureMessage(), e.what() + ": the message");
            assertTrue(failure.getFailureDetail().startsWith("examples/exp2-defects.rsaml:" + e.line() + ":" + e.column() + ": "
                    + e.severity() + " " + e.ruleId() + ": " + e.message()), e.what() + ": the located finding: " + failure.getFailureDetail());
        }

        ReportTestSuite binary = suites.stream().filter(s -> s.getNumberOfErrors() == 1).findFirst().orElseThrow();
        assertEquals(1, binary.getNumberOfTests(), "the unreadable input is one test case");
        assertTrue(binary.getTestCases().get(0).hasError(), "an unreadable input is an error, not a failure");
        long withErrors = examples.stream().filter(m -> expectations(m).stream().anyMatch(e -> e.severity().equals("error"))).count();
        long cleanSuites = suites.stream().filter(s -> s.getNumberOfFailures() == 0 && s.getNumberOfErrors() == 0).count();
        assertEquals(examples.size() - withErrors, cleanSuites, "every example that states no error passes (warnings do not fail it)");
    }

    @Test
    void warningsBelowTheThresholdPassButStayVisibleInJunit(@TempDir Path dir) throws Exception {
        Path lenient = dir.resolve("lenient.xml");
        Path strict = dir.resolve("strict.xml");
        String model = Cli.INPUTS.resolve("warnings-only.rsaml").toString();
        assertEquals(0, Cli.run("validate", "--output", "junit=" + lenient, model).code(), "warnings alone pass by default");
        assertEquals(1, Cli.run("validate", "--fail-on", "warning", "--output", "junit=" + strict, model).code(),
                "warnings fail with --fail-on warning");
        String lenientXml = Files.readString(lenient);
        assertTrue(lenientXml.contains("failures=\"0\""), lenientXml);
        assertTrue(lenientXml.contains("<system-out>") && lenientXml.contains("warning RSA-11"), lenientXml);
        String strictXml = Files.readString(strict);
        assertTrue(strictXml.contains("<failure type=\"RSA-11\""), strictXml);
    }

    @Test
    void severalReportsInOneRun(@TempDir Path dir) throws Exception {
        Cli.Result r = Cli.runIn(dir, "validate", "--format", "text",
                "--output", "sarif=reports/rsaml.sarif", "--output", "reports/rsaml.json", "-o", "reports/TEST-rsaml.xml",
                Cli.ROOT.resolve("examples").toString());
        assertEquals(1, r.code(), r::toString);
        assertTrue(r.out().contains("error RSA-08"), r::toString);
        assertEquals(Set.of(), sarifProblems(Files.readString(dir.resolve("reports/rsaml.sarif"))), "the SARIF file conforms to the schema");
        long errors = ValidateCommandTest.exampleModels().stream().flatMap(m -> expectations(m).stream())
                .filter(e -> e.severity().equals("error")).count();
        assertEquals(errors, JsonParser.parseString(Files.readString(dir.resolve("reports/rsaml.json"))).getAsJsonObject()
                .getAsJsonObject("summary").get("errors").getAsInt(), "the JSON report counts the errors the examples state");
        assertTrue(Files.readString(dir.resolve("reports/TEST-rsaml.xml")).startsWith("<?xml"), "the JUnit file is XML");
        try (var listing = Files.list(dir.resolve("reports"))) {
            assertEquals(3, listing.count(), "no temporary file is left behind");
        }
    }

    @Test
    void aReportThatCannotBeWrittenFailsTheRunAndLeavesNothing(@TempDir Path dir) throws Exception {
        Files.createDirectories(dir.resolve("taken.sarif"));
        Files.writeString(dir.resolve("previous.json"), "previous report");
        Files.writeString(dir.resolve("blocker"), "a file where a folder should be");
        Cli.Result r = Cli.runIn(dir, "validate", "-o", "sarif=taken.sarif", "-o", "json=blocker/r.json",
                Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString());
        assertEquals(2, r.code(), r::toString);
        assertTrue(r.err().contains("taken.sarif: error: cannot write the sarif report"), r::toString);
        assertTrue(r.err().contains("r.json: error: cannot write the json report"), r::toString);
        BadInputTest.assertNoStackTrace(r);
        try (var listing = Files.list(dir)) {
            assertEquals(3, listing.count(), "no temporary or partial file is left behind");
        }
        assertTrue(Files.isDirectory(dir.resolve("taken.sarif")), "the directory in the report's place is left as it was");
    }

    @Test
    void everyLoadErrorOfAFileIsInEveryFormat(@TempDir Path dir) throws Exception {
        // A mistake on each line that declares a module: all of them are reported, none summarised away.
        String name = "many-errors.rsaml";
        List<String> model = Files.readAllLines(Cli.INPUTS.resolve(name));
        List<Integer> expected = new ArrayList<>();
        for (int i = 0; i < model.size(); i++) {
            if (model.get(i).contains("<modules name=\"m")) {
                expected.add(i + 1);
            }
        }
        assertEquals(12, expected.size(), "many-errors.rsaml declares twelve faulty modules");

        Cli.Result text = Cli.runIn(Cli.INPUTS, "validate", "--output", "sarif=" + dir.resolve("r.sarif"),
                "--output", "json=" + dir.resolve("r.json"), "--output", "junit=" + dir.resolve("r.xml"), name);
        assertEquals(2, text.code(), text::toString);
        List<String> lines = text.outLines().stream().filter(l -> l.startsWith(name + ":")).toList();
        assertEquals(expected, lines.stream().map(l -> Integer.parseInt(l.split(":")[1])).toList(), text::toString);
        assertTrue(lines.stream().allMatch(l -> l.matches(name + ":\\d+:\\d+: error: .+")), text::toString);
        assertFalse(text.out().contains("more error"), text::toString);

        JsonArray errors = JsonParser.parseString(Files.readString(dir.resolve("r.json"))).getAsJsonObject().getAsJsonArray("files")
                .get(0).getAsJsonObject().getAsJsonArray("errors");
        List<String> fromJson = new ArrayList<>();
        for (var e : errors) {
            JsonObject error = e.getAsJsonObject();
            fromJson.add(name + ":" + error.get("line").getAsInt() + ":" + error.get("column").getAsInt() + ": error: "
                    + error.get("message").getAsString());
        }
        assertEquals(lines, fromJson, "the JSON report holds the same input errors as the text output");

        String sarif = Files.readString(dir.resolve("r.sarif"));
        assertEquals(Set.of(), sarifProblems(sarif), "the SARIF report conforms to the SARIF 2.1.0 schema");
        JsonArray notifications = JsonParser.parseString(sarif).getAsJsonObject().getAsJsonArray("runs").get(0).getAsJsonObject()
                .getAsJsonArray("invocations").get(0).getAsJsonObject().getAsJsonArray("toolExecutionNotifications");
        List<String> fromSarif = new ArrayList<>();
        for (var n : notifications) {
            JsonObject notification = n.getAsJsonObject();
            JsonObject region = notification.getAsJsonArray("locations").get(0).getAsJsonObject()
                    .getAsJsonObject("physicalLocation").getAsJsonObject("region");
            fromSarif.add(name + ":" + region.get("startLine").getAsInt() + ":" + region.get("startColumn").getAsInt() + ": error: "
                    + notification.getAsJsonObject("message").get("text").getAsString());
        }
        assertEquals(lines, fromSarif, "the SARIF notifications are the same input errors as the text output");

        List<ReportTestSuite> suites;
        try (InputStreamReader in = new InputStreamReader(Files.newInputStream(dir.resolve("r.xml")), StandardCharsets.UTF_8)) {
            suites = new TestSuiteXmlParser(new NullConsoleLogger()).parse(in);
        }
        ReportTestCase load = suites.get(0).getTestCases().get(0);
        assertTrue(load.hasError(), "the unreadable input is a JUnit error");
        assertTrue(load.getFailureMessage().endsWith("(and 11 more errors, all listed in the text below)"), load.getFailureMessage());
        assertEquals(lines, load.getFailureDetail().lines().toList(), "the JUnit error carries every input error's line");

        // Generation refuses the model with the same lines.
        Cli.Result generate = Cli.runIn(Cli.INPUTS, "generate", "--target", "cpp", "-o", dir.resolve("out").toString(), name);
        assertEquals(2, generate.code(), generate::toString);
        assertEquals(lines, generate.errLines(), generate::toString);
        Cli.Result generateJson = Cli.runIn(Cli.INPUTS, "generate", "--format", "json", "--target", "cpp", "-o",
                dir.resolve("out").toString(), name);
        assertEquals(Cli.runIn(Cli.INPUTS, "validate", "--format", "json", name).out(), generateJson.out(), "the document of rsaml validate");
    }

    private static JsonObject find(JsonArray files, String name) {
        for (var f : files) {
            if (f.getAsJsonObject().get("file").getAsString().equals(name)) {
                return f.getAsJsonObject();
            }
        }
        throw new AssertionError(name + " not in " + files);
    }
}
