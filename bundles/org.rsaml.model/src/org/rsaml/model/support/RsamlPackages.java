/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.PackageLayout;
import org.rsaml.model.Processor;

/**
 * The ROS 2 packages of an architecture's nodes (Architecture.packages), read once for the rule that
 * checks their names (RSA-29) and the ROS 2 generator that makes them: with {@code perLayer} each
 * layer that has modules gets a package of its nodes, with {@code perProcessor} each processor that
 * has modules (and {@value #DEFAULT}, the modules no processor names); the package is named
 * {@code <architecture>_<part>}, where the part is made from the layer's or processor's name by
 * {@link #part(String)}. A ROS package name (REP 144) is lower-case letters, digits and single
 * underscores, starting with a letter: the architecture's part is one, so a part that is one (or
 * starts with a digit) makes a valid name.
 */
public final class RsamlPackages {

    /** The part of the package of the modules no processor names, with {@code perProcessor}. */
    public static final String DEFAULT = "default";

    /** The part of the package of the message types the model names. */
    public static final String INTERFACES = "interfaces";

    /** The part of the package of the scheduling runtime, the component container and the lifecycle manager. */
    public static final String RUNTIME = "runtime";

    private static final Set<String> TAKEN = Set.of(INTERFACES, RUNTIME);

    /**
     * ROS 2's own packages that a generated package may not be named like: those the ROS 2 target's package.xml
     * files and CMakeLists.txt name (build tools, client libraries, launch, linters, rosidl; the generator's tests
     * hold every package it names to this list, besides the generated ones and those the model's ports name), and
     * the message and interface packages of a ROS 2 installation a port may name. A package of the same name would
     * depend on itself (colcon refuses it) or hide ROS 2's from every package built on it.
     */
    public static final Set<String> ROS2_OWN = Set.of("ament_cmake", "ament_lint_auto", "ament_lint_common",
            "launch", "launch_ros", "launch_testing", "launch_testing_ament_cmake", "launch_testing_ros", "ros2launch",
            "rcl", "rclcpp", "rclpy", "rclcpp_components", "rclcpp_lifecycle", "rclcpp_action", "rcutils", "rmw", "rosidl_default_generators",
            "rosidl_default_runtime", "builtin_interfaces", "rcl_interfaces", "lifecycle_msgs", "action_msgs", "service_msgs",
            "type_description_interfaces", "unique_identifier_msgs", "rosgraph_msgs", "statistics_msgs", "std_msgs", "std_srvs",
            "sensor_msgs", "geometry_msgs", "nav_msgs", "diagnostic_msgs", "shape_msgs", "stereo_msgs", "trajectory_msgs",
            "visualization_msgs", "actionlib_msgs", "tf2_msgs");

    private RsamlPackages() {
    }

    /**
     * The part a package name takes from a model name: its ASCII letters and digits, in lower case,
     * the words (split at other characters, underscores and lower-to-upper case changes) joined by
     * single underscores ({@code Obstacle Detection}, {@code obstacleDetection} and
     * {@code obstacle_detection} all give {@code obstacle_detection}); empty when it has none.
     */
    public static String part(String name) {
        return String.join("_", words(name)).toLowerCase(Locale.ROOT);
    }

    /**
     * The words of a name: runs of ASCII letters and digits, split at every other character and at
     * lower-to-upper case changes ({@code eMoveSP} gives {@code e}, {@code Move}, {@code SP}; an
     * acronym ends before the capital of the next word: {@code HTTPServer} gives {@code HTTP},
     * {@code Server}). RsaML's one rule for the words of a name: the generators make every name of
     * the generated code from these words too.
     */
    public static List<String> words(String raw) {
        List<String> words = new ArrayList<>();
        if (raw == null) {
            return words;
        }
        StringBuilder part = new StringBuilder();
        for (int i = 0; i <= raw.length(); i++) {
            char c = i < raw.length() ? raw.charAt(i) : ' ';
            boolean ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
            if (ok) {
                part.append(c);
                continue;
            }
            int start = 0;
            for (int j = 1; j < part.length(); j++) {
                char prev = part.charAt(j - 1);
                char cur = part.charAt(j);
                boolean lowerToUpper = (Character.isLowerCase(prev) || Character.isDigit(prev)) && Character.isUpperCase(cur);
                boolean acronymEnd = Character.isUpperCase(prev) && Character.isUpperCase(cur) && j + 1 < part.length()
                        && Character.isLowerCase(part.charAt(j + 1));
                if (lowerToUpper || acronymEnd) {
                    words.add(part.substring(start, j));
                    start = j;
                }
            }
            if (part.length() > start) {
                words.add(part.substring(start));
            }
            part.setLength(0);
        }
        return words;
    }

