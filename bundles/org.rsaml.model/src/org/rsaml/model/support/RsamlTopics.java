/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.regex.Pattern;

import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.NodeLifecycle;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Port;

/**
 * The ROS 2 topics ports name (Port.topic), read once for the rule that checks them (RSA-28) and the
 * ROS 2 generator that uses them: a topic a port names is the topic of every port connected to it,
 * directly or through other ports, so such ports must not name different topics, and ports that are
 * not connected must not name the same one (ROS 2 would connect them).
 */
public final class RsamlTopics {

    /**
     * A topic name ROS 2 accepts as RsaML writes it: segments of letters, digits and underscores,
     * none starting with a digit, separated by single slashes; absolute (a leading slash) or relative
     * (resolved in the nodes' namespace). Names private to a node ({@code ~/x}) and substitutions
     * ({@code {node}}) are not taken: a topic is shared by the ports connected to it, in several nodes.
     */
    private static final Pattern TOPIC = Pattern.compile("/?[A-Za-z_][A-Za-z0-9_]*(?:/[A-Za-z_][A-Za-z0-9_]*)*");

    /** The longest full topic name (with its leading slash) ROS 2 takes: RMW_TOPIC_MAX_NAME_LENGTH, 255 less 8 for prefixes. */
    public static final int MAX_FULL_NAME = 255 - 8;

    /** The topics every ROS 2 node uses in the root namespace, with what they carry. */
    private static final Map<String, String> ROS2_TOPICS = Map.of(
            "rosout", "every node publishes its log messages there as rcl_interfaces/msg/Log",
            "parameter_events", "every node publishes its parameter changes there as rcl_interfaces/msg/ParameterEvent");

    private RsamlTopics() {
    }

    /** The topic the port names, without surrounding white space; null when it names none. */
    public static String named(Port port) {
        return RsamlText.normalized(port.getTopic());
    }

    /** Whether ROS 2 takes the name as a topic name. */
    public static boolean isValid(String topic) {
        return topic != null && TOPIC.matcher(topic).matches();
    }

    /** The ports connected to this one, directly or through other ports, itself first. */
    public static List<Port> connected(Port port) {
        Set<Port> seen = new LinkedHashSet<>();
        Deque<Port> todo = new ArrayDeque<>(List.of(port));
        while (!todo.isEmpty()) {
            Port p = todo.pop();
            if (!seen.add(p)) {
                continue;
            }
            if (p instanceof OutputPort o) {
                for (Connection c : o.getOutgoing()) {
                    if (c.getTarget() != null) {
                        todo.add(c.getTarget());
                    }
                }
            } else if (p instanceof EntryPort e) {
                for (Connection c : e.getIncoming()) {
                    if (c.getSource() != null) {
                        todo.add(c.getSource());
                    }
                }
            }
        }
        return new ArrayList<>(seen);
    }

    /** The topic the ports connected to this one share by name: the first their model order names; null when none does. */
    public static String sharedTopic(Port port) {
        for (Port p : connected(port)) {
            if (named(p) != null) {
                return named(p);
            }
        }
        return null;
    }

    /**
     * What makes the topic this port names unusable (completing "output port 'x' of module 'm' "),
     * or null: it is not a valid ROS 2 name, its full name is longer than ROS 2 takes, ROS 2 itself uses
     * it (rosout, parameter_events, a managed node's transition_event), a port connected to it names another topic, or a port it is not connected to names the same topic; or, for a port that names none and
     * whose default topic its group uses, that default topic is longer than ROS 2 takes. One port's answer reads the whole architecture:
     * to check every port, take {@link #table} once and ask it.
     */
    public static String problem(Port port) {
        return problem(port, RsamlTopics::table);
    }

    /**
     * As {@link #problem(Port)}, with the table of the port's architecture from {@code tables} (one
     * kept for a whole validation), asked for only when the answer needs it: a port that names no topic
     * and whose default topic is short has none, without reading the architecture.
     */
    public static String problem(Port port, Function<Architecture, Table> tables) {
        if (named(port) == null && !mayHaveLongDefault(port)) {
            return null;
        }
        Architecture architecture = architecture(port);
        return architecture == null ? new Table(List.of(connected(port)), null).problem(port) : tables.apply(architecture).problem(port);
    }

