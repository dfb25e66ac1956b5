/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.rsaml.generator.internal.NameScope;
import org.rsaml.generator.internal.Names;
import org.rsaml.generator.internal.cxx.CxxNames;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.DataKind;
import org.rsaml.analysis.plan.Flow;
import org.rsaml.analysis.plan.LinkPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.analysis.plan.Release;
import org.rsaml.model.NodeLifecycle;
import org.rsaml.model.support.RsamlTimes;
import org.rsaml.model.Processor;
import org.rsaml.model.support.RsamlNames;
import org.rsaml.model.support.RsamlTopics;

/**
 * What only the ROS 2 target names and decides: node and executable names, the interfaces package
 * and its message types, the ROS types of the ports, the topics (ports joined by connections share
 * one topic, named after their first output port, relative so that a launch namespace moves them
 * all), each topic's QoS, and how often a module in a reactive cycle may react.
 */
public final class Ros2Names {

    /** A structured message type: a ROS type named on the port, or one of the interfaces package. */
    public static final class RosMessage {
        private static final Pattern ROS_NAME = Pattern.compile("([a-z][a-z0-9_]*)/(?:msg/)?([A-Z][A-Za-z0-9]*)");
        public final String key;
        public final String rosPackage;
        public final String rosName;
        public final String rosCppName;
        public final String rosHeader;
        /** Whether the type is defined in the generated interfaces package. */
        public final boolean rosGenerated;

        RosMessage(String interfacesPackage, String key, NameScope scope) {
            this.key = key;
            Matcher m = ROS_NAME.matcher(key);
            if (m.matches()) {
                rosGenerated = false;
                rosPackage = m.group(1);
                rosName = m.group(2);
            } else {
                rosGenerated = true;
                rosPackage = interfacesPackage;
                String base = String.join("", Names.words(key.replace("/", "_")).stream()
                        .map(w -> Character.toUpperCase(w.charAt(0)) + w.substring(1)).toList());
                if (base.isEmpty() || !Character.isLetter(base.charAt(0))) {
                    base = "Msg" + base;
                }
                rosName = scope.allocate(base).replace("_", "");
            }
            rosCppName = rosPackage + "::msg::" + rosName;
            rosHeader = rosPackage + "/msg/" + Names.rosidlHeaderStem(rosName) + ".hpp";
        }
    }

    private final String interfacesPackage;
    private final Map<PlannedModule, String> executables = new IdentityHashMap<>();
    private final String containerExecutable;
    private final String lifecycleManagerExecutable;
    private final List<PlannedModule> managed;
    private final Map<PlannedPort, String> topics = new IdentityHashMap<>();
    private final Map<String, RosMessage> messages = new LinkedHashMap<>();
    private final Map<PlannedPort, Boolean> sensorTopics = new IdentityHashMap<>();
    private final Map<PlannedModule, Long> cycleBounds = new IdentityHashMap<>();
    private final List<Container> containers = new ArrayList<>();
    private final Map<String, String> topicArguments = new LinkedHashMap<>();

    /**
     * A component container: the nodes of the modules allocated to one processor, in one process
     * pinned to the processor's core when it has one; or, as the model's 'default' processor, the
     * nodes of the modules no processor names (all of them without a deployment).
     */
    public static final class Container {
        /** The container's node name, unique among the package's node names. */
        public final String name;
        /** The processor, or null for the modules no processor names. */
        public final Processor processor;
        /** The CPU core the container's process is pinned to, or -1. */
        public final int core;
        public final List<PlannedModule> modules = new ArrayList<>();

        Container(String name, Processor processor) {
            this.name = name;
            this.processor = processor;
            this.core = processor == null ? -1 : processor.getCore();
        }
    }

    public Ros2Names(ExecutionPlan plan, CxxNames names) {
        this.interfacesPackage = names.project() + "_interfaces";
        // The shared library of the nodes is named after the package.
        RsamlNames.RosNodes nodes = new RsamlNames.RosNodes(names.ids(), names.project());
        RsamlNames.Scope executableScope = nodes.scope();
        for (PlannedModule m : plan.modules()) {
            executables.put(m, nodes.of(m.module()));
        }
        // Containers are nodes too, in the same namespace: one per processor that runs a module,
        // in the model's order, then one for the modules no processor names.
        Map<Processor, Container> byProcessor = new LinkedHashMap<>();
        Container unallocated = null;
        for (Processor p : plan.architecture().getProcessors()) {
            if (plan.modules().stream().anyMatch(m -> m.processor() == p)) {
                byProcessor.put(p, new Container(executableScope.allocate(
                        Names.stem(names.project() + "_" + Names.snake(p.getName()) + "_container")), p));
            }
        }
        for (PlannedModule m : plan.modules()) {
            if (m.processor() != null) {
                byProcessor.get(m.processor()).modules.add(m);
            } else {
                if (unallocated == null) {
                    unallocated = new Container(executableScope.allocate(names.project() + "_container"), null);
                }
                unallocated.modules.add(m);
            }
        }
        containers.addAll(byProcessor.values());
        if (unallocated != null) {
            containers.add(unallocated);
        }
        containerExecutable = executableScope.allocate(names.project() + "_component_container");
        lifecycleManagerExecutable = executableScope.allocate(names.project() + "_lifecycle_manager");
        managed = plan.modules().stream().filter(m -> m.module().effectiveLifecycle() == NodeLifecycle.MANAGED).toList();
        NameScope messageScope = new NameScope(true);
        for (String key : plan.messageTypes()) {
            messages.put(key, new RosMessage(interfacesPackage, key, messageScope));
        }
        assignTopics(plan, names);
        boundCycles(plan);
    }