    /**
     * The name of the package named after the architecture, from the architecture's name made a ROS name
     * ({@code snake}): that name, or, when it or the interfaces or runtime package named after it
     * ({@code <name>_interfaces}, {@code <name>_runtime}) would be one of ROS 2's own packages ({@link #ROS2_OWN}),
     * the first of {@code <name>_2}, {@code <name>_3}, ... for which none is.
     */
    public static String systemPackage(String snake) {
        return new RsamlNames.Scope(false, ROS2_OWN.toArray(String[]::new)).allocate(snake, "", "", "", "_" + INTERFACES, "", "_" + RUNTIME);
    }

    /**
     * The generator's warning for an element whose package got another name than {@code named} because
     * {@code own} (the names among it and those named after it that are) would be ROS 2's own packages:
     * which element, its new and old name, why, what takes the new name and how to choose another.
     *
     * @param element the element as a user knows it ({@code architecture 'mobileBase'}, {@code layer 'msgs'})
     * @param whatIs what is named {@code fresh}, with its verb ({@code the package of its nodes is})
     */
    public static String renamedFromOwn(String element, String fresh, String named, List<String> own, String whatIs) {
        return element + " is named " + fresh + " in ROS 2, not " + named + ": " + String.join(" and ", own)
                + (own.size() == 1 ? " is a package" : " are packages") + " of ROS 2 itself (a generated package of that name would"
                + " depend on itself or hide ROS 2's); " + whatIs + " named " + fresh
                + " (rename the " + element.replaceFirst(" .*", "") + " to choose another name)";
    }

    /** The layout the architecture asks for; single when the element is in none. */
    public static PackageLayout layout(Architecture architecture) {
        return architecture == null ? PackageLayout.SINGLE : architecture.getPackages();
    }

    /**
     * What makes the package of this layer's nodes unusable (completing "Layer 'x' "), or null: the
     * architecture asks for no package per layer, the layer has no modules, or the name is usable.
     */
    public static String problem(Layer layer) {
        Architecture a = layer.getArchitecture();
        if (layout(a) != PackageLayout.PER_LAYER || layer.getModules().isEmpty()) {
            return null;
        }
        List<Object> others = new ArrayList<>();
        for (Layer l : a.getLayers()) {
            if (l != layer && !l.getModules().isEmpty()) {
                others.add(l);
            }
        }
        return problem(part(layer.getName()), "layer", others);
    }

    /**
     * What makes the package of this processor's nodes unusable (completing "Processor 'x' "), or
     * null: the architecture asks for no package per processor, no module is allocated to it, or the
     * name is usable.
     */
    public static String problem(Processor processor) {
        Architecture a = processor.eContainer() instanceof Architecture arch ? arch : null;
        if (layout(a) != PackageLayout.PER_PROCESSOR || processor.getModules().isEmpty()) {
            return null;
        }
        String part = part(processor.getName());
        if (part.equals(DEFAULT)) {
            return "would put its nodes in the package ending _" + DEFAULT + ", the package of the modules no processor names"
                    + " (packages perProcessor); rename the processor";
        }
        List<Object> others = new ArrayList<>();
        for (Processor p : a.getProcessors()) {
            if (p != processor && !p.getModules().isEmpty()) {
                others.add(p);
            }
        }
        return problem(part, "processor", others);
    }

    private static String problem(String part, String kind, List<Object> others) {
        String layout = kind.equals("layer") ? "packages perLayer" : "packages perProcessor";
        if (part.isEmpty()) {
            return "has no ASCII letter or digit in its name to make the name of its nodes' ROS 2 package from (" + layout
                    + "); a ROS package name is lower-case letters, digits and underscores: rename the " + kind;
        }
        if (TAKEN.contains(part)) {
            return "would put its nodes in the package ending _" + part + ", the package of the "
                    + (part.equals(INTERFACES) ? "model's message types" : "scheduling runtime") + " (" + layout + "); rename the " + kind;
        }
        for (Object o : others) {
            String name = o instanceof Layer l ? l.getName() : ((Processor) o).getName();
            if (part(name).equals(part)) {
                return "would put its nodes in the same ROS 2 package as " + kind + " '" + RsamlLabels.name((org.eclipse.emf.ecore.EObject) o)
                        + "' (the package name ending _" + part + ", " + layout + "); rename one of them";
            }
        }
        return null;
    }
}
