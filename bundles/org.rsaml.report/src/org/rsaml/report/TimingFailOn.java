/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

import org.rsaml.analysis.Verdict;
import org.rsaml.validation.Severity;

/**
 * Which timing verdicts fail a run of {@code rsaml analyze} (exit code 1) and of the Maven
 * {@code analyze} goal (a failed build): the one place that decides it for both. By default only a
 * deadline or a latency requirement that can be missed fails; {@link #NOT_ANALYSED} also fails a
 * model whose timing is not proven (some task, processor or requirement <em>not analysed</em>),
 * so that a script can tell a proven model from one the analysis could not decide.
 */
public enum TimingFailOn {
    /** A possible miss fails (the default). */
    MISS("miss"),
    /** A possible miss, or anything not analysed, fails: only a proven model passes. */
    NOT_ANALYSED("not-analysed"),
    /** Verdicts never fail (reports and logs only). */
    NEVER("never");

    private final String label;

    TimingFailOn(String label) {
        this.label = label;
    }

    /** As written on the command line and in the goal's configuration. */
    public String label() {
        return label;
    }

    /**
     * The level written as {@code miss}, {@code not-analysed} or {@code never} (any case, surrounding blanks ignored).
     *
     * @throws IllegalArgumentException naming the value and the levels there are, as {@link FindingFailOn#parse} does
     */
    public static TimingFailOn parse(String text) {
        String t = text == null ? "" : text.strip().toLowerCase(Locale.ROOT);
        return Arrays.stream(values()).filter(v -> v.label.equals(t)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("'" + text + "' is not a level; it is one of "
                        + Arrays.stream(values()).map(TimingFailOn::label).collect(Collectors.joining(", "))));
    }

    /** Whether a model whose architecture has this overall verdict fails the run. */
    public boolean fails(Verdict verdict) {
        return switch (this) {
            case MISS -> verdict == Verdict.MISSES;
            case NOT_ANALYSED -> verdict != Verdict.MEETS;
            case NEVER -> false;
        };
    }

    /**
     * The lowest severity of the timing rules' findings (RSA-22 to RSA-25) that fails the run in the
     * SARIF and JUnit reports: the errors are the misses, RSA-24 (not analysed) is a warning.
     */
    public Severity findingThreshold() {
        return switch (this) {
            case MISS -> Severity.ERROR;
            case NOT_ANALYSED -> Severity.WARNING;
            case NEVER -> null;
        };
    }

    @Override
    public String toString() {
        return label;
    }
}
