/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

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
 */
public record Rule(String id, String name, Severity severity, String source, String context, String description,
        String scope, String message, String remediation) {

    /** What to change to satisfy the rule, under the name SARIF gives it. */
    public String help() {
        return remediation;
    }
}
