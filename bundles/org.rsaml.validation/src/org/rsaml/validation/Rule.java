/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

/**
 * One RsaML rule: a stable id used in messages, reports and docs, a severity, and the text that
 * tells a user what the rule asks and how to satisfy it.
 *
 * @param id          stable identifier, e.g. {@code RSA-08}
 * @param name        short name, e.g. {@code layer-execution-budget}
 * @param severity    how serious a violation is
 * @param source      where the rule comes from ({@code paper} for the eight semantic rules)
 * @param description one sentence: what the rule requires
 * @param help        what to change to satisfy it
 */
public record Rule(String id, String name, Severity severity, String source, String description, String help) {
}
