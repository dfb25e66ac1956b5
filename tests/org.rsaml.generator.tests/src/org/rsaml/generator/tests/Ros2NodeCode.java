/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.rsaml.model.Architecture;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;

/**
 * What {@link Ros2Test} checks in the code of a generated package's nodes (gen/): messages by shared
 * pointer, the package's launch test, and a timer per periodic function on the node's clock with its
 * period a parameter.
 */
final class Ros2NodeCode {
    private Ros2NodeCode() {
    }

    /**
     * Every subscription takes a ConstSharedPtr, which the node keeps as in_&lt;port&gt; (no copy on the
     * way to the reaction), and every publication hands over a unique_ptr.
     */
    static void assertMessagesByPointer(Architecture arch, Path root) throws Exception {
        String nodesText = allText(root.resolve("gen"));
        Matcher sub = Pattern.compile("this->create_subscription<([\\w:]+)>\\(.*?\\]\\(([^)]*)\\) \\{", Pattern.DOTALL).matcher(nodesText);
        int subscriptions = 0;
        while (sub.find()) {
            subscriptions++;
            assertEquals(sub.group(1) + "::ConstSharedPtr message", sub.group(2), "a subscription's callback must take the message by shared pointer");
        }
        int inputs = arch.getLayers().stream().flatMap(l -> l.getModules().stream()).mapToInt(m -> (int) m.getPorts().stream()
                .filter(p -> !(p instanceof OutputPort)).count()).sum();
        assertTrue(subscriptions >= inputs, subscriptions + " subscriptions for " + inputs + " entry ports");
        assertFalse(nodesText.contains("= *message"), "a message is copied into an entry port");
        Matcher entry = Pattern.compile("\\n\\s*([\\w:]+) (in_\\w+);").matcher(nodesText);
        while (entry.find()) {
            assertTrue(entry.group(1).endsWith("::ConstSharedPtr"), "entry port " + entry.group(2) + " holds a copy: " + entry.group(1));
        }
        Matcher publish = Pattern.compile("->publish\\(([^;]*)\\);").matcher(nodesText);
        while (publish.find()) {
            // a copy of the port's value, or the message an output port's send method was handed (Ros2SendTest)
            assertTrue(publish.group(1).startsWith("std::make_unique<") || publish.group(1).equals("std::move(message)"),
                    "a publication that is not a unique_ptr: " + publish.group());
        }
    }

    /**
     * colcon test: linters where installed, and the launch test, added only under BUILD_TESTING and
     * where launch_testing is found, which names the entry ports that timed modules feed (each must
     * receive messages) and is valid Python.
     */
    static void assertLaunchTest(Architecture arch, String pkg, Path root, String cmake) throws Exception {
        Matcher testing = Pattern.compile("(?s)\\nif\\(BUILD_TESTING\\)\\n(.*?)\\nendif\\(\\)\\n").matcher(cmake);
        assertTrue(testing.find(), "no BUILD_TESTING block:\n" + cmake);
        assertTrue(testing.group(1).contains("find_package(ament_lint_auto QUIET)\n  if(ament_lint_auto_FOUND)\n"), testing.group(1));
        assertTrue(testing.group(1).contains("find_package(launch_testing_ament_cmake QUIET)\n  if(launch_testing_ament_cmake_FOUND)\n    add_launch_test(test/test_"
                + pkg + "_launch.py TIMEOUT 120)\n  else()"), "the launch test is added only where launch_testing is found:\n" + testing.group(1));
        assertEquals(1, cmake.split("add_launch_test\\(", -1).length - 1, "the launch test is added once, in the BUILD_TESTING block:\n" + cmake);
        Path launchTest = root.resolve("test/test_" + pkg + "_launch.py");
        Tools.ok(root, 60, Ros2Build.python(), "-m", "py_compile", launchTest.toString());
        Matcher fed = Pattern.compile("FED_PORTS = \\[(.*)\\]").matcher(Files.readString(launchTest));
        assertTrue(fed.find(), "the launch test names no ports: " + launchTest);
        Set<String> expectedFed = new TreeSet<>();
        for (org.rsaml.analysis.plan.Flow f : org.rsaml.analysis.plan.ExecutionPlan.of(arch).flows()) {
            if (!f.source().module().releases().isEmpty()) {
                expectedFed.add(f.target().module().qualifiedName() + ":" + f.target().name());
            }
        }
        Set<String> listed = new TreeSet<>();
        Matcher quoted = Pattern.compile("'((?:[^'\\\\]|\\\\.)*)'").matcher(fed.group(1));
        while (quoted.find()) {
            listed.add(quoted.group(1));
        }
        if (expectedFed.stream().noneMatch(x -> x.contains("'") || x.contains("\\"))) {
            assertEquals(expectedFed, listed, "the entry ports the launch test expects messages at");
        }
    }

