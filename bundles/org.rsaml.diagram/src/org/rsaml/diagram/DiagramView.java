/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

import java.util.Locale;

import org.rsaml.model.support.Choices;

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
        return Choices.parse(values(), DiagramView::id, "view", value);
    }
}
