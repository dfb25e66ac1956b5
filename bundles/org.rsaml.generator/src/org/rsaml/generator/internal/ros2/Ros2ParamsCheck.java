/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads the architect's kept parameters file (config/&lt;pkg&gt;.params.yaml, through
 * {@link Ros2ParamsFile}) against what the model now gives each node, so that generating again
 * says, naming the file and line: a value that differs from the model's (the model changed since
 * the file was written, or the file was edited: either way the file's value is the one the node
 * runs with), a time the node no longer has (a function renamed, a unit changed: the launch files
 * refuse the file), a parameter no node declares (a misspelt name, which ROS 2 ignores), a
 * section of a node the package does not have, a node or parameter of the model the file lacks (a
 * module added, a line deleted: the file no longer has every parameter; the regenerated copy beside
 * it has), and a file the launch files cannot read.
 */
final class Ros2ParamsCheck {

    /** The name of a time parameter, its unit the suffix: the launch files refuse one its node does not have. */
    private static final Pattern TIME = Pattern.compile("[\\w.]+\\.(?:period|min_interval|duration)_(?:ns|us|ms|s)");
    /** A QoS override: qos_overrides.TOPIC.ENTITY.POLICY. */
    private static final Pattern QOS = Pattern.compile("qos_overrides\\.(.+)\\.(publisher|subscription)\\.(\\w+)");
    /** The QoS policies ROS 2 lets a parameter override. */
    private static final Set<String> POLICIES = Set.of("reliability", "history", "depth", "durability", "deadline", "lifespan", "liveliness",
            "liveliness_lease_duration", "avoid_ros_namespace_conventions");
    /** Parameters every generated node declares besides the model's (rclcpp's and the scheduling runtime's). */
    private static final Set<String> DECLARED = Set.of("use_sim_time", "rsaml.simulated_load", "start_type_description_service");
    /** Topics of ROS 2's own whose QoS a node's parameters may override. */
    private static final Set<String> ROS_TOPICS = Set.of("/parameter_events", "/rosout");

    private Ros2ParamsCheck() {
    }

    /**
     * The warnings about the parameters file {@code text} (at {@code path} in the output) given
     * {@code model}: each node's parameters with the model's values (times in their units, QoS), by
     * node name; {@code current} is where the regenerated copy with every parameter is.
     */
    static List<String> check(String path, String text, Map<String, Map<String, String>> model, String current) {
        List<String> warnings = new ArrayList<>();
        Ros2ParamsFile file = Ros2ParamsFile.read(text);
        if (file.error() != null) {
            warnings.add(path + ":" + file.error().line() + ": " + file.error().message() + "; the launch files refuse the file until you correct it");
            return warnings;
        }
        for (Ros2ParamsFile.Section s : file.sections()) {
            if (!model.containsKey(s.node()) && !s.node().contains("*")) {
                warnings.add(path + ":" + s.line() + ": there is no node '" + s.node() + "' in this package (its nodes: " + String.join(", ", model.keySet())
                        + "); ROS 2 gives its parameters to no node: correct the name or remove the section");
            }
        }
        for (Ros2ParamsFile.Parameter p : file.parameters()) {
            String at = path + ":" + p.line() + ": ";
            Map<String, String> values = model.get(p.node());
            if (values == null) {
                // a wildcard section (/**): its parameters are for any node
                if (p.node().contains("*") && model.values().stream().noneMatch(v -> declares(v, p.name()))) {
                    warnings.add(at + "no node of this package has a parameter " + p.name() + "; ROS 2 ignores it: correct the name or remove the line");
                }
                continue;
            }
            String modelValue = values.get(p.name());
            if (modelValue != null) {
                if (!same(p.value(), modelValue)) {
                    warnings.add(at + "node '" + p.node() + "' parameter " + p.name() + " is " + p.value() + " in this file but " + modelValue
                            + " in the model; the file's value is the one the node runs with (the file is yours and kept when you generate):"
                            + " to take the model's, edit the line to '" + p.name() + ": " + modelValue + "'");
                }
            } else if (TIME.matcher(p.name()).matches()) {
                List<String> times = values.keySet().stream().filter(n -> TIME.matcher(n).matches()).toList();
                warnings.add(at + "node '" + p.node() + "' has no parameter " + p.name() + " since the model changed (its times: "
                        + (times.isEmpty() ? "none" : String.join(", ", times)) + "); the launch files refuse the file until you rename or remove the line");
            } else if (!declares(values, p.name())) {
                warnings.add(at + "node '" + p.node() + "' has no parameter " + p.name() + " (its parameters: " + String.join(", ", values.keySet())
                        + "); ROS 2 ignores it: correct the name or remove the line");
            }
        }
        lacking(path, text, file, model, current, warnings);
        return warnings;
    }

