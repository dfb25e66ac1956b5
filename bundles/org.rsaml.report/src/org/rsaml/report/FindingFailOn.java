/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import org.rsaml.model.support.Choices;
import org.rsaml.validation.Severity;

/**
 * Which findings fail a check ({@code rsaml validate --fail-on}, exit code 1; the validate goal's
 * {@code failOn}, a failed build): the one place that maps the level a user writes to the lowest
 * failing severity, for every front end.
 */
public enum FindingFailOn {
    /** Errors fail (the default). */
    ERROR("error", Severity.ERROR),
    /** Errors and warnings fail. */
    WARNING("warning", Severity.WARNING),
    /** Findings never fail (reports only). */
    NEVER("never", null);

    private final String label;
    private final Severity threshold;

    FindingFailOn(String label, Severity threshold) {
        this.label = label;
        this.threshold = threshold;
    }

    /** As written on the command line and in the goal's configuration. */
    public String label() {
        return label;
    }

    /** The lowest severity that fails, or {@code null} when findings never fail. */
    public Severity threshold() {
        return threshold;
    }

    /**
     * The level written as {@code error}, {@code warning} or {@code never} (any case, surrounding blanks ignored).
     *
     * @throws IllegalArgumentException naming the value and the levels there are
     */
    public static FindingFailOn parse(String text) {
        return Choices.parse(values(), FindingFailOn::label, "level", text);
    }

    @Override
    public String toString() {
        return label;
    }
}