    /**
     * Whether the default topic of a port that names none could be longer than ROS 2 takes: its
     * names in snake case are near the limit (a name scope's suffix adds a few characters at most).
     * Spares reading the whole architecture for the ports whose default topic is short.
     */
    private static boolean mayHaveLongDefault(Port port) {
        Module m = port.getModule();
        if (m == null || m.getLayer() == null) {
            return false;
        }
        String layer = String.valueOf(m.getLayer().getName());
        String module = String.valueOf(m.getName());
        String name = String.valueOf(port.getName());
        // A name in snake case is at most 2 n + 9 characters long (an underscore between words of its n letters and
        // digits, or "unnamed"; an "n" before a leading digit, an "_" after a reserved word): short names end here,
        // without being put in snake case, as they would below.
        if (3 + 2 * (layer.length() + module.length() + name.length()) + 3 * 9 + 3 * 12 <= MAX_FULL_NAME) {
            return false;
        }
        int length = 3 + RsamlNames.snake(layer).length() + RsamlNames.snake(module).length() + RsamlNames.snake(name).length();
        return length + 3 * 12 > MAX_FULL_NAME;
    }

    /** The topics of an architecture's ports, read once (linear in its ports and connections). */
    public static Table table(Architecture architecture) {
        return table(new RsamlNames.Ids(architecture));
    }

    /** Likewise, with the architecture's names already made. */
    public static Table table(RsamlNames.Ids ids) {
        return new Table(groups(ids.ports()), ids);
    }

    private static Architecture architecture(Port port) {
        return port.getModule() == null || port.getModule().getLayer() == null ? null : port.getModule().getLayer().getArchitecture();
    }

    /** The ports in groups of ports connected to each other (directly or through other ports), in model order. */
    private static List<List<Port>> groups(List<Port> ports) {
        Map<Port, Port> parent = new IdentityHashMap<>();
        for (Port p : ports) {
            parent.put(p, p);
        }
        for (Port p : ports) {
            if (p instanceof OutputPort o) {
                for (Connection c : o.getOutgoing()) {
                    Port t = c.getTarget();
                    if (t != null && parent.containsKey(t)) {
                        Port a = root(parent, p);
                        Port b = root(parent, t);
                        if (a != b) {
                            parent.put(b, a);
                        }
                    }
                }
            }
        }
        Map<Port, List<Port>> byRoot = new LinkedHashMap<>();
        for (Port p : ports) {
            byRoot.computeIfAbsent(root(parent, p), k -> new ArrayList<>()).add(p);
        }
        return new ArrayList<>(byRoot.values());
    }

    private static Port root(Map<Port, Port> parent, Port p) {
        Port r = p;
        while (parent.get(r) != r) {
            r = parent.get(r);
        }
        while (parent.get(p) != r) {
            Port next = parent.get(p);
            parent.put(p, r);
            p = next;
        }
        return r;
    }

    /**
     * The topics of an architecture, by group of connected ports: the topic a group names (the first its
     * ports name), else the default topic of its first output port ({@link RsamlNames.Ids#defaultTopic});
     * each port's problem and topic are then found without reading the other ports again.
     */
    public static final class Table {

        /** Each port: its group's index. */
        private final Map<Port, Integer> groupOf = new IdentityHashMap<>();
        /** Per group: the first two ports that name different topics. */
        private final List<Port[]> distinct = new ArrayList<>();
        /** Per group: its topic (null without ids), and the port whose default it is (null when named). */
        private final List<String> topics = new ArrayList<>();
        private final List<Port> defaulted = new ArrayList<>();
        /** Per topic (as compared): the first port naming it in each of the first two groups that do. */
        private final Map<String, Port[]> namers = new HashMap<>();
        private final Map<String, int[]> namerGroups = new HashMap<>();
        /** Per default topic (as compared) of a group that names none: that group's index. */
        private final Map<String, Integer> defaults = new HashMap<>();
        /** Per topic of transitions of a managed module's node (as compared): that module. */
        private final Map<String, Module> transitionEvents = new HashMap<>();
        private final RsamlNames.Ids ids;

        Table(List<List<Port>> groups, RsamlNames.Ids ids) {
            this.ids = ids;
            if (ids != null) {
                // The nodes' names as the generator gives them (a clash renamed), in the package named after the architecture.
                RsamlNames.RosNodes nodes = new RsamlNames.RosNodes(ids, RsamlPackages.systemPackage(RsamlNames.snake(ids.architectureName())));
                for (Module m : ids.modules()) {
                    if (m.effectiveLifecycle() == NodeLifecycle.MANAGED) {
                        transitionEvents.put(nodes.transitionEventTopic(m), m);
                    }
                }
            }
            for (int g = 0; g < groups.size(); g++) {
                Port[] two = new Port[2];
                Port firstOutput = null;
                for (Port p : groups.get(g)) {
                    groupOf.put(p, g);
                    if (firstOutput == null && p instanceof OutputPort) {
                        firstOutput = p;
                    }
                    String topic = named(p);
                    if (topic == null) {
                        continue;
                    }
                    if (two[0] == null) {
                        two[0] = p;
                    } else if (two[1] == null && !same(named(two[0]), topic)) {
                        two[1] = p;
                    }
                    String key = strip(topic);
                    Port[] ports = namers.computeIfAbsent(key, k -> new Port[2]);
                    int[] in = namerGroups.computeIfAbsent(key, k -> new int[] { -1, -1 });
                    if (in[0] == -1) {
                        in[0] = g;
                        ports[0] = p;
                    } else if (in[0] != g && in[1] == -1) {
                        in[1] = g;
                        ports[1] = p;
                    }
                }
                distinct.add(two);
                Port owner = two[0] != null || ids == null ? null : firstOutput != null ? firstOutput : groups.get(g).get(0);
                String topic = two[0] != null ? named(two[0]) : owner == null ? null : ids.defaultTopic(owner);
                topics.add(topic);
                defaulted.add(owner);
                if (owner != null) {
                    defaults.putIfAbsent(strip(topic), g);
                }
            }
        }

