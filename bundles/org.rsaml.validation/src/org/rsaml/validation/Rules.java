/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.rsaml.validation.internal.RuleCatalog;

/**
 * The catalogue of RsaML rules, read from {@code rules/rules.properties} of this bundle. RSA-01 to
 * RSA-08 are the paper's eight semantic rules; the others are the checks an architect expects next to
 * them. The catalogue binds each rule to what implements it: OCL invariants of {@code rsaml.ecore}
 * (its {@code constraints} key), results of the timing analysis (its {@code verdicts} key), or EMF's
 * structural checks (source {@code EMF}); no code names a rule by its id.
 */
public final class Rules {

    private static final Map<String, Rule> BY_ID = new LinkedHashMap<>();
    private static final Map<String, Rule> BY_CONSTRAINT = new HashMap<>();
    private static final Map<String, Rule> BY_VERDICT = new HashMap<>();

    static {
        for (Rule rule : RuleCatalog.load()) {
            BY_ID.put(rule.id(), rule);
            for (String constraint : rule.constraints()) {
                BY_CONSTRAINT.put(constraint, rule);
            }
            for (String verdict : rule.verdicts()) {
                BY_VERDICT.put(verdict, rule);
            }
        }
    }

    /** RSA-00: EMF's structural checks, and models that cannot be read (the catalogue's rule of source {@code EMF}). */
    public static final Rule STRUCTURE = RuleCatalog.structure(BY_ID.values());

    private Rules() {
    }

    /** All rules, in id order. */
    public static List<Rule> all() {
        return List.copyOf(BY_ID.values());
    }

    /** The rules of the timing analysis (source {@code timing analysis}: RSA-22 to RSA-25), in id order. */
    public static List<Rule> timing() {
        return BY_ID.values().stream().filter(Rule::isTiming).toList();
    }

    public static Optional<Rule> byId(String id) {
        return Optional.ofNullable(BY_ID.get(id));
    }

    /** The rule an OCL constraint of rsaml.ecore implements, as the catalogue's {@code constraints} key binds it. */
    public static Optional<Rule> forConstraint(String constraintName) {
        return constraintName == null ? Optional.empty() : Optional.ofNullable(BY_CONSTRAINT.get(constraintName));
    }

    /** The rule of the timing analysis that reports a verdict, as the catalogue's {@code verdicts} key binds it. */
    public static Optional<Rule> forVerdict(String verdict) {
        return verdict == null ? Optional.empty() : Optional.ofNullable(BY_VERDICT.get(verdict));
    }

    /** The rules whose errors leave an architecture without a task set (the catalogue's {@code timingPrerequisite}). */
    public static List<Rule> timingPrerequisites() {
        return BY_ID.values().stream().filter(Rule::timingPrerequisite).toList();
    }
}