    /**
     * Warns about each node of the model without a section in the file and each parameter of the
     * model a node's section lacks (a wildcard section's parameters count for every node).
     */
    private static void lacking(String path, String text, Ros2ParamsFile file, Map<String, Map<String, String>> model, String current,
            List<String> warnings) {
        Map<String, Integer> sections = new LinkedHashMap<>();
        file.sections().forEach(s -> sections.putIfAbsent(s.node(), s.line()));
        Map<String, Set<String>> present = new HashMap<>();
        Set<String> everyNode = new HashSet<>();
        for (Ros2ParamsFile.Parameter p : file.parameters()) {
            (p.node().contains("*") ? everyNode : present.computeIfAbsent(p.node(), n -> new HashSet<>())).add(p.name());
        }
        String from = current + ", regenerated every time with every parameter as the model now has it";
        int end = Math.max(1, (int) text.chars().filter(c -> c == '\n').count());
        for (Map.Entry<String, Map<String, String>> node : model.entrySet()) {
            Set<String> names = present.getOrDefault(node.getKey(), Set.of());
            Map<String, String> missing = new LinkedHashMap<>(node.getValue());
            missing.keySet().removeIf(n -> names.contains(n) || everyNode.contains(n));
            Integer line = sections.get(node.getKey());
            if (line == null && !missing.isEmpty()) {
                List<String> values = missing.entrySet().stream().map(e -> e.getKey() + ": " + e.getValue()).toList();
                warnings.add(path + ":" + end + ": this file has no section for node '" + node.getKey() + "' (a module added since the file was"
                        + " written, or its section deleted); the node runs with the model's values (" + String.join(", ", values)
                        + "), which you cannot tune here, and generating warns about it every time until it is"
                        + " there: copy its section into this file from " + from);
            } else if (line != null) {
                missing.forEach((name, value) -> warnings.add(path + ":" + line + ": node '" + node.getKey() + "' has no line for parameter " + name
                        + "; the node runs with the model's value " + value + ", and generating warns about it every time until the line is back:"
                        + " add '" + name + ": " + value + "' to its ros__parameters, as in " + from));
            }
        }
    }

    /** Whether a node with the model's parameters {@code values} declares {@code name}. */
    private static boolean declares(Map<String, String> values, String name) {
        if (values.containsKey(name) || DECLARED.contains(name)) {
            return true;
        }
        Matcher qos = QOS.matcher(name);
        if (!qos.matches() || !POLICIES.contains(qos.group(3))) {
            return false;
        }
        String entity = "qos_overrides." + qos.group(1) + "." + qos.group(2) + ".";
        return ROS_TOPICS.contains(qos.group(1)) || values.keySet().stream().anyMatch(n -> n.startsWith(entity));
    }

    /** Whether a value written in the file is the model's: the same number (20 is 20.0), else the same text. */
    private static boolean same(String written, String model) {
        try {
            return new BigDecimal(written.strip()).compareTo(new BigDecimal(model)) == 0;
        } catch (NumberFormatException e) {
            return written.strip().equals(model);
        }
    }
}
