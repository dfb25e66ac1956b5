/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

/** What a diagram shows of an architecture. */
public enum DiagramView {
    /** Layers by level, modules with their ports, connections, inhibitors, suppressors, sensors, actuators. */
    ARCHITECTURE,
    /** Missions with their goals and plans, the supervisors that control the plans, the orders. */
    MISSION;

    /** The name used on the command line and in file names: {@code architecture}, {@code mission}. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @throws IllegalArgumentException naming the accepted values */
    public static DiagramView parse(String value) {
        for (DiagramView view : values()) {
            if (view.id().equalsIgnoreCase(value == null ? "" : value.trim())) {
                return view;
            }
        }
        throw new IllegalArgumentException("unknown view '" + value + "'; expected one of "
                + Arrays.stream(values()).map(DiagramView::id).collect(Collectors.joining(", ")));
    }
}
