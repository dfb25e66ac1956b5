/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
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
 * Messages are neither copied when published nor by the subscriptions of a component container on a
 * real ROS 2 ({@link Ros2Jazzy}): the publisher hands over the message it filled and intra-process
 * communication gives that very message to every subscription, seen by the architect's code. The run
 * checks what every {@link Ros2LaunchTest} run does too.
 */
class Ros2SharedMessagesTest {

    private static final Pattern SEEN = Pattern.compile("shared (built|left|right) (\\d+) (\\S+)");

    /**
     * No copy from the publisher's code to the subscribers' in a component container: the producer
     * of resources/ros2-shared-messages.rsaml fills out_value (its architect's code) with 1, 2, 3, ...
     * every 20 ms and prints the address of the message it filled; two reactive modules of the same
     * container print the address of each message their handlers get. Both get the message the
     * producer filled (the same address for each value): had the publication copied out_value, as it
     * did when the port kept its value, or each subscription taken a copy over the middleware, the
     * addresses would differ. The run also checks what every run does (releases, rates, reactions
     * measured).
     */
    @Test
    void theSubscriptionsOfAContainerReceiveTheMessageThePublisherFilled(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String name = "resources/ros2-shared-messages.rsaml";
        String out = Ros2LaunchTest.run(Ros2Test.model(name), name, tmp, src -> {
            Path pkg = src.resolve("shared_messages/src");
            Path producer = pkg.resolve("high/Producer.cpp");
            replace(producer, "void Producer::compute() {}", String.join("\n",
                    "void Producer::compute() {",
                    "  static double count = 0;",
                    "  out_value->data = ++count;",
                    "  std::printf(\"shared built %.0f %p\\n\", out_value->data, static_cast<const void*>(out_value.get()));",
                    "  std::fflush(stdout);",
                    "}"));
            replace(producer, "#include \"high/Producer.hpp\"", "#include \"high/Producer.hpp\"\n\n#include <cstdio>");
            for (String module : List.of("left", "right")) {
                String cls = Character.toUpperCase(module.charAt(0)) + module.substring(1);
                Path cpp = pkg.resolve("low/" + cls + ".cpp");
                replace(cpp, "{ (void)message; }", "{\n  std::printf(\"shared " + module + " %.0f %p\\n\", message.data, static_cast<const void*>(&message));\n"
                        + "  std::fflush(stdout);\n}");
                replace(cpp, "#include \"low/" + cls + ".hpp\"", "#include \"low/" + cls + ".hpp\"\n\n#include <cstdio>");
            }
        });
        Map<String, Map<String, String>> seen = new TreeMap<>();
        Matcher m = SEEN.matcher(out);
        while (m.find()) {
            seen.computeIfAbsent(m.group(2), v -> new TreeMap<>()).put(m.group(1), m.group(3));
        }
        List<String> all = seen.entrySet().stream().filter(e -> e.getValue().size() == 3).map(Map.Entry::getKey).toList();
        assertTrue(all.size() >= 50, "the producer and both subscribers should have printed most of the producer's messages (every 20 ms for "
                + Ros2LaunchTest.RUN_MS + " ms): " + all.size() + " values seen by all three\n" + Tools.last(out, 4000));
        for (String value : all) {
            Map<String, String> at = seen.get(value);
            assertEquals(at.get("built"), at.get("left"), "message " + value + " that the producer filled is not the one left received (a copy): " + at);
            assertEquals(at.get("built"), at.get("right"), "message " + value + " that the producer filled is not the one right received (a copy): " + at);
        }
    }

    private static void replace(Path file, String what, String with) throws java.io.IOException {
        String text = Files.readString(file);
        assertTrue(text.contains(what), file + " does not contain " + what + ":\n" + text);
        Files.writeString(file, text.replace(what, with));
    }
}
