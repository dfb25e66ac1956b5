/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.util.List;

import org.rsaml.validation.Rule;

import com.google.gson.stream.JsonWriter;

/**
 * The rules RsaML checks, as {@code rsaml rules} lists them: a table of id, severity, name and description (with
 * each rule's scope and fix when verbose), or a JSON array of the catalogue's entries.
 */
public final class RuleList {

    private RuleList() {
    }

    /** One line a rule; {@code verbose} adds its scope and fix, each on a line of its own. */
    public static void text(List<Rule> rules, boolean verbose, PrintWriter out) {
        for (Rule rule : rules) {
            out.printf("%-7s %-8s %-29s %s%n", rule.id(), rule.severity().label(), rule.name(), rule.description());
            if (verbose) {
                out.printf("%-46s scope: %s%n", "", rule.scope());
                out.printf("%-46s fix: %s%n", "", rule.remediation());
            }
        }
    }

    /** A JSON array, one object a rule: id, name, severity, source, context, description, scope, help. */
    public static void json(List<Rule> rules, Writer out) throws IOException {
        JsonWriter json = new JsonWriter(out);
        json.setIndent("  ");
        json.setHtmlSafe(false);
        json.beginArray();
        for (Rule rule : rules) {
            json.beginObject().name("id").value(rule.id()).name("name").value(rule.name())
                    .name("severity").value(rule.severity().label()).name("source").value(rule.source())
                    .name("context").value(rule.context()).name("description").value(rule.description())
                    .name("scope").value(rule.scope()).name("help").value(rule.remediation()).endObject();
        }
        json.endArray();
        json.flush();
        out.write(System.lineSeparator());
    }
}
