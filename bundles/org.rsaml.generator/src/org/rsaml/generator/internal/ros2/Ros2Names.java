/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.util.ArrayList;
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
import org.rsaml.generator.plan.ExecutionPlan;
import org.rsaml.generator.plan.ExecutionPlan.Flow;
import org.rsaml.generator.plan.ExecutionPlan.PlannedModule;
import org.rsaml.generator.plan.ExecutionPlan.PlannedPort;

/**
 * What only the ROS 2 target names: executables, the interfaces package and its message types,
 * the ROS types of the ports, and the topics (ports joined by connections share one topic, named
 * after their first output port).
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
    private final Map<PlannedPort, String> topics = new IdentityHashMap<>();
    private final Map<String, RosMessage> messages = new LinkedHashMap<>();

    public Ros2Names(ExecutionPlan plan, CxxNames names) {
        this.interfacesPackage = names.project() + "_interfaces";
        NameScope executableScope = new NameScope(true);
        for (PlannedModule m : plan.modules()) {
            executables.put(m, executableScope.allocate(Names.stem(names.layerId(m) + "_" + names.nodeName(m))));
        }
        NameScope messageScope = new NameScope(true);
        for (String key : plan.messageTypes()) {
            messages.put(key, new RosMessage(interfacesPackage, key, messageScope));
        }
        assignTopics(plan, names);
    }

    private void assignTopics(ExecutionPlan plan, CxxNames names) {
        Map<PlannedPort, String> own = new HashMap<>();
        List<PlannedPort> all = new ArrayList<>();
        for (PlannedModule m : plan.modules()) {
            NameScope segments = new NameScope(false);
            for (PlannedPort p : m.ports()) {
                own.put(p, "/" + names.layerId(m) + "/" + names.nodeName(m) + "/" + segments.allocate(Names.snake(p.port().getName())));
                all.add(p);
            }
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
        Map<PlannedPort, String> topicOfRoot = new HashMap<>();
        for (PlannedPort p : all) {
            if (!p.entry()) {
                topicOfRoot.putIfAbsent(find(parent, p), own.get(p));
            }
        }
        for (PlannedPort p : all) {
            topics.put(p, topicOfRoot.getOrDefault(find(parent, p), own.get(p)));
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

    public String topic(PlannedPort p) {
        return topics.get(p);
    }

    public List<RosMessage> messages() {
        return new ArrayList<>(messages.values());
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
