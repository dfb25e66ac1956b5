/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.TimingText;
import org.rsaml.analysis.Verdict;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * Experiment 2's HTML report in the system's headless Chromium, driven by puppeteer-core
 * (browser/report-check.mjs, installed by the build into target/browser-driver): its findings
 * listed, a click on each highlights its element, zooms in on it and centres it, a click on an
 * element shows its attributes and findings, zoom and pan move the view, nothing is fetched. The
 * missed latency example's page shows the timing: its list, the worst path drawn in the miss colour,
 * highlighted and brought into view by a click. The screenshots stay in target/browser/ for a person
 * to look at.
 */
class BrowserTest {

    private static final String MISSED = "mobile-base-latency-missed.rsaml";

    private static final Path EXP2 = TestRepository.example("exp2-defects.rsaml");

    private static JsonObject seen;
    /** What exp2 must give, from its {@code <!-- expect: -->} comments. */
    private static List<ExpectedFinding> expected;
    private static JsonObject timing;
    /** The module the page is asked to click: the first module exp2's expectations name (its over-budget module). */
    private static org.rsaml.model.Module module;
    private static String moduleName;

    @BeforeAll
    static void openTheReports() throws Exception {
        Files.createDirectories(Browser.OUT);
        expected = ExpectedFinding.of(EXP2);
        module = firstModuleWithAFinding();
        moduleName = RsamlLabels.qualifiedName(module);
        Path page = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(EXP2,
                "examples/exp2-defects.rsaml", DiagramFormat.HTML, Browser.OUT);
        seen = Browser.run("exp2-report", List.of(page.toString()), List.of(moduleName));
        Path timed = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(TestRepository.example(MISSED), "examples/" + MISSED, DiagramFormat.HTML,
                Browser.OUT.resolve("timing"));
        timing = Browser.run("timing-report", List.of(timed.toString()), List.of()).getAsJsonObject("overlay");
    }

    /** The element of the first expectation of exp2 that is a module (the page lists a module's attributes and findings). */
    private static org.rsaml.model.Module firstModuleWithAFinding() throws Exception {
        Resource model = ModelLoader.load(EXP2, "examples/exp2-defects.rsaml").resource();
        for (ExpectedFinding e : expected) {
            for (Iterator<EObject> all = model.getAllContents(); all.hasNext();) {
                if (all.next() instanceof org.rsaml.model.Module m && RsamlLabels.qualifiedName(m).equals(e.qualifiedName())) {
                    return m;
                }
            }
        }
        throw new AssertionError(EXP2 + " states no finding on a module in its <!-- expect: --> comments; the page's click on"
                + " a module needs one: " + expected);
    }

    @Test
    void thePageShowsTheModelsFindingsAndLoadsNothing() {
        long errors = expected.stream().filter(e -> e.severity().equals("error")).count();
        long warnings = expected.stream().filter(e -> e.severity().equals("warning")).count();
        assertEquals("examples/exp2-defects.rsaml: " + errors + (errors == 1 ? " error, " : " errors, ") + warnings
                + (warnings == 1 ? " warning" : " warnings"), seen.get("summary").getAsString(),
                "the page's summary counts the findings the model expects");
        assertEquals(expected.size(), seen.getAsJsonArray("findings").size(), "one listed finding per expectation: " + seen);
        assertEquals(new JsonArray(), seen.getAsJsonArray("requests"), "the page fetches nothing");
        assertEquals(new JsonArray(), seen.getAsJsonArray("errors"), "no script error");
    }

