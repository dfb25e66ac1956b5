/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * An output port's send method ({@code send_<port>}) in the generated ROS 2 nodes: the architect's code publishes a
 * message of its own at once, handed over without a copy, beside the port's value, a copy of which every activation
 * publishes.
 */
class Ros2SendTest {

    private static final Pattern OUTPUT = Pattern.compile("\\n\\s*([\\w:]+) out_(\\w+);");

    /**
     * Every output port of every node has its send method, taking the message as a {@code std::unique_ptr} and
     * publishing it moved, not copied, under the condition the port's value is published under (its inhibitors; a
     * managed node active); it marks the port sent, and publish_outputs() skips a port marked so (clearing the mark)
     * and otherwise publishes a copy of the port's value. Subsumption-brooks has inhibited ports, ros2-lifecycle
     * managed nodes. No ROS 2 needed.
     */
    @Test
    void everyOutputPortHasItsSendMethod(@TempDir Path tmp) throws Exception {
        int ports = 0;
        int inhibited = 0;
        int managed = 0;
        for (Path model : List.of(Tools.example("subsumption-brooks.rsaml"), Tools.resource("ros2-lifecycle.rsaml"))) {
            Path out = tmp.resolve(model.getFileName().toString());
            new RsamlGenerator().generate(model, Target.ROS2, out, false);
            List<Path> bases;
            try (Stream<Path> s = Files.walk(out)) {
                bases = s.filter(f -> f.toString().endsWith("Base.hpp") && f.toString().contains("/gen/")).sorted().toList();
            }
            assertTrue(!bases.isEmpty(), "no node base classes under " + out);
            for (Path base : bases) {
                String text = Files.readString(base);
                String publishOutputs = section(text, "virtual void publish_outputs() {");
                Matcher o = OUTPUT.matcher(text);
                while (o.find()) {
                    String type = o.group(1);
                    String port = o.group(2);
                    ports++;
                    String send = section(text, "void send_" + port + "(std::unique_ptr<" + type + "> message) {");
                    assertTrue(send.contains("sent_" + port + "_ = true;"), base + ": send_" + port + " does not mark the port sent:\n" + send);
                    assertEquals(1, count(send, "->publish("), base + ": send_" + port + " publishes once:\n" + send);
                    assertTrue(send.contains("pub_" + port + "_->publish(std::move(message));"), base + ": send_" + port
                            + " does not hand its message over as it is:\n" + send);
                    Matcher skip = Pattern.compile("if \\(!sent_" + port + "_\\.exchange\\(false\\)( && (.*))?\\) \\{\\s*pub_" + port
                            + "_->publish\\(std::make_unique<" + Pattern.quote(type) + ">\\(out_" + port + "\\)\\);").matcher(publishOutputs);
                    assertTrue(skip.find(), base + ": publish_outputs() does not skip port " + port + " when it was sent, or does not"
                            + " publish a copy of its value otherwise:\n" + publishOutputs);
                    if (skip.group(2) != null) {
                        inhibited++;
                        assertTrue(send.contains("if (" + skip.group(2) + ") {"), base + ": send_" + port + " is not blocked by the"
                                + " inhibitors that block the port's value (" + skip.group(2) + "):\n" + send);
                    }
                    if (publishOutputs.contains("rsaml_active()")) {
                        managed++;
                        assertTrue(send.indexOf("if (!this->rsaml_active()) {") >= 0
                                && send.indexOf("if (!this->rsaml_active()) {") < send.indexOf("->publish("), base + ": send_" + port
                                + " of a managed node publishes while the node is not active:\n" + send);
                    }
                    assertTrue(text.contains("std::atomic<bool> sent_" + port + "_{false};"), base + ": no mark of port " + port + " sent");
                }
            }
        }
        assertTrue(ports > 0 && inhibited > 0 && managed > 0, "the models have output ports (" + ports + "), inhibited ones (" + inhibited
                + ") and ones of managed nodes (" + managed + ")");
    }

    private static final Pattern SENT = Pattern.compile("producer sent (\\d+) (0x[0-9a-f]+)");
    private static final Pattern KEPT = Pattern.compile("producer kept (\\d+) (-?\\d+)");
    private static final Pattern GOT = Pattern.compile("subscriber (left|right) got (\\d+) (0x[0-9a-f]+)");

