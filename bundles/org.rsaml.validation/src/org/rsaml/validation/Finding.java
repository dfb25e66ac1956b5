/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

/**
 * A problem found in a model, located so that a person or a tool can go straight to it.
 *
 * @param rule          the rule that is violated
 * @param severity      the severity of this finding (the rule's)
 * @param message       what is wrong, naming the elements and values involved (without the rule id)
 * @param qualifiedName the element's path by names, e.g. {@code robot/decision/proceduralExec/e0}
 * @param uriFragment   the element's URI fragment in its resource
 * @param file          the model file as the user named it, or the resource URI
 * @param line          1-based line of the element's start tag, or 0 when unknown
 * @param column        1-based column of the element's start tag, or 0 when unknown
 * @param detail        what the message summarises, in full (an RSA-23 finding's whole worst path,
 *                      where the message shows its ends only), or null when the message says it all;
 *                      the JSON and SARIF reports carry it
 */
public record Finding(Rule rule, Severity severity, String message, String qualifiedName, String uriFragment,
        String file, int line, int column, String detail) {

    /** A finding whose message says it all. */
    public Finding(Rule rule, Severity severity, String message, String qualifiedName, String uriFragment, String file, int line,
            int column) {
        this(rule, severity, message, qualifiedName, uriFragment, file, line, column, null);
    }

    public String ruleId() {
        return rule.id();
    }

    /** The finding as Eclipse shows it, {@code RSA-08: message} ({@link Rule#text}). */
    public String text() {
        return rule.text(message);
    }

    /** Compiler style: {@code file:line:column: error RSA-08: message}. */
    @Override
    public String toString() {
        return file + ":" + line + ":" + column + ": " + severity.label() + " " + rule.id() + ": " + message;
    }
}
