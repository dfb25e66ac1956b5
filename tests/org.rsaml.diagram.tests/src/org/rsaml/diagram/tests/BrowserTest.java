/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;

/**
 * Experiment 2's HTML report in headless Chromium: five findings listed, a click on each one
 * highlights and centres its element, a click on an element shows its attributes and findings.
 * Screenshots are kept in target/browser/ for a person to look at.
 */
class BrowserTest {

    private static final Path OUT = Path.of("target", "browser").toAbsolutePath();

    @Test
    void experimentTwosReportShowsAndLocatesItsFiveFindings() throws Exception {
        Files.createDirectories(OUT);
        Path page = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(Examples.example("exp2-defects.rsaml"),
                "examples/exp2-defects.rsaml", DiagramFormat.HTML, OUT);
        try (Chromium chromium = new Chromium(page, 1600, 1000)) {
            assertEquals("5", chromium.eval("String(document.querySelectorAll('#findings li').length)"));
            assertEquals("examples/exp2-defects.rsaml: 5 errors, 0 warnings", chromium.eval("document.getElementById('summary').textContent"));
            assertEquals("0", chromium.eval("String(performance.getEntriesByType('resource').length)"), "the page loads nothing");
            save(chromium.screenshot(), "exp2-report.png");

            JsonArray findings = chromium.evalJson("Array.from(document.querySelectorAll('#findings li'))"
                    + ".map(function (li) { return {rule: li.dataset.rule, qname: li.dataset.qname}; })").getAsJsonArray();
            Set<String> rules = new HashSet<>();
            for (int i = 0; i < findings.size(); i++) {
                JsonObject finding = findings.get(i).getAsJsonObject();
                String rule = finding.get("rule").getAsString();
                String qname = finding.get("qname").getAsString();
                rules.add(rule);
                chromium.click("#findings li:nth-child(" + (i + 1) + ")");
                JsonArray highlighted = chromium.evalJson("Array.from(document.querySelectorAll('#diagram .highlight'))"
                        + ".map(function (e) { return e.dataset.qname; })").getAsJsonArray();
                assertEquals(1, highlighted.size(), rule + ": one element highlighted");
                assertEquals(qname, highlighted.get(0).getAsString(), rule + " highlights its element");
                JsonArray offset = chromium.evalJson("(function(){ var s = document.querySelector('#diagram > svg').getBoundingClientRect();"
                        + " var e = document.querySelector('#diagram .highlight').getBoundingClientRect();"
                        + " return [e.left + e.width / 2 - (s.left + s.width / 2), e.top + e.height / 2 - (s.top + s.height / 2)]; })()").getAsJsonArray();
                assertTrue(Math.abs(offset.get(0).getAsDouble()) < 3 && Math.abs(offset.get(1).getAsDouble()) < 3,
                        rule + ": the element is centred in the diagram (off by " + offset + ")");
                assertTrue(chromium.eval("document.querySelector('#details .qname').textContent").endsWith(qname),
                        rule + ": the element's details are shown");
                save(chromium.screenshot(), "exp2-finding-" + (i + 1) + "-" + rule + ".png");
            }
            assertEquals(Set.of("RSA-01", "RSA-02", "RSA-04", "RSA-07", "RSA-08"), rules);

            chromium.click("#zoom-fit");
            String module = "hybridMobileRobotWithDefects/control/resourceChecker";
            chromium.click("#diagram g[data-qname='" + module + "'] > text");
            assertEquals("Module " + module, chromium.eval("document.querySelector('#details .qname').textContent"));
            String details = chromium.eval("document.getElementById('details').textContent");
            assertTrue(details.contains("execDuration2.5"), details);
            assertTrue(details.contains("RSA-08"), details);

            double before = Double.parseDouble(chromium.eval("String(document.querySelector('#diagram > svg').viewBox.baseVal.width)"));
            chromium.click("#zoom-in");
            double after = Double.parseDouble(chromium.eval("String(document.querySelector('#diagram > svg').viewBox.baseVal.width)"));
            assertEquals(before * 0.8, after, 0.01, "zoom in narrows the view");

            chromium.click("#zoom-fit");
            byte[] png = chromium.screenshot();
            save(png, "exp2-overview.png");
            assertNotBlank(png);
        }
    }

    private static void save(byte[] png, String name) throws Exception {
        Files.write(OUT.resolve(name), png);
    }

    private static void assertNotBlank(byte[] png) throws Exception {
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(png));
        Set<Integer> colours = new HashSet<>();
        long drawn = 0;
        for (int y = 0; y < image.getHeight(); y += 2) {
            for (int x = 0; x < image.getWidth(); x += 2) {
                int rgb = image.getRGB(x, y) & 0xffffff;
                colours.add(rgb);
                if (rgb != 0xffffff) {
                    drawn++;
                }
            }
        }
        long sampled = (long) ((image.getHeight() + 1) / 2) * ((image.getWidth() + 1) / 2);
        assertTrue(colours.size() > 20, "the screenshot shows a drawing (" + colours.size() + " colours)");
        assertTrue(drawn > sampled / 20, "the screenshot is not blank (" + drawn + " of " + sampled + " pixels drawn)");
    }
}
