/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.HashMap;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/** The same model gives the same bytes, wherever and however often it is generated. */
class DeterminismTest {

    static Target[] targets() {
        return new Target[] { Target.CPP, Target.ROS2 };
    }

    @ParameterizedTest
    @MethodSource("targets")
    void twoRunsGiveByteIdenticalProjects(Target target, @TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("subsumption-brooks.rsaml"), tmp.resolve("model.rsaml"));
        new RsamlGenerator().generate(model, target, tmp.resolve("a"), false);
        new RsamlGenerator().generate(Tools.example("subsumption-brooks.rsaml"), target, tmp.resolve("elsewhere/b"), false);
        Map<String, byte[]> a = Tools.snapshot(tmp.resolve("a"));
        assertTrue(a.size() > 20, "the generated project has its files");
        assertTrue(Tools.sameFiles(a, Tools.snapshot(tmp.resolve("elsewhere/b"))), "the two projects differ");
        for (Map.Entry<String, byte[]> f : a.entrySet()) {
            String text = new String(f.getValue(), StandardCharsets.UTF_8);
            assertFalse(text.contains(tmp.toString()), f.getKey() + " contains a path of this machine");
            assertFalse(text.contains("\r"), f.getKey() + " has CR line ends");
            assertFalse(text.matches("(?s).*20[0-9][0-9]-[01][0-9]-[0-3][0-9].*"), f.getKey() + " contains a date");
        }
    }

    @ParameterizedTest
    @MethodSource("targets")
    void regeneratingTouchesNoFile(Target target, @TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        new RsamlGenerator().generate(Tools.example("hierarchical-nasrem.rsaml"), target, out, false);
        Map<Path, FileTime> times = new HashMap<>();
        FileTime past = FileTime.fromMillis(1_000_000_000_000L);
        try (Stream<Path> walk = Files.walk(out)) {
            for (Path p : walk.filter(Files::isRegularFile).toList()) {
                Files.setLastModifiedTime(p, past);
                times.put(p, past);
            }
        }
        Map<String, byte[]> before = Tools.snapshot(out);
        var again = new RsamlGenerator().generate(Tools.example("hierarchical-nasrem.rsaml"), target, out, false);
        assertEquals(0, again.written().size(), "a second generation writes no file");
        assertTrue(Tools.sameFiles(before, Tools.snapshot(out)), "a second generation leaves every file as it was");
        for (Map.Entry<Path, FileTime> t : times.entrySet()) {
            assertEquals(t.getValue(), Files.getLastModifiedTime(t.getKey()), t.getKey() + " was rewritten");
        }
    }
}