    /**
     * A timer per periodic function, on the node's clock, its period a parameter with the model's
     * value in the function's unit, which both launch files give the node ({@code nodeParameters}, by
     * node) from the parameters file. (The scheduling runtime in gen/rsaml/ stamps its trace lines
     * with the steady clock; its timers are the node's.)
     */
    static void assertTimers(Architecture arch, Path root, Map<String, String> nodeParameters, Map<String, String> nodesByModule) throws Exception {
        String all = allText(root.resolve("gen"));
        String scheduling = Files.readString(root.resolve("gen/rsaml/scheduling.hpp"));
        assertTrue(scheduling.contains("rclcpp::create_timer(\n        base_, timers_, clock_,") && scheduling.contains("node.get_clock()"),
                "the timers of a plain or managed node are on the node's clock:\n" + scheduling);
        assertFalse(all.contains("create_wall_timer"), "a wall timer ignores use_sim_time");
        assertFalse(all.contains("steady_clock"), "steady_clock ignores use_sim_time");
        assertTrue(all.contains("publisher_options.qos_overriding_options = rclcpp::QosOverridingOptions::with_default_policies();"), "publishers let the user override QoS from parameters");
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                for (Function f : m.getFunctions()) {
                    if (f.getExecType() == ExecutionType.PERIODIC && f.getPeriod() > 0) {
                        // in the function's unit, as the model and the parameters file write it
                        String value = new BigDecimal(Double.toString(f.getPeriod())).stripTrailingZeros().toPlainString();
                        value = value.contains(".") ? value : value + ".0";
                        String unit = f.getTimeUnit().getLiteral();
                        Matcher p = Pattern.compile("(timer_release_\\w+)_period_ = nanoseconds\\(\"([\\w.]+\\.period_" + unit
                                + ")\", this->declare_parameter<double>\\(\"\\2\", " + Pattern.quote(value) + "\\), " + f.getTimeUnit().getValue()
                                + "\\.0\\);").matcher(all);
                        assertTrue(p.find(), "no period parameter for " + f.getName() + " (" + value + " " + unit + ")");
                        String given = nodeParameters.get(nodesByModule.get(Ros2Test.key(m)));
                        assertTrue(given.contains(".period_" + unit + "': " + value), "the launch files do not give node "
                                + nodesByModule.get(Ros2Test.key(m)) + " the period of " + f.getName() + " from the parameters file: " + given);
                        assertTrue(all.contains(p.group(1) + "_ = this->rsaml_add_timer("), "no timer for " + f.getName());
                        assertTrue(all.contains(p.group(1) + "_period_, [this]"), "the timer of " + f.getName() + " does not take its period parameter");
                    }
                }
            }
        }
    }

    /** The node sources of a package's gen/ (not the scheduling runtime's), one after the other. */
    static String allText(Path dir) throws Exception {
        StringBuilder sb = new StringBuilder();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.filter(f -> f.toString().endsWith(".hpp") || f.toString().endsWith(".cpp"))
                    .filter(f -> !f.getParent().getFileName().toString().equals("rsaml")).sorted().toList()) {
                sb.append(Files.readString(p)).append('\n');
            }
        }
        return sb.toString();
    }
}