    private void assignTopics(ExecutionPlan plan, CxxNames names) {
        // the topic of each port, named or default, as the rule on topics (RSA-28) sees it
        RsamlTopics.Table table = RsamlTopics.table(names.ids());
        List<PlannedPort> all = new ArrayList<>();
        for (PlannedModule m : plan.modules()) {
            all.addAll(m.ports());
        }
        Map<PlannedPort, PlannedPort> parent = new HashMap<>();
        for (PlannedPort p : all) {
            parent.put(p, p);
        }
        for (Flow f : plan.flows()) {
            PlannedPort a = find(parent, f.source());
            PlannedPort b = find(parent, f.target());
            if (a != b) {
                parent.put(b, a);
            }
        }
        Map<PlannedPort, Boolean> sensorOfRoot = new HashMap<>();
        NameScope arguments = new NameScope(false, "namespace", "use_sim_time", "simulated_load");
        for (PlannedPort p : all) {
            String named = RsamlTopics.named(p.port());
            if (named != null && named.equals(table.topic(p.port())) && !topicArguments.containsKey(named)) {
                topicArguments.put(named, arguments.allocate(Names.stem(named.replaceFirst("^/", "").replace('/', '_') + "_topic")));
            }
        }
        for (PlannedPort p : all) {
            if (!p.entry() && !p.module().module().getSensors().isEmpty() && p.module().module().getActuators().isEmpty()) {
                sensorOfRoot.put(find(parent, p), true);
            }
        }
        for (PlannedPort p : all) {
            topics.put(p, table.topic(p.port()));
            sensorTopics.put(p, sensorOfRoot.getOrDefault(find(parent, p), false));
        }
    }

    /**
     * ROS 2 messages carry no wave, so a module in a reactive cycle is held to what the wave
     * semantics gives it: at most one reaction per wave, and waves come at most as often as the
     * shortest period of the timed releases whose data reaches the module (of the architecture when
     * none reaches it; never again after the first reaction when nothing is timed).
     */
    private void boundCycles(ExecutionPlan plan) {
        if (plan.reactiveCycles().isEmpty()) {
            return;
        }
        // A module's bound is the shortest period of the releases of the modules its data comes from (itself
        // included). Spreading each release's period downstream, the shortest first, and stopping where a module
        // already has one, visits every module and every feeding edge once (not a search upstream per module).
        Map<PlannedModule, List<PlannedModule>> fed = new HashMap<>();
        for (Flow f : plan.flows()) {
            fed.computeIfAbsent(f.source().module(), k -> new ArrayList<>()).add(f.target().module());
        }
        for (LinkPlan l : plan.links()) {
            if (l.deliversData()) {
                fed.computeIfAbsent(l.trigger().module(), k -> new ArrayList<>()).add(l.target().module());
            }
        }
        List<Release> releases = new ArrayList<>(plan.releases());
        releases.sort(java.util.Comparator.comparingLong(Release::periodNs));
        long shortest = releases.isEmpty() ? ExecutionPlan.MAX_TIME_NS : releases.get(0).periodNs();
        Map<PlannedModule, Long> bounds = new IdentityHashMap<>();
        Deque<PlannedModule> todo = new ArrayDeque<>();
        for (Release r : releases) {
            PlannedModule from = r.module();
            if (bounds.putIfAbsent(from, r.periodNs()) == null) {
                todo.add(from);
                while (!todo.isEmpty()) {
                    for (PlannedModule next : fed.getOrDefault(todo.pop(), List.of())) {
                        if (bounds.putIfAbsent(next, r.periodNs()) == null) {
                            todo.add(next);
                        }
                    }
                }
            }
        }
        for (List<PlannedModule> cycle : plan.reactiveCycles()) {
            for (PlannedModule m : cycle) {
                cycleBounds.put(m, bounds.getOrDefault(m, shortest));
            }
        }
    }

    private static PlannedPort find(Map<PlannedPort, PlannedPort> parent, PlannedPort p) {
        while (parent.get(p) != p) {
            p = parent.get(p);
        }
        return p;
    }