    /**
     * On a real ROS 2 ({@link Ros2Jazzy}), in one component container: the producer of resources/ros2-shared-messages.rsaml
     * (the architect's code, written here) sends each odd value with send_value, printing the message's address, and sets
     * out_value to each even one, printing the value the port still held; the two subscribers (left, right) print the
     * address of each message they get. A sent message is the very object the subscribers get; the port keeps its value
     * across the sends between (it held the value set two activations before); and no subscriber gets a value twice (the
     * activation that sent does not publish the port's value after it).
     */
    @Test
    void aSentMessageIsTheObjectItsSubscribersGet(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String name = "resources/ros2-shared-messages.rsaml";
        String out = Ros2LaunchTest.run(Ros2Test.model(name), name, tmp, src -> {
            Path pkg = src.resolve("shared_messages/src");
            Tools.replace(pkg.resolve("high/Producer.cpp"), "void Producer::compute() {}", """
                    void Producer::compute() {
                      static long count = 0;
                      ++count;
                      if (count % 2 == 1) {
                        auto message = std::make_unique<std_msgs::msg::Float64>();
                        message->data = static_cast<double>(count);
                        std::printf("producer sent %ld %p\\n", count, static_cast<const void*>(message.get()));
                        send_value(std::move(message));
                      } else {
                        std::printf("producer kept %ld %.0f\\n", count, out_value.data);
                        out_value.data = static_cast<double>(count);
                      }
                      std::fflush(stdout);
                    }""");
            Tools.replace(pkg.resolve("high/Producer.cpp"), "#include \"high/Producer.hpp\"", "#include \"high/Producer.hpp\"\n\n#include <cstdio>\n#include <memory>");
            for (String module : List.of("left", "right")) {
                String cls = Character.toUpperCase(module.charAt(0)) + module.substring(1);
                Path cpp = pkg.resolve("low/" + cls + ".cpp");
                Tools.replace(cpp, "{ (void)message; }", "{\n  std::printf(\"subscriber " + module + " got %.0f %p\\n\", message.data, static_cast<const void*>(&message));\n"
                        + "  std::fflush(stdout);\n}");
                Tools.replace(cpp, "#include \"low/" + cls + ".hpp\"", "#include \"low/" + cls + ".hpp\"\n\n#include <cstdio>");
            }
        });
        Map<String, String> sent = new TreeMap<>();
        Matcher s = SENT.matcher(out);
        while (s.find()) {
            sent.put(s.group(1), s.group(2));
        }
        Map<String, List<String>> got = new TreeMap<>();
        Map<String, Map<String, String>> at = new TreeMap<>();
        Matcher g = GOT.matcher(out);
        while (g.find()) {
            got.computeIfAbsent(g.group(1), k -> new ArrayList<>()).add(g.group(2));
            at.computeIfAbsent(g.group(2), k -> new TreeMap<>()).put(g.group(1), g.group(3));
        }
        List<String> sentAndGot = sent.keySet().stream().filter(v -> at.containsKey(v) && at.get(v).size() == 2).toList();
        assertTrue(sentAndGot.size() >= 25, "both subscribers should have got most of the sent messages (every other one of a"
                + " message every 20 ms for " + Ros2LaunchTest.RUN_MS + " ms): " + sentAndGot.size() + "\n" + Tools.last(out, 4000));
        for (String v : sentAndGot) {
            assertEquals(Map.of("left", sent.get(v), "right", sent.get(v)), at.get(v), "message " + v + " as sent (its address) and as"
                    + " each subscriber got it: not the very object sent");
        }
        int kept = 0;
        Matcher k = KEPT.matcher(out);
        while (k.find()) {
            long count = Long.parseLong(k.group(1));
            if (count >= 4) {
                kept++;
                assertEquals(count - 2, Long.parseLong(k.group(2)), "at activation " + count + ", out_value holds the value set at activation "
                        + (count - 2) + " (the send between does not change it)");
            }
        }
        assertTrue(kept >= 25, "the producer set out_value in most of its activations: " + kept);
        for (Map.Entry<String, List<String>> e : got.entrySet()) {
            List<String> values = e.getValue();
            assertEquals(values.stream().distinct().count(), values.size(), e.getKey() + " got a value twice (an activation that"
                    + " sent also published the port's older value): " + values);
            long even = values.stream().filter(v -> Long.parseLong(v) % 2 == 0).count();
            assertTrue(even >= 25, e.getKey() + " got the values set to out_value too (published as a copy): " + even);
        }
    }

    /** The body of the method (or block) that {@code opening} opens, to its closing brace at the same indentation. */
    private static String section(String text, String opening) {
        int start = text.indexOf(opening);
        assertTrue(start >= 0, "no " + opening + " in:\n" + text);
        int lineStart = text.lastIndexOf('\n', start) + 1;
        String indent = text.substring(lineStart, start);
        int end = text.indexOf("\n" + indent + "}", start);
        assertTrue(end > start, "no end of " + opening);
        return text.substring(start, end);
    }

    private static int count(String text, String what) {
        return text.split(Pattern.quote(what), -1).length - 1;
    }
}