    @Test
    void clickingEachFindingHighlightsZoomsToAndCentresItsElement() throws Exception {
        JsonArray findings = seen.getAsJsonArray("findings");
        JsonArray clicks = seen.getAsJsonArray("clicks");
        assertEquals(findings.size(), clicks.size(), "each listed finding was clicked once");
        Set<String> rules = new HashSet<>();
        int zoomedIn = 0;
        for (int i = 0; i < findings.size(); i++) {
            JsonObject finding = findings.get(i).getAsJsonObject();
            JsonObject click = clicks.get(i).getAsJsonObject();
            String rule = finding.get("rule").getAsString();
            String qname = finding.get("qname").getAsString();
            rules.add(rule);
            assertEquals(List.of(qname), strings(click.getAsJsonArray("highlighted")), rule + " highlights exactly its element");
            JsonArray offset = click.getAsJsonArray("offset");
            assertTrue(Math.abs(offset.get(0).getAsDouble()) < 3 && Math.abs(offset.get(1).getAsDouble()) < 3,
                    rule + ": the element is centred in the diagram (off by " + offset + ")");
            assertTrue(click.get("details").getAsString().endsWith(" " + qname), rule + ": the element's details are shown");
            JsonObject before = click.getAsJsonObject("before");
            JsonObject after = click.getAsJsonObject("after");
            assertTrue(after.get("inside").getAsBoolean(), rule + ": the element is inside the view after the click: " + after);
            JsonArray view = before.getAsJsonArray("view");
            boolean small = before.get("width").getAsDouble() < view.get(0).getAsDouble() / 4
                    && before.get("height").getAsDouble() < view.get(1).getAsDouble() / 4;
            if (small) {
                assertTrue(after.get("width").getAsDouble() > before.get("width").getAsDouble() * 1.2
                        && after.get("height").getAsDouble() > before.get("height").getAsDouble() * 1.2,
                        rule + ": the click zooms in on the element (" + before + " before, " + after + " after)");
                zoomedIn++;
            } else {
                assertTrue(after.get("width").getAsDouble() >= before.get("width").getAsDouble() * 0.99,
                        rule + ": an element as large as the view is not zoomed out of (" + before + " before, " + after + " after)");
            }
            Browser.assertNotBlank(Path.of(click.get("screenshot").getAsString()));
        }
        assertEquals(expected.stream().map(ExpectedFinding::ruleId).collect(Collectors.toSet()), rules,
                "every expected rule's finding was clicked");
        assertEquals(3, zoomedIn, "the findings on the two small elements (a module, and a function with two: RSA-07 and RSA-24) are zoomed in"
                + " on; the others' elements fill a quarter of the view already");
    }

    @Test
    void clickingAnElementListsItsAttributesAndFindings() throws Exception {
        JsonObject element = seen.getAsJsonObject("element");
        assertEquals("Module " + moduleName, element.get("details").getAsString(), "the clicked element is named");
        assertEquals(RsamlLabels.number(module.getExecDuration()), element.getAsJsonObject("attributes").get("execDuration").getAsString(),
                "its attributes are listed, its execution duration as the model states it");
        ExpectedFinding own = ExpectedFinding.on(EXP2, moduleName);
        assertEquals(List.of(own.severity() + " " + own.diagnosticMessage()), strings(element.getAsJsonArray("findings")),
                "its own finding, worded as the command line words it");
        assertEquals(List.of(moduleName), strings(element.getAsJsonArray("highlighted")), "only the element is highlighted");
    }

    @Test
    void zoomAndPanMoveTheView() throws Exception {
        JsonObject zoom = seen.getAsJsonObject("zoom");
        double fit = zoom.get("fit").getAsDouble();
        assertEquals(fit * 0.8, zoom.get("in").getAsDouble(), 0.01, "+ narrows the view");
        assertEquals(fit * 0.8 * 1.25 * 1.25, zoom.get("out").getAsDouble(), 0.01, "- widens it");
        JsonObject pan = seen.getAsJsonObject("pan");
        assertTrue(pan.get("after").getAsDouble() < pan.get("before").getAsDouble() - 50, "dragging right moves the view left: " + pan);
        Browser.assertNotBlank(Path.of(seen.get("overview").getAsString()));
    }

