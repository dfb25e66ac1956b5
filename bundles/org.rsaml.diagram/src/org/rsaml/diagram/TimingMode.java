/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

import java.util.Locale;

import org.rsaml.model.Architecture;
import org.rsaml.model.support.Choices;

/** Whether the architecture view draws the timing analysis over the architecture. */
public enum TimingMode {
    /** Drawn when the model asks a timing question: it deploys modules on processors or states latency requirements. */
    AUTO,
    /** Always drawn (every module then runs on the {@code default} processor unless deployed). */
    ON,
    /** Never drawn. */
    OFF;

    /** The name used on the command line and in the Maven goal: {@code auto}, {@code on}, {@code off}. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** Whether the timing is drawn for this architecture. */
    public boolean appliesTo(Architecture architecture) {
        return switch (this) {
            case ON -> true;
            case OFF -> false;
            case AUTO -> !architecture.getProcessors().isEmpty() || !architecture.getLatencyRequirements().isEmpty();
        };
    }

    /** @throws IllegalArgumentException naming the accepted values */
    public static TimingMode parse(String value) {
        return Choices.parse(values(), TimingMode::id, "timing mode", value);
    }
}