        /** The topic of a port of this table's architecture in the generated code: its group's named topic, else a default one. */
        public String topic(Port port) {
            Integer g = groupOf.get(port);
            return g == null ? null : topics.get(g);
        }

        /** As {@link RsamlTopics#problem}, for a port of this table's architecture. */
        public String problem(Port port) {
            String topic = named(port);
            if (topic == null) {
                return defaultProblem(port);
            }
            if (!isValid(topic)) {
                return "names the topic '" + topic + "', which is not a ROS 2 topic name";
            }
            String tooLong = tooLong(topic);
            if (tooLong != null) {
                return "names the topic '" + topic + "', " + tooLong + ": shorten it";
            }
            String own = ROS2_TOPICS.get(strip(topic));
            if (own != null) {
                return "names the topic '" + topic + "', which ROS 2 itself uses (" + own + "): choose another name";
            }
            Module managed = transitionEvents.get(strip(topic));
            if (managed != null) {
                return "names the topic '" + topic + "', on which ROS 2 publishes the transitions of the managed node of module '"
                        + RsamlLabels.name(managed) + "' (lifecycle_msgs/msg/TransitionEvent): choose another name";
            }
            Integer g = groupOf.get(port);
            if (g == null) {
                return null;
            }
            for (Port p : distinct.get(g)) {
                if (p != null && p != port && !same(named(p), topic)) {
                    return "names the topic '" + topic + "', but " + describe(p) + ", connected to it, names '" + named(p)
                            + "': connected ports share one topic";
                }
            }
            String key = strip(topic);
            int[] in = namerGroups.get(key);
            for (int i = 0; i < 2; i++) {
                if (in[i] != -1 && in[i] != g) {
                    Port p = namers.get(key)[i];
                    return "names the topic '" + topic + "', as " + describe(p) + " does, which it is not connected to:"
                            + " ROS 2 would connect them";
                }
            }
            Integer other = defaults.get(key);
            if (other != null && other.intValue() != g.intValue()) {
                Port p = defaulted.get(other);
                return "names the topic '" + topic + "', which is the default topic of " + describe(p) + " (" + topics.get(other)
                        + "), which it is not connected to: ROS 2 would connect them; name another topic, or connect the ports";
            }
            return null;
        }

        /**
         * The problem of the default topic of a port that names none ({@code <layer>/<node>/<port>}): when
         * it is its group's topic (no connected port names one) and longer than ROS 2 takes, said on the
         * port whose default it is only. Null otherwise.
         */
        private String defaultProblem(Port port) {
            Integer g = groupOf.get(port);
            if (g == null || defaulted.get(g) != port) {
                return null;
            }
            String tooLong = tooLong(topics.get(g));
            return tooLong == null ? null : "names no topic, and its default topic '" + topics.get(g) + "' (<layer>/<node>/<port>), "
                    + tooLong + ": name a shorter topic (topic) or shorten the layer's, module's or port's name";
        }
    }

    /** Why the topic's full name (with its leading slash) is longer than ROS 2 takes; null when it is not. */
    private static String tooLong(String topic) {
        String full = "/" + strip(topic);
        return full.length() <= MAX_FULL_NAME ? null : "whose full name " + full.substring(0, 20) + "... has " + full.length()
                + " characters, more than the " + MAX_FULL_NAME + " ROS 2 takes (RMW_TOPIC_MAX_NAME_LENGTH)";
    }

    /** Whether two names are one topic where the nodes run in the root namespace (the default). */
    private static boolean same(String a, String b) {
        return strip(a).equals(strip(b));
    }

    private static String strip(String topic) {
        return topic.startsWith("/") ? topic.substring(1) : topic;
    }

    private static String describe(Port p) {
        return (p instanceof EntryPort ? "entry port '" : "output port '") + RsamlLabels.name(p) + "'"
                + (p.getModule() == null ? "" : " of module '" + RsamlLabels.name(p.getModule()) + "'");
    }
}
