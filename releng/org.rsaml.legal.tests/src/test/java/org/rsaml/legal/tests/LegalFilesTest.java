/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.legal.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/** The legal files Eclipse projects ship, and the licence header of every hand-written source. */
class LegalFilesTest {

    private static final String SPDX = "SPDX-License-Identifier: EPL-2.0";

    /** Hand-written source kinds; generated ones (src-gen/, xtend-gen/) and build output are skipped. */
    private static final Set<String> SOURCE_EXTENSIONS = Set.of("java", "xtend", "groovy", "hpp", "cpp", "h", "py", "sh");

    private static final Set<String> SKIPPED_DIRECTORIES = Set.of("target", "src-gen", "xtend-gen", ".git", ".mvn",
            ".settings", "node_modules");

    /** The Maven wrapper is Apache-2.0 licensed third-party code. */
    private static final Set<String> THIRD_PARTY = Set.of("mvnw", "mvnw.cmd");

    private static final Path ROOT = Path.of(System.getProperty("rsaml.root", "../..")).toAbsolutePath().normalize();

    @Test
    void everyHandWrittenSourceCarriesTheLicenceHeader() throws IOException {
        List<String> missing = new ArrayList<>();
        Files.walkFileTree(ROOT, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                String name = dir.getFileName() == null ? "" : dir.getFileName().toString();
                boolean skipped = !dir.equals(ROOT) && (SKIPPED_DIRECTORIES.contains(name) || dir.equals(ROOT.resolve("out")));
                return skipped ? FileVisitResult.SKIP_SUBTREE : FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                if (isHandWrittenSource(file) && !headerOf(file).contains(SPDX)) {
                    missing.add(ROOT.relativize(file).toString());
                }
                return FileVisitResult.CONTINUE;
            }
        });
        assertTrue(missing.isEmpty(), () -> "These sources lack the licence header (a comment with '" + SPDX
                + "' in their first lines, as in every other source of RsaML):\n  " + String.join("\n  ", missing));
    }

    @Test
    void theLicenceIsTheEclipsePublicLicence2() throws IOException {
        List<String> lines = Files.readAllLines(ROOT.resolve("LICENSE"));
        assertEquals("Eclipse Public License - v 2.0", lines.get(0).strip(), "LICENSE starts with the EPL-2.0 title");
        assertTrue(lines.stream().anyMatch(l -> l.contains("Exhibit A - Form of Secondary Licenses Notice")),
                "LICENSE must hold the whole EPL-2.0 text");
        assertTrue(Files.readString(ROOT.resolve("NOTICE")).contains(SPDX), "NOTICE must declare the project licence");
    }

    @Test
    void everyBundleAndFeatureShipsAboutHtml() throws IOException {
        List<Path> modules = new ArrayList<>();
        for (String parent : List.of("bundles", "features", "tests")) {
            try (Stream<Path> children = Files.list(ROOT.resolve(parent))) {
                children.filter(d -> Files.exists(d.resolve("build.properties"))).forEach(modules::add);
            }
        }
        assertFalse(modules.isEmpty(), "the check sees the modules");
        for (Path module : modules) {
            assertTrue(Files.exists(module.resolve("about.html")), () -> module + " has no about.html");
            Properties build = new Properties();
            try (Reader in = Files.newBufferedReader(module.resolve("build.properties"))) {
                build.load(in);
            }
            List<String> included = List.of(build.getProperty("bin.includes", "").split("\\s*,\\s*"));
            assertTrue(included.contains("about.html"),
                    () -> module.resolve("build.properties") + ": bin.includes must list about.html, so the built "
                            + "bundle or feature carries it");
        }
    }

    @Test
    void generatedCodeCarriesTheLicenceHeaderToo() throws IOException {
        String genmodel = Files.readString(ROOT.resolve("bundles/org.rsaml.model/model/rsaml.genmodel"));
        assertTrue(genmodel.matches("(?s).*copyrightText=\"[^\"]*" + SPDX + "\".*"),
                "rsaml.genmodel's copyrightText must end with '" + SPDX + "' so EMF writes it into src-gen/");
    }

    private static boolean isHandWrittenSource(Path file) throws IOException {
        String name = file.getFileName().toString();
        if (THIRD_PARTY.contains(name) && file.getParent().equals(ROOT)) {
            return false;
        }
        int dot = name.lastIndexOf('.');
        if (dot > 0) {
            return SOURCE_EXTENSIONS.contains(name.substring(dot + 1));
        }
        // Extension-less scripts (./rsaml, .ci/run) are sources too.
        return Files.isExecutable(file) && Files.size(file) > 2 && headerOf(file).startsWith("#!");
    }

    private static String headerOf(Path file) throws IOException {
        try (Stream<String> lines = Files.lines(file)) {
            return String.join("\n", lines.limit(5).toList());
        } catch (java.io.UncheckedIOException e) {
            return ""; // not text
        }
    }
}
