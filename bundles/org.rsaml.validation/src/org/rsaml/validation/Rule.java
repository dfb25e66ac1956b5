/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.List;

/**
 * One RsaML rule, as the catalogue beside {@code rsaml.ecore} defines it: a stable id used in
 * messages, reports and docs, a severity, and the text that tells a user what the rule asks, what
 * it checks and how to satisfy it.
 *
 * @param id          stable identifier, e.g. {@code RSA-08}
 * @param name        short name, e.g. {@code layer-execution-budget}
 * @param severity    how serious a violation is
 * @param source      where the rule comes from ({@code paper} for the eight semantic rules)
 * @param context     the model classes the rule is checked on
 * @param description one sentence: what the rule requires
 * @param scope       exactly which elements are checked and which are not
 * @param message     the finding's message template, with {@code {parameter}}s
 * @param remediation what to change to satisfy it
 * @param constraints the invariants of rsaml.ecore that implement the rule, by constraint name (none for
 *                    EMF's structure and the timing analysis)
 * @param verdicts    for a rule of the timing analysis, the results of the analysis it reports, by the names
 *                    {@code org.rsaml.validation.internal.TimingChecks} gives them (none for the other rules)
 * @param timingPrerequisite whether an error of the rule leaves an architecture without a task set, so that
 *                    its timing is not analysed while the error stands
 */
public record Rule(String id, String name, Severity severity, String source, String context, String description,
        String scope, String message, String remediation, List<String> constraints, List<String> verdicts,
        boolean timingPrerequisite) {

    /** What {@code source} says of the rules the timing analysis decides (RSA-22 to RSA-25). */
    public static final String TIMING_ANALYSIS = "timing analysis";

    public Rule {
        constraints = List.copyOf(constraints);
        verdicts = List.copyOf(verdicts);
    }

    /** A rule implemented by no invariant and no verdict of the timing analysis. */
    public Rule(String id, String name, Severity severity, String source, String context, String description,
            String scope, String message, String remediation) {
        this(id, name, severity, source, context, description, scope, message, remediation, List.of(), List.of(), false);
    }

    /** Whether the timing analysis decides the rule rather than an invariant. */
    public boolean isTiming() {
        return TIMING_ANALYSIS.equals(source);
    }

    /**
     * A finding of this rule as every Eclipse channel shows it — the builder's and the editors' markers, the
     * diagrams' decorations, EMF's stock {@code Diagnostician} (Sirius's <i>Validate</i>): {@code "RSA-08: message"}.
     */
    public String text(String message) {
        return id + ": " + message;
    }

    /** What to change to satisfy the rule, under the name SARIF gives it. */
    public String help() {
        return remediation;
    }
}
