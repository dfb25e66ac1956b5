/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.Names;
import org.rsaml.validation.ModelLoader;

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
            List<Path> bases = generatedBases(model, out);
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
                    int refused = send.indexOf("if (!message) {\n");
                    assertTrue(refused >= 0 && send.indexOf("throw std::invalid_argument(\"node ", refused) > refused
                            && send.contains("send_" + port + " was given no message (a null pointer)\");")
                            && refused < send.indexOf("sent_" + port + "_ = true;"), base + ": send_" + port + " does not refuse a null"
                            + " message first, with an exception naming the node and the method:\n" + send);
                    if (publishOutputs.contains("rsaml_active()")) {
                        managed++;
                        // The mark is set under the lock on_deactivate forgets the marks under, once the node is no longer active.
                        int locked = send.indexOf("std::lock_guard<std::mutex> lock(sending_);");
                        int checked = send.indexOf("if (!this->rsaml_active()) {");
                        assertTrue(locked > refused && checked > locked && send.indexOf("sent_" + port + "_ = true;") > checked
                                && checked < send.indexOf("->publish("), base + ": send_" + port + " of a managed node does not check the"
                                + " node active and mark the port under the lock sending_ before it publishes:\n" + send);
                        String deactivate = section(text, "CallbackReturn on_deactivate(const rclcpp_lifecycle::State& state) override {");
                        int lock = deactivate.indexOf("std::lock_guard<std::mutex> lock(sending_);");
                        int inactive = deactivate.indexOf("this->rsaml_state(false, \"inactive\");");
                        int forgot = deactivate.indexOf("sent_" + port + "_ = false;");
                        assertTrue(lock >= 0 && inactive > lock && forgot > inactive && !deactivate.substring(lock, forgot).contains("}"),
                                base + ": on_deactivate does not forget a send of port " + port + " (sent_" + port + "_ = false) under the"
                                        + " lock sending_, after the node stopped being active:\n" + deactivate);
                        assertTrue(text.contains("std::mutex sending_;"), base + ": no lock sending_");
                    }
                    assertTrue(text.contains("std::atomic<bool> sent_" + port + "_{false};"), base + ": no mark of port " + port + " sent");
                }
            }
        }
        assertTrue(ports > 0 && inhibited > 0 && managed > 0, "the models have output ports (" + ports + "), inhibited ones (" + inhibited
                + ") and ones of managed nodes (" + managed + ")");
    }

    /**
     * What the doc comment of a send method says of the publish that skips the port after a send is what that node does:
     * a node that reacts to data publishes at the end of the reaction that follows an input handler; a node that does not
     * (a periodic node: its input handlers run on each arrival, with no publish after them) publishes a send from an input
     * handler at once and skips the port at the end of its next release; a managed node forgets a send on deactivation.
     * Subsumption-brooks has periodic nodes with input and output ports, ros2-lifecycle managed ones. No ROS 2 needed.
     */
    @Test
    void theSendMethodSaysWhichPublishFollowsAnInputHandler(@TempDir Path tmp) throws Exception {
        int periodic = 0;
        int reacting = 0;
        int managed = 0;
        for (Path model : List.of(Tools.example("subsumption-brooks.rsaml"), Tools.resource("ros2-lifecycle.rsaml"))) {
            Path out = tmp.resolve(model.getFileName().toString());
            List<Path> bases = generatedBases(model, out);
            for (Path base : bases) {
                String text = Files.readString(base);
                boolean inputs = text.contains("ConstSharedPtr& message, bool replacing) {");
                boolean reacts = text.contains("this->rsaml_run_reaction(");
                boolean isManaged = text.contains("CallbackReturn on_deactivate(");
                Matcher o = OUTPUT.matcher(text);
                while (o.find()) {
                    String port = o.group(2);
                    int send = text.indexOf("void send_" + port + "(");
                    String doc = text.substring(text.lastIndexOf("/**", send), send).replaceAll("\\s*\\n\\s*\\*/?", " ").replaceAll("\\s+", " ");
                    String said = base + ": the doc comment of send_" + port + ":\n" + doc;
                    assertFalse(doc.contains("whose activation ends with that publish"), said);
                    if (inputs && reacts) {
                        reacting++;
                        assertTrue(doc.contains("An input handler is followed by the node's reaction, which ends with that publish"), said);
                    } else if (inputs) {
                        periodic++;
                        assertTrue(doc.contains("The input handlers run on each arrival and no publish follows them (the node does not"
                                + " react to data): a send from one is published at once, and the publish that ends the node's next"
                                + " release skips the port."), said);
                        assertFalse(doc.contains("reaction"), said);
                    }
                    if (isManaged) {
                        managed++;
                        assertTrue(doc.contains("Deactivating the node forgets a send that publish has not yet followed: the first"
                                + " publish after the node is activated again publishes the port's value."), said);
                    } else {
                        assertFalse(doc.contains("Deactivating"), said);
                    }
                }
            }
        }
        assertTrue(periodic > 0 && reacting > 0 && managed > 0, "the models have output ports of nodes with input handlers that no"
                + " publish follows (" + periodic + "), of nodes that react to data (" + reacting + ") and of managed nodes (" + managed + ")");
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

    private static final Pattern LIDAR_SET = Pattern.compile("lidar set (\\d+)");

    /**
     * On a real ROS 2 ({@link Ros2Jazzy}), the managed lidar and mapper of resources/ros2-lifecycle.rsaml, each in its
     * process, brought to active by the package's lifecycle manager. The lidar's code (written here) sets out_scan to the
     * number of each release and, in its on_deactivate, sends a message (-1) before the generated deactivation runs: a send
     * no publish of the ports has followed when the node stops being active. The lidar is deactivated and activated again
     * ({@code ros2 lifecycle set}): the mapper got the message sent, and the first release after the activation publishes
     * the port's value (the mapper gets its number), the send forgotten. Then the lidar, started again with LIDAR_SEND_NULL
     * set, sends a null message in its first release: its process says so in one line (an error in the node's code, naming
     * the send method) and aborts, neither status 0 nor 2.
     */
    @Test
    void aManagedNodeForgetsASendOnDeactivationAndRefusesANullOne(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        long started = System.nanoTime();
        Path model = Ros2Test.model("resources/ros2-lifecycle.rsaml");
        String pkg = Names.snake(ModelLoader.load(model, "ros2-lifecycle.rsaml").architecture().getName());
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        Path code = src.resolve(pkg + "/src");
        Path lidarCpp = code.resolve("perception/Lidar.cpp");
        Matcher action = Pattern.compile("void Lidar::(\\w+)\\(\\) \\{\\}").matcher(Files.readString(lidarCpp));
        assertTrue(action.find(), "the lidar's action as generated: " + lidarCpp);
        Tools.replace(lidarCpp, action.group(), "void Lidar::" + action.group(1) + "() {\n"
                + "  static long count = 0;\n"
                + "  ++count;\n"
                + "  if (std::getenv(\"LIDAR_SEND_NULL\")) {\n"
                + "    send_scan(nullptr);\n"
                + "  }\n"
                + "  out_scan.data = static_cast<double>(count);\n"
                + "  std::printf(\"lidar set %ld\\n\", count);\n"
                + "  std::fflush(stdout);\n"
                + "}");
        Tools.replace(lidarCpp, "#include \"perception/Lidar.hpp\"", "#include \"perception/Lidar.hpp\"\n\n#include <cstdio>\n#include <cstdlib>");
        Tools.replace(code.resolve("perception/Lidar.hpp"), "  using LidarBase::LidarBase;\n", """
                  using LidarBase::LidarBase;

                  CallbackReturn on_deactivate(const rclcpp_lifecycle::State& state) override {
                    auto message = std::make_unique<std_msgs::msg::Float64>();
                    message->data = -1.0;
                    std::printf("lidar sent -1\\n");
                    std::fflush(stdout);
                    send_scan(std::move(message));
                    return LidarBase::on_deactivate(state);
                  }
                """);
        Path mapperCpp = code.resolve("mapping/Mapper.cpp");
        Tools.replace(mapperCpp, "{ (void)message; }", "{\n  std::printf(\"mapper got %.0f\\n\", message.data);\n  std::fflush(stdout);\n}");
        Tools.replace(mapperCpp, "#include \"mapping/Mapper.hpp\"", "#include \"mapping/Mapper.hpp\"\n\n#include <cstdio>");
        Path install = Ros2Jazzy.colconBuild(src, tmp);
        Map<String, String> nodes = Ros2Test.nodes(src.resolve(pkg));
        String lidar = nodes.get("perception/lidar");
        String mapper = nodes.get("mapping/mapper");
        int domain = 1 + (int) ((ProcessHandle.current().pid() + 30) % 100);
        String lidarOut;
        String mapperOut;
        int reactivated;
        try (Ros2Process lidarNode = Ros2Process.start(tmp, install, domain, pkg, lidar, "", "send-lidar");
                Ros2Process mapperNode = Ros2Process.start(tmp, install, domain, pkg, mapper, "", "send-mapper");
                Ros2Process manager = Ros2Process.start(tmp, install, domain, pkg, pkg + "_lifecycle_manager --ros-args -p node_names:=[" + lidar + ","
                        + mapper + "]", "", "send-manager")) {
            manager.await(mapper + " is active", 1);
            mapperNode.await("mapper got 3", 1);
            lifecycle(tmp, install, domain, lidar, "deactivate");
            lidarNode.await("state perception/lidar inactive", 2);
            Thread.sleep(300); // no release runs while inactive
            lifecycle(tmp, install, domain, lidar, "activate");
            lidarNode.await("state perception/lidar active", 2);
            String o = lidarNode.output();
            // configured (inactive), activated, deactivated (inactive again), activated again
            int configured = o.indexOf("state perception/lidar inactive");
            reactivated = o.indexOf("state perception/lidar active", o.indexOf("state perception/lidar inactive", configured + 1));
            assertTrue(configured >= 0 && reactivated > configured, "the lidar was configured, activated, deactivated and activated again:\n"
                    + Tools.last(o, 4000));
            lidarNode.awaitAfter(LIDAR_SET, reactivated, 3);
            Thread.sleep(300); // the last scans reach the mapper
            lidarNode.signal();
            mapperNode.signal();
            manager.signal();
            lidarOut = lidarNode.exited();
            mapperOut = mapperNode.exited();
            manager.exited();
        }
        Matcher first = LIDAR_SET.matcher(lidarOut);
        assertTrue(first.find(reactivated), "the lidar ran after its activation:\n" + Tools.last(lidarOut, 4000));
        String firstAfter = first.group(1);
        String said = "the lidar said:\n" + Tools.last(lidarOut, 3000) + "\nthe mapper said:\n" + Tools.last(mapperOut, 3000);
        assertTrue(lidarOut.contains("lidar sent -1") && mapperOut.contains("mapper got -1\n"), "the message the lidar sent before it was"
                + " deactivated reached the mapper; " + said);
        List<String> got = mapperOut.lines().filter(l -> l.startsWith("mapper got ")).map(l -> l.substring("mapper got ".length())).toList();
        assertTrue(got.contains(firstAfter), "the first release of the lidar after it was activated again (" + firstAfter + ") published"
                + " the port's value: the send before the deactivation was forgotten; the mapper got " + got + "; " + said);
        Tools.took("Ros2SendTest", "a send forgotten on deactivation", started);

        // A null message: one line, and the program aborts.
        long nullStarted = System.nanoTime();
        try (Ros2Process lidarNode = Ros2Process.start(tmp, install, domain, pkg, lidar, "export LIDAR_SEND_NULL=1; ", "null-lidar");
                Ros2Process manager = Ros2Process.start(tmp, install, domain, pkg, pkg + "_lifecycle_manager --ros-args -p node_names:=[" + lidar + "]",
                        "", "null-manager")) {
            boolean ended = lidarNode.process().waitFor(120, TimeUnit.SECONDS);
            String out = lidarNode.output();
            String nullSaid = lidar + " given a null message to send said:\n" + Tools.last(out, 4000);
            assertTrue(ended, "still running 120 s after it was started; " + nullSaid + "\nthe lifecycle manager said:\n"
                    + Tools.last(manager.output(), 2000));
            int exit = lidarNode.process().exitValue();
            assertTrue(exit != 0 && exit != 2, () -> "exited with " + exit + ", not as a failed program (neither 0 nor 2); " + nullSaid);
            List<String> lines = out.lines().filter(l -> l.startsWith(lidar + ": ")).toList();
            assertEquals(1, lines.size(), () -> "one line of the program, not " + lines.size() + "; " + nullSaid);
            assertTrue(lines.get(0).startsWith(lidar + ": uncaught std::invalid_argument: node ") && lines.get(0).contains(
                    ": send_scan was given no message (a null pointer); an error in the node's code"), () -> "the line names the exception,"
                            + " the node and its send method, as an error of the node's code; " + nullSaid);
            assertFalse(out.contains("lidar set 1"), () -> "the release that sent null went on; " + nullSaid);
        } // the lifecycle manager, whose node is gone, is killed
        Tools.took("Ros2SendTest", "a null message refused", nullStarted);
    }

    /** Asks ROS 2 to take the managed node {@code node} through {@code transition} (up to 5 times, a second apart: discovery). */
    private static void lifecycle(Path tmp, Path install, int domain, String node, String transition) throws Exception {
        Tools.Result r = null;
        for (int attempt = 1; attempt <= 5 && (r == null || r.exit() != 0); attempt++) {
            if (attempt > 1) {
                Thread.sleep(1000);
            }
            r = Tools.run(tmp, 60, Ros2Jazzy.bash("export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST ROS_DOMAIN_ID=" + domain
                    + "; ros2 lifecycle set --no-daemon /" + node + " " + transition, install).toArray(String[]::new));
        }
        assertEquals(0, r.exit(), "ros2 lifecycle set /" + node + " " + transition + " said:\n" + r.output());
    }

    /** The node base classes (generated, under gen/) of the model's ROS 2 packages, generated into {@code out}. */
    private static List<Path> generatedBases(Path model, Path out) throws Exception {
        new RsamlGenerator().generate(model, Target.ROS2, out, false);
        try (Stream<Path> s = Files.walk(out)) {
            return s.filter(f -> f.toString().endsWith("Base.hpp") && f.toString().contains("/gen/")).sorted().toList();
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