    /** The package of the structured types the model names without a ROS package. */
    public String interfacesPackage() {
        return interfacesPackage;
    }

    public String executable(PlannedModule m) {
        return executables.get(m);
    }

    /** The package's component container executable, which schedules the nodes' releases as analysed. */
    public String containerExecutable() {
        return containerExecutable;
    }

    /** The component containers the package's launch file starts, each with at least one node. */
    public List<Container> containers() {
        return containers;
    }

    /**
     * The topics the model names (Port.topic), in model order, each with the launch argument that
     * remaps it ({@code scan} -> {@code scan_topic}).
     */
    public Map<String, String> topicArguments() {
        return topicArguments;
    }

    /** The node's name: unique in the architecture, since all nodes share the launch namespace. */
    public String rosNode(PlannedModule m) {
        return executables.get(m);
    }

    /**
     * The port's topic: the one it or a port connected to it names (Port.topic, RSA-28), else one
     * named after the publisher's module path; relative ones resolve in the node's namespace.
     */
    public String topic(PlannedPort p) {
        return topics.get(p);
    }

    /**
     * Whether the port's topic is a sensor stream (published by a module that reads sensors and
     * drives no actuator): best effort, few messages kept; otherwise reliable, as commands and
     * results need.
     */
    public boolean sensorStream(PlannedPort p) {
        return sensorTopics.get(p);
    }

    /** The QoS profile of the port's topic, in C++. */
    public String qos(PlannedPort p) {
        return sensorStream(p) ? "rclcpp::SensorDataQoS()" : "rclcpp::QoS(10).reliable()";
    }

    /**
     * The policies of {@link #qos(PlannedPort)} a parameters file can override, as the values of
     * ROS 2's {@code qos_overrides.TOPIC.publisher|subscription.POLICY} parameters.
     */
    public Map<String, String> qosPolicies(PlannedPort p) {
        Map<String, String> policies = new LinkedHashMap<>();
        policies.put("reliability", sensorStream(p) ? "best_effort" : "reliable");
        policies.put("history", "keep_last");
        policies.put("depth", sensorStream(p) ? "5" : "10");
        return policies;
    }

    /** Whether the module's node is managed (an rclcpp_lifecycle node): its own lifecycle, else its architecture's. */
    public boolean managed(PlannedModule m) {
        return managed.contains(m);
    }

    /** The modules whose nodes are managed, in model order. */
    public List<PlannedModule> managedModules() {
        return managed;
    }

    /** The executable that configures and activates the managed nodes (built only when there are some). */
    public String lifecycleManagerExecutable() {
        return lifecycleManagerExecutable;
    }

    /** For a module in a reactive cycle, the least time between two reactions (0: not in a cycle). */
    public long cycleBoundNs(PlannedModule m) {
        return cycleBounds.getOrDefault(m, 0L);
    }

    /** A bound for messages: {@code 20 ms}, or {@code run} when the module reacts only once. */
    public static String duration(long ns) {
        if (ns >= ExecutionPlan.MAX_TIME_NS) {
            return "run (nothing timed feeds it)";
        }
        return RsamlTimes.milliseconds(ns);
    }

    /** The least time between two reactions of the module: its sporadic interval or its cycle's bound. */
    public long reactionIntervalNs(PlannedModule m) {
        return Math.max(m.minIntervalNs(), cycleBoundNs(m));
    }

    public List<RosMessage> messages() {
        return new ArrayList<>(messages.values());
    }

    /**
     * Whether a message on this trigger port asserts its links only when its value is true: a boolean
     * port; on any other data kind every message asserts them (docs/timing.md, "Inhibitors and
     * suppressors"; the C++ runtime's {@code asserts()}). A message that does not assert has no effect.
     */
    public boolean assertsOnlyWhenTrue(PlannedPort trigger) {
        return trigger.kind() == DataKind.BOOLEAN;
    }

    public String rosType(PlannedPort p) {
        return switch (p.kind()) {
            case NUMERIC -> "std_msgs::msg::Float64";
            case ALPHANUMERIC -> "std_msgs::msg::String";
            case BOOLEAN -> "std_msgs::msg::Bool";
            case STRUCTURED -> messages.get(p.messageType()).rosCppName;
        };
    }

    public String rosHeader(PlannedPort p) {
        return switch (p.kind()) {
            case NUMERIC -> "std_msgs/msg/float64.hpp";
            case ALPHANUMERIC -> "std_msgs/msg/string.hpp";
            case BOOLEAN -> "std_msgs/msg/bool.hpp";
            case STRUCTURED -> messages.get(p.messageType()).rosHeader;
        };
    }

    public String rosPackage(PlannedPort p) {
        return p.messageType() != null ? messages.get(p.messageType()).rosPackage : "std_msgs";
    }
}
