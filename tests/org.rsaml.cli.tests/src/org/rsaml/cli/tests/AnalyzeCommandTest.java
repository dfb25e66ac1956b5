/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.apache.maven.plugin.surefire.log.api.NullConsoleLogger;
import org.apache.maven.plugins.surefire.report.ReportTestCase;
import org.apache.maven.plugins.surefire.report.ReportTestSuite;
import org.apache.maven.plugins.surefire.report.TestSuiteXmlParser;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** {@code rsaml analyze}: verdicts with witnesses, exit codes, JSON, SARIF, JUnit XML and SVG timelines. */
class AnalyzeCommandTest {

    @Test
    void aHoldingRequirementExitsZeroWithTheTableAndTheWorstPath() {
        Cli.Result r = Cli.run("analyze", "examples/mobile-base-latency.rsaml");
        assertEquals(0, r.code(), r.toString());
        assertTrue(r.out().contains("processor core0 (preemptive fixed priority): 2 tasks, utilisation 0.4000"), r.out());
        assertTrue(r.out().matches("(?s).*task\\s+period\\s+deadline\\s+cost\\s+priority\\s+WCRT\\s+slack\\s+verdict.*"), r.out());
        assertTrue(r.out().matches("(?s).*navigation/pathPlanner\\.plan\\s+100 ms\\s+100 ms\\s+30 ms\\s+\\d+\\s+38 ms\\s+62 ms\\s+meets.*"),
                r.out());
        assertTrue(r.out().contains("latency requirement 'scanToWheels' from sensor 'laserScanner' to actuator 'wheelMotors'"), r.out());
        assertTrue(r.out().contains("the worst-case reaction time is at most 37 ms over 1 path, within 50 ms"), r.out());
        assertTrue(r.out().contains("examples/mobile-base-latency.rsaml: timing meets"), r.out());
    }

    /** JSON lists every path of a requirement with its own bounds, and the elements a requirement's path is named by. */
    @Test
    void jsonListsEveryPathAndTheNamedOnes() {
        Cli.Result r = Cli.run("analyze", "--format", "json", "tests/org.rsaml.analysis.tests/resources/latency-named-paths.rsaml");
        assertEquals(1, r.code(), "a requirement of the model names a path that does not exist: " + r);
        JsonArray latencies = JsonParser.parseString(r.out()).getAsJsonArray().get(0).getAsJsonObject().getAsJsonArray("latencies");
        JsonObject all = latencies.get(0).getAsJsonObject();
        assertEquals("scanToWheels", all.get("requirement").getAsString(), "the first latency is the model's first requirement");
        JsonArray every = all.getAsJsonArray("everyPath");
        assertEquals(3, every.size(), all.toString());
        assertEquals(3, all.get("pathsListed").getAsInt(), "the JSON says how many paths it lists: " + all);
        assertEquals(all.get("paths").getAsInt(), every.size(), "every path counted is listed: " + all);
        assertFalse(all.get("pathsAtLeast").getAsBoolean(), "three paths are an exact count: " + all);
        assertTrue(!all.has("pathsNotListed"), "nothing is said to be left out when every path is listed: " + all);
        assertEquals(1_227_000_000L, every.get(0).getAsJsonObject().get("reactionTimeNs").getAsLong(), all.toString());
        assertEquals(33_000_000L, every.get(2).getAsJsonObject().get("reactionTimeNs").getAsLong(), all.toString());
        assertEquals("deliberative/monitor.halt",
                every.get(2).getAsJsonObject().getAsJsonArray("stages").get(1).getAsJsonObject().get("stage").getAsString(),
                "the shortest path passes the monitor's halt stage: " + all);
        JsonObject safety = latencies.get(2).getAsJsonObject();
        assertEquals("safetyChain", safety.get("requirement").getAsString(), "the third latency is the safety chain's requirement");
        assertEquals("[\"deliberative/monitor\",\"inhibitor deliberative/monitor.halt\"]", safety.getAsJsonArray("via").toString(),
                "the JSON lists the elements the requirement's path is named by");
        assertEquals(33_000_000L, safety.get("reactionTimeNs").getAsLong(), safety.toString());
    }

