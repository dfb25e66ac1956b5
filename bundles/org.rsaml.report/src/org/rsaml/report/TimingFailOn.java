/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import org.rsaml.analysis.Verdict;
import org.rsaml.model.support.Choices;
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
        return Choices.parse(values(), TimingFailOn::label, "level", text);
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
     * How seriously a front end shows a model's verdict under this level (the level a build log gives its lines): an
     * error when it fails the run, a warning when it falls short of "meets" without failing it, else information.
     */
    public Severity shown(Verdict verdict) {
        return fails(verdict) ? Severity.ERROR : verdict != Verdict.MEETS ? Severity.WARNING : Severity.INFO;
    }

    /**
     * The lowest severity of the timing rules' findings ({@code Rules.timing()}) that fails the run in the
     * SARIF and JUnit reports: the errors are the misses, "not analysed" is a warning.
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
