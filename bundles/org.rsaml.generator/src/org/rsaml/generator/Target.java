/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator;

import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

/** What {@link RsamlGenerator} produces from an architecture. */
public enum Target {
    /** A CMake C++17 project that builds and runs on its own (threads, timers, a trace of the run). */
    CPP("cpp"),
    /** ament_cmake packages for ROS 2 (rclcpp): a node per module, topics, a launch file. */
    ROS2("ros2");

    private final String id;

    Target(String id) {
        this.id = id;
    }

    /** The name users type: {@code cpp} or {@code ros2}. */
    public String id() {
        return id;
    }

    /**
     * The target named {@code name} (case and surrounding blanks ignored).
     *
     * @throws IllegalArgumentException naming the targets there are
     */
    public static Target parse(String name) {
        String wanted = name == null ? "" : name.strip().toLowerCase(Locale.ROOT);
        for (Target t : values()) {
            if (t.id.equals(wanted)) {
                return t;
            }
        }
        throw new IllegalArgumentException("unknown target '" + name + "'; the targets are "
                + Arrays.stream(values()).map(Target::id).collect(Collectors.joining(", ")));
    }

    @Override
    public String toString() {
        return id;
    }
}