    @Test
    void aMissedRequirementExitsOne() {
        Cli.Result r = Cli.run("analyze", "examples/mobile-base-latency-missed.rsaml");
        assertEquals(1, r.code(), r.toString());
        assertTrue(r.out().contains("verdict: MISSES: the worst-case reaction time can reach 57 ms, more than 50 ms"), r.out());
    }

    /**
     * A model whose processors are all declared LLF (not analysed) is not proven: by default it exits 0
     * like a proven one (nothing can be shown to miss), with --fail-on not-analysed it exits 1 in every
     * format, while a proven model still exits 0.
     */
    @Test
    void aModelNotAnalysedFailsOnlyWithFailOnNotAnalysed(@TempDir Path tmp) throws Exception {
        String model = Files.readString(Cli.ROOT.resolve("examples/mobile-base-latency.rsaml"));
        String llf = model.replace("core=\"0\" modules", "core=\"0\" schedPolicy=\"LLF\" modules")
                .replace("core=\"1\" modules", "core=\"1\" schedPolicy=\"LLF\" modules");
        assertTrue(!llf.equals(model), "both processors declared LLF");
        Files.writeString(tmp.resolve("llf.rsaml"), llf);
        Cli.Result plain = Cli.runIn(tmp, "analyze", "llf.rsaml");
        assertTrue(plain.out().contains("llf.rsaml: timing not analysed"), plain::toString);
        assertEquals(0, plain.code(), () -> "by default only a possible miss fails\n" + plain);
        for (String format : List.of("text", "json", "sarif", "junit")) {
            Cli.Result strict = Cli.runIn(tmp, "analyze", "--fail-on", "not-analysed", "--format", format, "llf.rsaml");
            assertEquals(1, strict.code(), () -> format + ": not proven fails with --fail-on not-analysed\n" + strict);
            Cli.Result never = Cli.runIn(tmp, "analyze", "--fail-on", "never", "--format", format, "llf.rsaml");
            assertEquals(0, never.code(), () -> format + ": --fail-on never\n" + never);
        }
        Cli.Result proven = Cli.run("analyze", "--fail-on", "not-analysed", "examples/mobile-base-latency.rsaml");
        assertEquals(0, proven.code(), () -> "a proven model passes\n" + proven);
        Cli.Result missed = Cli.run("analyze", "--fail-on", "never", "examples/mobile-base-latency-missed.rsaml");
        assertEquals(0, missed.code(), () -> "--fail-on never reports a miss without failing\n" + missed);
        Cli.Result bad = Cli.run("analyze", "--fail-on", "warning", "examples/mobile-base-latency.rsaml");
        assertEquals(2, bad.code(), bad::toString);
        assertTrue(bad.err().contains("'warning' is not a level; it is one of miss, not-analysed, never"), bad::toString);
    }

    @Test
    void aMissedRequirementHasItsWorstPathAsTimeline(@TempDir Path tmp) throws Exception {
        Files.copy(Cli.ROOT.resolve("examples/mobile-base-latency-missed.rsaml"), tmp.resolve("missed.rsaml"));
        Cli.Result r = Cli.runIn(tmp, "analyze", "--timeline", "svg", "missed.rsaml");
        assertEquals(1, r.code(), r.toString());
        assertTrue(r.err().contains("timeline written: svg/mobileBaseSlowDetector-latency-scanToWheels.svg"), r.err());
        Path file = tmp.resolve("svg/mobileBaseSlowDetector-latency-scanToWheels.svg");
        org.w3c.dom.Document svg = javax.xml.parsers.DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());
        String all = svg.getDocumentElement().getTextContent();
        assertTrue(all.contains("latency requirement 'scanToWheels' can be exceeded: reaction time up to 57 ms, at most 50 ms"), all);
        // a lane per stage of the worst path, in order, each waiting then responding (40 + 4, then 10 + 3 ms)
        int detector = all.indexOf("navigation/obstacleDetector: waits up to 40 ms");
        int controller = all.indexOf("control/velocityController: waits up to 10 ms");
        assertTrue(detector > 0 && controller > detector, all);
        assertTrue(all.contains("navigation/obstacleDetector: responds within 4 ms"), all);
        assertTrue(all.contains("control/velocityController: responds within 3 ms"), all);
        assertTrue(all.contains("required 50 ms"), all);
        assertEquals(4, svg.getElementsByTagName("rect").getLength(), Files.readString(file));

