/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.math.BigDecimal;
import java.util.ArrayList;
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
 * section of a node the package does not have, and a file the launch files cannot read.
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
     * node name.
     */
    static List<String> check(String path, String text, Map<String, Map<String, String>> model) {
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
                            + " to take the model's, edit the line to '" + p.name() + ": " + modelValue + "' or delete it");
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
        return warnings;
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
