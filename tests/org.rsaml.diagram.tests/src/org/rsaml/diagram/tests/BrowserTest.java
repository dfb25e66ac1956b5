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
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * Experiment 2's HTML report in the system's headless Chromium, driven by puppeteer-core
 * (browser/report-check.mjs, installed by the build into target/browser-driver): five findings
 * listed, a click on each highlights and centres its element, a click on an element shows its
 * attributes and findings, zoom and pan move the view, nothing is fetched. The screenshots stay
 * in target/browser/ for a person to look at.
 */
class BrowserTest {

    private static final String MODULE = "hybridMobileRobotWithDefects/control/resourceChecker";

    private static JsonObject seen;

    @BeforeAll
    static void openTheReport() throws Exception {
        Files.createDirectories(Browser.OUT);
        Path page = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(Examples.example("exp2-defects.rsaml"),
                "examples/exp2-defects.rsaml", DiagramFormat.HTML, Browser.OUT);
        seen = Browser.run("exp2-report", List.of(page.toString()), List.of(MODULE));
    }

    @Test
    void thePageShowsTheFiveFindingsAndLoadsNothing() {
        assertEquals("examples/exp2-defects.rsaml: 5 errors, 0 warnings", seen.get("summary").getAsString());
        assertEquals(5, seen.getAsJsonArray("findings").size(), seen.toString());
        assertEquals(new JsonArray(), seen.getAsJsonArray("requests"), "the page fetches nothing");
        assertEquals(new JsonArray(), seen.getAsJsonArray("errors"), "no script error");
    }

    @Test
    void clickingEachFindingHighlightsAndCentresItsElement() throws Exception {
        JsonArray findings = seen.getAsJsonArray("findings");
        JsonArray clicks = seen.getAsJsonArray("clicks");
        assertEquals(findings.size(), clicks.size());
        Set<String> rules = new HashSet<>();
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
            Browser.assertNotBlank(Path.of(click.get("screenshot").getAsString()));
        }
        assertEquals(Set.of("RSA-01", "RSA-02", "RSA-04", "RSA-07", "RSA-08"), rules);
    }

    @Test
    void clickingAnElementListsItsAttributesAndFindings() {
        JsonObject element = seen.getAsJsonObject("element");
        assertEquals("Module " + MODULE, element.get("details").getAsString());
        assertEquals("2.5", element.getAsJsonObject("attributes").get("execDuration").getAsString());
        assertEquals(List.of("error RSA-08: Module 'resourceChecker' takes 2.5 ms but layer 'control' allows at most 2.0 ms"),
                strings(element.getAsJsonArray("findings")));
        assertEquals(List.of(MODULE), strings(element.getAsJsonArray("highlighted")));
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

    private static List<String> strings(JsonArray array) {
        List<String> list = new ArrayList<>();
        for (JsonElement e : array) {
            list.add(e.getAsString());
        }
        return list;
    }
}