        Files.copy(Cli.ROOT.resolve("examples/mobile-base-latency.rsaml"), tmp.resolve("holds.rsaml"));
        Cli.Result holds = Cli.runIn(tmp, "analyze", "--timeline", "more", "holds.rsaml");
        assertEquals(0, holds.code(), holds.toString());
        assertTrue(holds.err().contains("holds.rsaml: no timeline written"), holds.err());
        assertTrue(Files.notExists(tmp.resolve("more")), "nothing to write, no directory");
    }

    /** Three functions on an EDF processor: within the first 10 ms, jobs due by then need 11 ms. */
    static final String EDF_OVERLOADED = """
            <?xml version="1.0" encoding="UTF-8"?>
            <rsaml:Architecture xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:rsaml="http://www.rsaml.org/rsaml/1.0"
                name="edfOverloaded" description="EDF" category="hybrid" declaredLayers="1">
              <layers name="l" description="l" timeUnit="ms" level="0">
                <modules name="a" description="a" timeUnit="ms" type="realTime" period="4" delay="2" execDuration="2" execType="periodic">
                  <functions name="fa" description="fa" timeUnit="ms" type="realTime" period="4" delay="2" execDuration="2" execType="periodic" schedPolicy="EDF"/>
                </modules>
                <modules name="b" description="b" timeUnit="ms" type="realTime" period="10" delay="10" execDuration="3" execType="periodic">
                  <functions name="fb" description="fb" timeUnit="ms" type="realTime" period="10" delay="10" execDuration="3" execType="periodic" schedPolicy="EDF"/>
                </modules>
                <modules name="c" description="c" timeUnit="ms" type="realTime" period="5" delay="3" execDuration="1" execType="periodic">
                  <functions name="fc" description="fc" timeUnit="ms" type="realTime" period="5" delay="3" execDuration="1" execType="periodic" schedPolicy="EDF"/>
                </modules>
              </layers>
              <processors name="cpu" description="EDF" schedPolicy="EDF" modules="//@layers[name='l']/@modules[name='a'] //@layers[name='l']/@modules[name='b'] //@layers[name='l']/@modules[name='c']"/>
            </rsaml:Architecture>
            """;

    @Test
    void anEdfOverloadHasItsDemandIntervalAsTimeline(@TempDir Path tmp) throws Exception {
        Files.writeString(tmp.resolve("edf.rsaml"), EDF_OVERLOADED);
        Cli.Result r = Cli.runIn(tmp, "analyze", "--timeline", "svg", "edf.rsaml");
        assertEquals(1, r.code(), r.toString());
        assertTrue(r.out().contains("witness: in the first 10 ms the jobs due need 11 ms: l/a.fa x3, l/b.fb x1, l/c.fc x2"), r.out());
        assertTrue(r.err().contains("timeline written: svg/edfOverloaded-cpu-demand.svg"), r.err());
        Path file = tmp.resolve("svg/edfOverloaded-cpu-demand.svg");
        org.w3c.dom.Document svg = javax.xml.parsers.DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());
        String all = svg.getDocumentElement().getTextContent();
        assertTrue(all.contains("cpu: the jobs released and due within the first 10 ms need 11 ms, more than the interval holds"), all);
        // a lane per task with each job's window from release to deadline and its cost, then the demand
        int a = all.indexOf("l/a.fa x3");
        int b = all.indexOf("l/b.fb x1");
        int c = all.indexOf("l/c.fc x2");
        assertTrue(a > 0 && b > a && c > b, all);
        assertTrue(all.contains("l/a.fa job 3: released at 8 ms, due at 10 ms, needs 2 ms"), all);
        assertTrue(all.contains("l/c.fc job 2: released at 5 ms, due at 8 ms, needs 1 ms"), all);
        assertTrue(all.contains("demand of the jobs due within 10 ms: 11 ms"), all);
        assertTrue(all.contains("interval 10 ms"), all);
        assertEquals(2 * (3 + 1 + 2) + 1, svg.getElementsByTagName("rect").getLength(), Files.readString(file));

        // RSA-22 says what analyze shows for EDF: the interval, not a critical-instant schedule
        Cli.Result v = Cli.runIn(tmp, "validate", "edf.rsaml");
        assertEquals(1, v.code(), v.toString());
        assertTrue(v.out().contains("error RSA-22: Function 'fa' can miss its deadline on processor 'cpu' (l/a.fa)"), v.out());
        assertTrue(v.out().contains("rsaml analyze shows the interval whose jobs need more than its length"), v.out());
        assertTrue(!v.out().contains("critical-instant"), v.out());
    }

    @Test
    void aMissedDeadlineHasItsWitnessAsTextJsonAndTimeline(@TempDir Path tmp) throws Exception {
        Path model = tmp.resolve("overloaded.rsaml");
        // the detector now takes 12 ms of every 20 and the planner is due within 60 ms: it completes at 78 ms
        Files.writeString(model, Files.readString(Cli.ROOT.resolve("examples/mobile-base-latency.rsaml"))
                .replace("period=\"20.0\" delay=\"20.0\" execDuration=\"4.0\"", "period=\"20.0\" delay=\"20.0\" execDuration=\"12.0\"")
                .replace("period=\"100.0\" delay=\"100.0\"", "period=\"100.0\" delay=\"60.0\""));
        Cli.Result text = Cli.runIn(tmp, "analyze", "--timeline", "svg", "overloaded.rsaml");
        assertEquals(1, text.code(), text.toString());
        assertTrue(text.out().contains("witness: critical instant at 0; job 1 of navigation/pathPlanner.plan"), text.out());
        try (Stream<Path> svgs = Files.list(tmp.resolve("svg"))) {
            List<Path> files = svgs.toList();
            assertEquals(1, files.size(), files.toString());
            String svg = Files.readString(files.get(0));
            assertTrue(svg.startsWith("<svg xmlns=\"http://www.w3.org/2000/svg\""), svg);
            assertTrue(svg.contains("navigation/pathPlanner.plan misses its deadline"), svg);
        }

        Cli.Result json = Cli.runIn(tmp, "analyze", "--format", "json", "overloaded.rsaml");
        assertEquals(1, json.code(), json.toString());
        JsonArray files = JsonParser.parseString(json.out()).getAsJsonArray();
        JsonObject core1 = files.get(0).getAsJsonObject().getAsJsonArray("processors").get(1).getAsJsonObject();
        assertEquals("misses", core1.get("verdict").getAsString(), "the overloaded core's verdict: " + core1);
        JsonObject plan = core1.getAsJsonArray("tasks").get(1).getAsJsonObject();
        assertEquals("navigation/pathPlanner.plan", plan.get("task").getAsString(), "the second task of core1: " + core1);
        assertEquals("misses", plan.get("verdict").getAsString(), "the path planner misses its deadline: " + plan);
        assertTrue(plan.getAsJsonObject("witness").getAsJsonObject("preemptions").get("navigation/obstacleDetector.detect").getAsLong() > 0,
                "the witness shows the obstacle detector preempting the planner: " + plan);
    }

    @Test
    void sarifListsTheTimingFindingsSchemaValid() throws Exception {
        Cli.Result r = Cli.run("analyze", "--format", "sarif", "examples/mobile-base-latency.rsaml", "examples/mobile-base-latency-missed.rsaml");
        assertEquals(1, r.code(), r.toString());
        assertEquals(Set.of(), ReportFormatsTest.sarifProblems(r.out()), r.out());
        JsonObject run = JsonParser.parseString(r.out()).getAsJsonObject().getAsJsonArray("runs").get(0).getAsJsonObject();
        List<String> rules = new ArrayList<>();
        run.getAsJsonObject("tool").getAsJsonObject("driver").getAsJsonArray("rules")
                .forEach(rule -> rules.add(rule.getAsJsonObject().get("id").getAsString()));
        assertEquals(Rules.timing().stream().map(Rule::id).toList(), rules, "the SARIF driver lists the catalogue's timing rules");
        JsonArray results = run.getAsJsonArray("results");
        assertEquals(1, results.size(), r.out());
        JsonObject result = results.get(0).getAsJsonObject();
        assertEquals("RSA-23", result.get("ruleId").getAsString(), "the missed latency requirement's rule: " + result);
        assertEquals("error", result.get("level").getAsString(), "a missed requirement is an error: " + result);
        assertTrue(result.getAsJsonObject("message").get("text").getAsString()
                .startsWith("Latency requirement 'scanToWheels' can be exceeded: the worst-case reaction time can reach 57 ms"), r.out());
        JsonObject location = result.getAsJsonArray("locations").get(0).getAsJsonObject().getAsJsonObject("physicalLocation");
        assertEquals("examples/mobile-base-latency-missed.rsaml", location.getAsJsonObject("artifactLocation").get("uri").getAsString(),
                "the finding names the file of the missed requirement");
        assertEquals(40, location.getAsJsonObject("region").get("startLine").getAsInt(), "the finding is at the requirement's line");
    }

    @Test
    void junitHasATestPerTimingRuleAndFile() throws Exception {
        Cli.Result r = Cli.run("analyze", "--format", "junit", "examples/mobile-base-latency.rsaml", "examples/mobile-base-latency-missed.rsaml");
        assertEquals(1, r.code(), r.toString());
        List<ReportTestSuite> suites = new TestSuiteXmlParser(new NullConsoleLogger())
                .parse(new InputStreamReader(new ByteArrayInputStream(r.out().getBytes(StandardCharsets.UTF_8)), StandardCharsets.UTF_8));
        assertEquals(2, suites.size(), r.out());
        for (ReportTestSuite suite : suites) {
            assertEquals(Rules.timing().size(), suite.getNumberOfTests(), "one test per timing rule: " + suite.getFullClassName());
        }
        ReportTestSuite missed = suites.stream().filter(s -> s.getNumberOfFailures() > 0).findFirst().orElseThrow(() -> new AssertionError(r.out()));
        assertEquals(1, missed.getNumberOfFailures(), "one failed test for the one missed requirement: " + r.out());
        ReportTestCase failed = missed.getTestCases().stream().filter(ReportTestCase::hasFailure).findFirst().orElseThrow();
        assertEquals("RSA-23", failed.getFailureType(), "the failure is typed by the latency rule: " + r.out());
        assertTrue(failed.getName().startsWith("RSA-23 latency-within-requirement (mobileBaseSlowDetector/scanToWheels)"), failed.getName());
    }

    /** A model that is read but cannot be analysed exits 2 whatever the format, and says why on the element. */
    @Test
    void aModelThatCannotBeAnalysedExitsTwoInEveryFormat(@TempDir Path tmp) throws Exception {
        String example = Files.readString(Cli.ROOT.resolve("examples/mobile-base-latency.rsaml"));
        // a negative execution duration leaves no task set (RSA-13); a module on two processors, no deployment (RSA-25)
        Files.writeString(tmp.resolve("negative.rsaml"), example.replace("period=\"20.0\" delay=\"20.0\" execDuration=\"4.0\"",
                "period=\"20.0\" delay=\"20.0\" execDuration=\"-4.0\""));
        String twice = example.replace("modules=\"//@layers[name='control']/@modules[name='velocityController']",
                "modules=\"//@layers[name='navigation']/@modules[name='obstacleDetector'] //@layers[name='control']/@modules[name='velocityController']");
        Files.writeString(tmp.resolve("two-processors.rsaml"), twice);
        assertTrue(!twice.equals(example), "the fixture must change the example");
        // an execution longer than the period (RSA-10): the plan could be built and would miss, but there is no task set
        Files.writeString(tmp.resolve("exceeds-period.rsaml"), example.replace("period=\"20.0\" delay=\"20.0\" execDuration=\"4.0\"",
                "period=\"20.0\" delay=\"20.0\" execDuration=\"24.0\""));
        for (String model : List.of("negative.rsaml", "two-processors.rsaml", "exceeds-period.rsaml")) {
            Map<String, Integer> codes = new TreeMap<>();
            List<Cli.Result> results = new ArrayList<>();
            for (String format : List.of("text", "json", "sarif", "junit")) {
                Cli.Result r = Cli.runIn(tmp, "analyze", "--format", format, model);
                codes.put(format, r.code());
                results.add(r);
            }
            assertEquals(Map.of("text", 2, "json", 2, "sarif", 2, "junit", 2), codes, model + ": " + results);
            for (Cli.Result r : results) {
                assertTrue(r.err().startsWith(model + ":") && r.err().contains(": error: the timing cannot be analysed: "),
                        model + ": " + r.err());
            }
        }
        Cli.Result sarif = Cli.runIn(tmp, "analyze", "--format", "sarif", "negative.rsaml");
        assertEquals(Set.of(), ReportFormatsTest.sarifProblems(sarif.out()), sarif.out());
        JsonObject run = JsonParser.parseString(sarif.out()).getAsJsonObject().getAsJsonArray("runs").get(0).getAsJsonObject();
        assertEquals(0, run.getAsJsonArray("results").size(), sarif.out());
        JsonObject invocation = run.getAsJsonArray("invocations").get(0).getAsJsonObject();
        assertEquals(false, invocation.get("executionSuccessful").getAsBoolean(), sarif.out());
        assertTrue(invocation.toString().contains("RSA-13: Module 'obstacleDetector' has a negative time value"), sarif.out());
        // No format gives a verdict for it: the same error, the same exit code, no MISSES on standard output.
        Map<String, String> outs = new TreeMap<>();
        for (String format : List.of("text", "json", "sarif", "junit")) {
            Cli.Result r = Cli.runIn(tmp, "analyze", "--format", format, "exceeds-period.rsaml");
            assertTrue(r.err().matches("(?s)exceeds-period\\.rsaml:\\d+:\\d+: error: the timing cannot be analysed: RSA-10: Module 'obstacleDetector'"
                    + " takes 24\\.0 ms but runs every 20\\.0 ms.*"), format + ": " + r.err());
            assertTrue(!r.out().contains("MISSES"), format + ": " + r.out());
            outs.put(format, r.out().strip());
        }
        assertEquals("", outs.get("text"), "text gives no verdict for a model it cannot analyse");
        assertEquals("[]", outs.get("json"), "JSON gives no verdict for a model it cannot analyse");
        assertTrue(outs.get("junit").contains("failures=\"0\" errors=\"1\""), outs.get("junit"));
        assertTrue(outs.get("sarif").contains("the timing cannot be analysed: RSA-10"), outs.get("sarif"));
        Cli.Result text = Cli.runIn(tmp, "analyze", "negative.rsaml");
        assertTrue(text.err().matches("(?s)negative\\.rsaml:\\d+:\\d+: error: the timing cannot be analysed: RSA-13: Module 'obstacleDetector'.*"),
                text.err());
    }

    @Test
    void aModelThatCannotBeReadExitsTwo() {
        Cli.Result r = Cli.run("analyze", "examples/no-such-model.rsaml");
        assertEquals(2, r.code(), r.toString());
        assertTrue(r.err().contains("no-such-model.rsaml"), r.err());
    }
}
