/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

import org.rsaml.validation.internal.RuleCatalog;
import org.rsaml.validation.internal.TimingChecks;

/**
 * The catalogue of RsaML rules, read from {@code model/rules.properties} of the model bundle. RSA-01
 * to RSA-08 are the paper's eight semantic rules; the others are the checks an architect expects next
 * to them. Every rule but RSA-00 is an OCL invariant in {@code rsaml.ecore}, named
 * {@code RSAnn_camelCaseName}.
 */
public final class Rules {

    private static final Map<String, Rule> BY_ID = new LinkedHashMap<>();
    private static final Map<String, Optional<Rule>> BY_CONSTRAINT = new ConcurrentHashMap<>();

    static {
        for (Rule rule : RuleCatalog.load()) {
            BY_ID.put(rule.id(), rule);
        }
    }

    /** RSA-00: EMF's structural checks, and models that cannot be read. */
    public static final Rule STRUCTURE = BY_ID.get("RSA-00");

    private Rules() {
    }

    /** All rules, in id order. */
    public static List<Rule> all() {
        return List.copyOf(BY_ID.values());
    }

    /** The rules of the timing analysis (RSA-22 to RSA-25), in id order. */
    public static List<Rule> timing() {
        return BY_ID.values().stream().filter(r -> TimingChecks.RULES.contains(r.id())).toList();
    }

    public static Optional<Rule> byId(String id) {
        return Optional.ofNullable(BY_ID.get(id));
    }

    /** The rule an OCL constraint of rsaml.ecore implements: {@code RSA08_layerExecutionBudget} is RSA-08. */
    public static Optional<Rule> forConstraint(String constraintName) {
        // Asked for every constraint on every element: looked up once per name.
        return constraintName == null ? Optional.empty() : BY_CONSTRAINT.computeIfAbsent(constraintName, Rules::ruleOfConstraint);
    }

    private static Optional<Rule> ruleOfConstraint(String constraintName) {
        if (constraintName.length() < 6 || !constraintName.startsWith("RSA")
                || !isDigit(constraintName.charAt(3)) || !isDigit(constraintName.charAt(4)) || constraintName.charAt(5) != '_') {
            return Optional.empty();
        }
        return byId("RSA-" + constraintName.substring(3, 5));
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }
}
