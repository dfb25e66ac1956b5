/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Messages are shared, not copied, by the subscriptions of a component container on a real ROS 2
 * ({@link Ros2Jazzy}): intra-process communication, seen by the architect's code. The run checks what
 * every {@link Ros2LaunchTest} run does too.
 */
class Ros2SharedMessagesTest {

    private static final Pattern SHARED = Pattern.compile("shared (left|right) (\\d+) (\\S+)");

    /**
     * Messages are shared, not copied, in a component container: the producer of
     * resources/ros2-shared-messages.rsaml publishes 1, 2, 3, ... every 20 ms to two reactive
     * modules of the same container, whose handlers (the architect's code) print the address of
     * each message they get. With intra-process communication both get the one message the producer
     * published (the same address for each value); over the middleware each subscription would
     * take a copy of its own, while in_in still holds the previous one. The run also checks what
     * every run does (releases, rates, reactions measured).
     */
    @Test
    void aMessageIsSharedByTheSubscriptionsOfAContainer(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String name = "resources/ros2-shared-messages.rsaml";
        String out = Ros2LaunchTest.run(Ros2Test.model(name), name, tmp, src -> {
            Path pkg = src.resolve("shared_messages/src");
            Tools.replace(pkg.resolve("high/Producer.cpp"), "void Producer::compute() {}", "void Producer::compute() { out_value.data += 1.0; }");
            for (String module : List.of("left", "right")) {
                String cls = Character.toUpperCase(module.charAt(0)) + module.substring(1);
                Path cpp = pkg.resolve("low/" + cls + ".cpp");
                Tools.replace(cpp, "{ (void)message; }", "{\n  std::printf(\"shared " + module + " %.0f %p\\n\", message.data, static_cast<const void*>(&message));\n"
                        + "  std::fflush(stdout);\n}");
                Tools.replace(cpp, "#include \"low/" + cls + ".hpp\"", "#include \"low/" + cls + ".hpp\"\n\n#include <cstdio>");
            }
        });
        Map<String, Map<String, String>> seen = new TreeMap<>();
        Matcher m = SHARED.matcher(out);
        while (m.find()) {
            seen.computeIfAbsent(m.group(2), v -> new TreeMap<>()).put(m.group(1), m.group(3));
        }
        List<String> both = seen.entrySet().stream().filter(e -> e.getValue().size() == 2).map(Map.Entry::getKey).toList();
        assertTrue(both.size() >= 50, "both subscribers should have printed most of the producer's messages (every 20 ms for "
                + Ros2LaunchTest.RUN_MS + " ms): " + both.size() + " values seen by both\n" + Tools.last(out, 4000));
        for (String value : both) {
            Map<String, String> at = seen.get(value);
            assertEquals(at.get("left"), at.get("right"), "message " + value + " was copied for each subscriber of the container: " + at);
        }
    }
}
