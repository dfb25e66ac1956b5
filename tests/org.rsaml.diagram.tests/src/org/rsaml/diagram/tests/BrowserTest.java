/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Experiment 2's HTML report in the system's headless Chromium, driven by puppeteer-core
 * (browser/report-check.mjs, installed by the build into target/browser-driver): five findings
 * listed, a click on each highlights and centres its element, a click on an element shows its
 * attributes and findings, zoom and pan move the view, nothing is fetched. The screenshots stay
 * in target/browser/ for a person to look at.
 */
class BrowserTest {

    private static final Path OUT = Path.of("target", "browser").toAbsolutePath();
    private static final Path DRIVER = Path.of("target", "browser-driver", "report-check.mjs").toAbsolutePath();
    private static final String MODULE = "hybridMobileRobotWithDefects/control/resourceChecker";

    private static JsonObject seen;

    @BeforeAll
    static void openTheReport() throws Exception {
        Files.createDirectories(OUT);
        Path page = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(Examples.example("exp2-defects.rsaml"),
                "examples/exp2-defects.rsaml", DiagramFormat.HTML, OUT);
        assertTrue(Files.isRegularFile(DRIVER), DRIVER + " is installed by the build (npm ci in target/browser-driver)");
        List<String> command = List.of(executable("node", "RSAML_NODE", "nodejs"), DRIVER.toString(), page.toString(), OUT.toString(),
                executable("chromium", "RSAML_CHROMIUM", "chromium"), MODULE);
        Path stdout = OUT.resolve("report-check.json");
        Path stderr = OUT.resolve("report-check.log");
        Process process = new ProcessBuilder(command).redirectOutput(stdout.toFile()).redirectError(stderr.toFile()).start();
        if (!process.waitFor(180, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("the browser did not finish within 180 s: " + Files.readString(stderr));
        }
        assertEquals(0, process.exitValue(), () -> "report-check.mjs failed: " + read(stderr));
        seen = JsonParser.parseString(Files.readString(stdout, StandardCharsets.UTF_8)).getAsJsonObject();
    }

    /** An executable named by an environment variable, else found on the PATH; fails naming the package to install. */
    static String executable(String name, String variable, String debianPackage) {
        String configured = System.getenv(variable);
        if (configured != null && !configured.isBlank()) {
            return configured;
        }
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin").split(java.io.File.pathSeparator)) {
            if (Files.isExecutable(Path.of(dir, name))) {
                return Path.of(dir, name).toString();
            }
        }
        throw new AssertionError("the browser test needs " + name + ": install the Debian/Ubuntu package " + debianPackage
                + " (apt-get install " + debianPackage + ") or name the executable in " + variable);
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            return e.toString();
        }
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
            assertNotBlank(Path.of(click.get("screenshot").getAsString()));
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
        assertNotBlank(Path.of(seen.get("overview").getAsString()));
    }

    private static List<String> strings(JsonArray array) {
        List<String> list = new ArrayList<>();
        for (JsonElement e : array) {
            list.add(e.getAsString());
        }
        return list;
    }

    private static void assertNotBlank(Path png) throws Exception {
        BufferedImage image = ImageIO.read(png.toFile());
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
        assertTrue(colours.size() > 20, png.getFileName() + " shows a drawing (" + colours.size() + " colours)");
        assertTrue(drawn > sampled / 20, png.getFileName() + " is not blank (" + drawn + " of " + sampled + " pixels drawn)");
    }
}
