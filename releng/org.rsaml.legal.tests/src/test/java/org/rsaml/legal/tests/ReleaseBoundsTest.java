/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.legal.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * RsaML supports Eclipse 2025-12 and later: the target files pin the EMF and platform bundles of that release, and
 * every manifest's lower bound on one of them must be exactly that version. A higher bound would refuse to install
 * into 2025-12; a lower one would claim releases nothing tests.
 */
class ReleaseBoundsTest {

    private static final Path ROOT = Path.of(System.getProperty("rsaml.root", "../..")).toAbsolutePath().normalize();

    private static final List<String> TARGETS = List.of("releng/org.rsaml.target/org.rsaml.target.target",
            "releng/org.rsaml.target/org.rsaml.ide.target");

    private static final Pattern DEPENDENCY = Pattern.compile(
            "<groupId>(org\\.eclipse\\.(?:platform|emf))</groupId>\\s*<artifactId>([^<]+)</artifactId>\\s*<version>([^<]+)</version>");

    private static final Pattern REQUIREMENT = Pattern.compile(
            "([\\w.]+)((?:;[^,\"]*(?:\"[^\"]*\")?)*)");

    private static final Pattern LOWER_BOUND = Pattern.compile("bundle-version=\"[\\[(]?([0-9.]+)");

    @Test
    void lowerBoundsAreTheVersionsOfTheOldestSupportedRelease() throws IOException {
        Map<String, String> release = releaseVersions();
        assertFalse(release.isEmpty(), "no EMF or platform bundle found in " + TARGETS);
        List<String> wrong = new ArrayList<>();
        int checked = 0;
        for (Path manifest : manifests()) {
            String requireBundle = header(manifest, "Require-Bundle");
            Matcher requirement = REQUIREMENT.matcher(requireBundle == null ? "" : requireBundle);
            while (requirement.find()) {
                String id = requirement.group(1);
                if (!release.containsKey(id)) {
                    continue;
                }
                checked++;
                Matcher bound = LOWER_BOUND.matcher(requirement.group(2));
                String expected = release.get(id);
                if (!bound.find()) {
                    wrong.add(ROOT.relativize(manifest) + ": " + id + " has no bundle-version; require \"[" + expected
                            + ",...)\"");
                } else if (!bound.group(1).equals(expected)) {
                    wrong.add(ROOT.relativize(manifest) + ": " + id + " lower bound " + bound.group(1)
                            + " is not " + expected + ", the version Eclipse 2025-12 ships");
                }
            }
        }
        assertTrue(checked > 0, "no manifest requires an EMF or platform bundle of the target files");
        assertTrue(wrong.isEmpty(), () -> "Lower bounds must be the versions of Eclipse 2025-12 (pinned in "
                + TARGETS + "):\n  " + String.join("\n  ", wrong));
    }

    /** Bundle id (= artifactId for these groups) to its version in the target files. */
    private static Map<String, String> releaseVersions() throws IOException {
        Map<String, String> versions = new TreeMap<>();
        for (String target : TARGETS) {
            Matcher dependency = DEPENDENCY.matcher(Files.readString(ROOT.resolve(target)));
            while (dependency.find()) {
                versions.put(dependency.group(2), dependency.group(3));
            }
        }
        return versions;
    }

    /** The manifests of the bundles users install, and of the test bundles, which run against the same release. */
    private static List<Path> manifests() throws IOException {
        List<Path> manifests = new ArrayList<>();
        for (String parent : List.of("bundles", "tests")) {
            try (Stream<Path> children = Files.list(ROOT.resolve(parent))) {
                children.map(d -> d.resolve("META-INF/MANIFEST.MF")).filter(Files::exists).sorted()
                        .forEach(manifests::add);
            }
        }
        return manifests;
    }

    private static String header(Path manifest, String name) throws IOException {
        try (InputStream in = Files.newInputStream(manifest)) {
            return new Manifest(in).getMainAttributes().getValue(name);
        }
    }
}