    @Test
    void theTimingOverlayIsVisibleAndItsPathIsHighlightedOnClick() throws Exception {
        // What the page must show of the missed requirement: read from the analysis of the same model.
        LatencyResult latency = missedRequirement();
        Set<String> sections = new HashSet<>(strings(timing.getAsJsonArray("sections")));
        assertTrue(sections.contains("Timing") && sections.contains("Findings"), "a Timing section beside the findings: " + sections);
        JsonObject missed = null;
        int index = -1;
        JsonArray items = timing.getAsJsonArray("items");
        for (int i = 0; i < items.size(); i++) {
            JsonObject item = items.get(i).getAsJsonObject();
            assertTrue(item.get("shown").getAsBoolean(), item + " is shown");
            if (item.get("text").getAsString().startsWith("latency " + latency.name() + " ")) {
                missed = item;
                index = i;
            }
        }
        assertTrue(missed != null && missed.get("text").getAsString().endsWith(": " + TimingText.word(Verdict.MISSES)),
                "the missed requirement " + latency.name() + " is listed: " + items);
        assertTrue(missed.get("style").getAsString().contains("overlay-misses"), "the missed requirement is styled as a miss: " + missed);
        Set<String> path = new HashSet<>();
        for (JsonElement e : timing.getAsJsonArray("path")) {
            JsonObject element = e.getAsJsonObject();
            assertEquals("rgb(164, 0, 0)", element.get("stroke").getAsString(), element + " is drawn in the miss colour");
            assertEquals("4px", element.get("width").getAsString(), element + " has the path's heavy stroke");
            assertTrue(element.get("visible").getAsBoolean(), element + " is visible in the whole diagram");
            if (!element.get("qname").getAsString().isEmpty()) {
                path.add(element.get("qname").getAsString());
            }
        }
        List<String> worst = new ArrayList<>();
        worst.add(RsamlLabels.qualifiedName(latency.requirement().getSource()));
        latency.worstPath().forEach(hop -> worst.add(RsamlLabels.qualifiedName(hop.module())));
        worst.add(RsamlLabels.qualifiedName(latency.requirement().getTarget()));
        assertTrue(path.containsAll(worst), "the worst path's ends and modules, " + worst + ", are drawn as such: " + path);
        String texts = timing.getAsJsonArray("texts").toString();
        for (int i = 0; i < latency.worstPath().size(); i++) {
            Hop hop = latency.worstPath().get(i);
            String contribution = latency.name() + " hop " + (i + 1) + ": " + hop.contribution();
            assertTrue(texts.contains(contribution), "the hops' contributions are written in the diagram: " + contribution + " in " + texts);
        }
        JsonObject click = timing.getAsJsonArray("clicks").get(index).getAsJsonObject();
        assertEquals(path, new HashSet<>(strings(click.getAsJsonArray("highlighted"))), "clicking the requirement highlights its path");
        assertTrue(click.getAsJsonObject("after").get("inside").getAsBoolean(), "the whole path is in view: " + click);
        Browser.assertNotBlank(Path.of(timing.get("screenshot").getAsString()));
        Browser.assertNotBlank(Path.of(click.get("screenshot").getAsString()));
    }

    private static List<String> strings(JsonArray array) {
        List<String> list = new ArrayList<>();
        for (JsonElement e : array) {
            list.add(e.getAsString());
        }
        return list;
    }

    /** The analysis's missed latency requirement of the timing example (the example holds one). */
    private static LatencyResult missedRequirement() throws Exception {
        ArchitectureTiming analysed = RsamlModelValidator.analyseTiming(ModelLoader.load(TestRepository.example(MISSED), "examples/" + MISSED));
        List<LatencyResult> missed = analysed.latencies().stream().filter(l -> l.verdict() == Verdict.MISSES && !l.worstPath().isEmpty()).toList();
        assertEquals(1, missed.size(), MISSED + " has one missed latency requirement with a worst path: " + analysed.latencies());
        return missed.get(0);
    }
}
