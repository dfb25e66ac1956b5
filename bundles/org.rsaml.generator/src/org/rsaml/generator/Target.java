/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;

import org.rsaml.generator.internal.cpp.CppTarget;
import org.rsaml.generator.internal.ros2.Ros2Target;
import org.rsaml.generator.spi.TargetGenerator;

/**
 * What {@link RsamlGenerator} produces from an architecture: {@link #CPP}, {@link #ROS2}, or a
 * target added with {@link #register(TargetGenerator)}.
 */
public final class Target {

    private static final Pattern ID = Pattern.compile("[a-z][a-z0-9-]*");
    private static final Map<String, Target> REGISTRY = new LinkedHashMap<>();

    /** A CMake C++17 project that builds and runs on its own (threads, timers, a trace of the run). */
    public static final Target CPP = register(new CppTarget());
    /** ament_cmake packages for ROS 2 (rclcpp): a node per module, topics, a launch file. */
    public static final Target ROS2 = register(new Ros2Target());

    private final TargetGenerator generator;

    private Target(TargetGenerator generator) {
        this.generator = generator;
    }

    /**
     * Makes a target available by its id ({@link #parse(String)}, {@link #values()}).
     *
     * @throws IllegalArgumentException the id is malformed or already taken
     */
    public static synchronized Target register(TargetGenerator generator) {
        String id = generator.id();
        if (id == null || !ID.matcher(id).matches()) {
            throw new IllegalArgumentException("a target id is lower-case letters, digits and dashes, not '" + id + "'");
        }
        if (REGISTRY.containsKey(id)) {
            throw new IllegalArgumentException("target '" + id + "' is already registered");
        }
        Target t = new Target(generator);
        REGISTRY.put(id, t);
        return t;
    }

    /** Removes a target added with {@link #register(TargetGenerator)}; the built-in ones stay. */
    public static synchronized void unregister(Target target) {
        if (target != CPP && target != ROS2) {
            REGISTRY.remove(target.id(), target);
        }
    }

    /** Every available target, built-in ones first. */
    public static synchronized Target[] values() {
        return REGISTRY.values().toArray(new Target[0]);
    }

    /** The name users type: {@code cpp} or {@code ros2}. */
    public String id() {
        return generator.id();
    }

    /** One line saying what the target produces. */
    public String description() {
        return generator.description();
    }

    TargetGenerator generator() {
        return generator;
    }

    /**
     * The target named {@code name} (case and surrounding blanks ignored).
     *
     * @throws IllegalArgumentException naming the targets there are
     */
    public static synchronized Target parse(String name) {
        String wanted = name == null ? "" : name.strip().toLowerCase(Locale.ROOT);
        Target t = REGISTRY.get(wanted);
        if (t == null) {
            throw new IllegalArgumentException("unknown target '" + name + "'; the targets are " + String.join(", ", REGISTRY.keySet()));
        }
        return t;
    }

    @Override
    public String toString() {
        return id();
    }
}
