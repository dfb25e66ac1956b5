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
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * STYLE.md: packages that are not API are exported {@code x-internal}, and a test bundle that uses one is named its
 * friend ({@code x-friends}). Without that, a test compiles against another bundle's internals with only a warning,
 * and the manifest says nobody outside the bundle uses what a test does.
 */
class InternalPackagesTest {

    private static final Path ROOT = Path.of(System.getProperty("rsaml.root", "../..")).toAbsolutePath().normalize();

    /** One entry of Export-Package: the package and its directives (quoted lists may hold commas). */
    private static final Pattern EXPORT = Pattern.compile("([\\w.]+)((?:;[^,\"]*(?:\"[^\"]*\")?)*)");

    private static final Pattern FRIENDS = Pattern.compile("x-friends:=\"([^\"]*)\"");

    /** The package of a type a source names, imported or written out in full: the name up to its first capitalised part. */
    private static final Pattern IMPORT = Pattern.compile("(?<![\\w.])(org\\.rsaml(?:\\.[a-z]\\w*)+)\\.[A-Z]");

    @Test
    void aTestBundleThatImportsAnInternalPackageIsItsFriend() throws IOException {
        Map<String, String> exporter = new TreeMap<>();
        Map<String, Set<String>> friends = new TreeMap<>();
        // The production bundles' internals (tests/org.rsaml.tests.support is for every test bundle, by design).
        for (Path bundle : bundles("bundles")) {
            String exports = header(bundle.resolve("META-INF/MANIFEST.MF"), "Export-Package");
            Matcher entry = EXPORT.matcher(exports == null ? "" : exports);
            while (entry.find()) {
                String directives = entry.group(2);
                Matcher named = FRIENDS.matcher(directives);
                if (named.find()) {
                    friends.put(entry.group(1), new TreeSet<>(Arrays.stream(named.group(1).split(",")).map(String::strip).toList()));
                } else if (directives.contains("x-internal:=true")) {
                    friends.put(entry.group(1), Set.of());
                } else {
                    continue;
                }
                exporter.put(entry.group(1), bundle.getFileName().toString());
            }
        }
        assertFalse(friends.isEmpty(), "no bundle under bundles/ exports an x-internal or x-friends package");

        List<String> wrong = new ArrayList<>();
        int checked = 0;
        for (Path bundle : bundles("tests")) {
            String name = bundle.getFileName().toString();
            Path src = bundle.resolve("src");
            if (!Files.isDirectory(src)) {
                continue;
            }
            List<Path> sources;
            try (Stream<Path> files = Files.walk(src)) {
                sources = files.filter(f -> f.toString().endsWith(".java")).sorted().toList();
            }
            for (Path source : sources) {
                Set<String> reported = new TreeSet<>();
                Matcher imported = IMPORT.matcher(Files.readString(source));
                while (imported.find()) {
                    String pkg = imported.group(1);
                    if (!friends.containsKey(pkg) || exporter.get(pkg).equals(name)) {
                        continue;
                    }
                    checked++;
                    if (!friends.get(pkg).contains(name) && reported.add(pkg)) {
                        wrong.add(ROOT.relativize(source) + " imports " + pkg + ", internal to " + exporter.get(pkg)
                                + " (friends: " + friends.get(pkg) + "); name " + name + " in its x-friends");
                    }
                }
            }
        }
        assertTrue(checked > 0, "no test imports an internal package of another bundle: the check would see nothing");
        assertTrue(wrong.isEmpty(), () -> "Internal packages used by tests that are not their friends:\n  " + String.join("\n  ", wrong));
    }

    /** The bundles (folders with a manifest) under each of {@code parents}, sorted. */
    private static List<Path> bundles(String... parents) throws IOException {
        List<Path> bundles = new ArrayList<>();
        for (String parent : parents) {
            try (Stream<Path> children = Files.list(ROOT.resolve(parent))) {
                children.filter(d -> Files.exists(d.resolve("META-INF/MANIFEST.MF"))).sorted().forEach(bundles::add);
            }
        }
        return bundles;
    }

    private static String header(Path manifest, String name) throws IOException {
        try (InputStream in = Files.newInputStream(manifest)) {
            return new Manifest(in).getMainAttributes().getValue(name);
        }
    }
}
