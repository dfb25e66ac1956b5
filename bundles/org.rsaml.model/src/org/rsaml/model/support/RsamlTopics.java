/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;

import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
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
     * or null: it is not a valid ROS 2 name, a port connected to it names another topic, or a port
     * it is not connected to names the same topic.
     */
    public static String problem(Port port) {
        String topic = named(port);
        if (topic == null) {
            return null;
        }
        if (!isValid(topic)) {
            return "names the topic '" + topic + "', which is not a ROS 2 topic name";
        }
        List<Port> group = connected(port);
        for (Port p : group) {
            String other = named(p);
            if (p != port && other != null && !same(other, topic)) {
                return "names the topic '" + topic + "', but " + describe(p) + ", connected to it, names '" + other
                        + "': connected ports share one topic";
            }
        }
        Architecture architecture = port.getModule() == null || port.getModule().getLayer() == null ? null
                : port.getModule().getLayer().getArchitecture();
        if (architecture != null) {
            for (Layer l : architecture.getLayers()) {
                for (Module m : l.getModules()) {
                    for (Port p : m.getPorts()) {
                        String other = named(p);
                        if (other != null && !group.contains(p) && same(other, topic)) {
                            return "names the topic '" + topic + "', as " + describe(p) + " does, which it is not connected to:"
                                    + " ROS 2 would connect them";
                        }
                    }
                }
            }
        }
        return null;
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
