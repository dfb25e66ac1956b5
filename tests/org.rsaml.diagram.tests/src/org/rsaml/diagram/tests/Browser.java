/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
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

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The system's headless Chromium driven by puppeteer-core through browser/report-check.mjs, which
 * the build installs into target/browser-driver (npm ci): no browser download, no WebDriver.
 */
final class Browser {

    static final Path OUT = Path.of("target", "browser").toAbsolutePath();
    private static final Path DRIVER = Path.of("target", "browser-driver", "report-check.mjs").toAbsolutePath();

    private Browser() {
    }

    /** Runs report-check.mjs with {@code arguments} (Chromium's path is inserted) and returns what it saw; screenshots go to OUT/name. */
    static JsonObject run(String name, List<String> before, List<String> after) throws Exception {
        Files.createDirectories(OUT);
        assertTrue(Files.isRegularFile(DRIVER), DRIVER + " is installed by the build (npm ci in target/browser-driver)");
        List<String> command = new ArrayList<>();
        command.add(executable("node", "RSAML_NODE", "nodejs"));
        command.add(DRIVER.toString());
        command.addAll(before);
        Path screenshots = OUT.resolve(name);
        Files.createDirectories(screenshots);
        command.add(screenshots.toString());
        command.add(executable("chromium", "RSAML_CHROMIUM", "chromium"));
        command.addAll(after);
        Path stdout = OUT.resolve(name + ".json");
        Path stderr = OUT.resolve(name + ".log");
        Process process = new ProcessBuilder(command).redirectOutput(stdout.toFile()).redirectError(stderr.toFile()).start();
        if (!process.waitFor(300, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("the browser did not finish within 300 s: " + read(stderr));
        }
        assertEquals(0, process.exitValue(), () -> "report-check.mjs failed: " + read(stderr));
        return JsonParser.parseString(Files.readString(stdout, StandardCharsets.UTF_8)).getAsJsonObject();
    }

    /** An executable named by an environment variable, else found on the PATH; fails naming the package to install. */
    static String executable(String name, String variable, String debianPackage) {
        String configured = System.getenv(variable);
        if (configured != null && !configured.isBlank()) {
            return configured;
        }
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(dir, name))) {
                return Path.of(dir, name).toString();
            }
        }
        throw new AssertionError("the browser tests need " + name + ": install the Debian/Ubuntu package " + debianPackage
                + " (apt-get install " + debianPackage + ") or name the executable in " + variable);
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            return e.toString();
        }
    }

    /** The screenshot shows a drawing: many colours, and more than a twentieth of it not white. */
    static void assertNotBlank(Path png) throws Exception {
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
