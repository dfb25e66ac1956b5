/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;

import org.rsaml.report.ExitCodes;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

import com.google.gson.stream.JsonWriter;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code rsaml rules}: the rules RsaML checks, from the rule catalogue: id, severity, description, scope, fix. */
@Command(name = "rules", mixinStandardHelpOptions = true, description = "Lists the rules RsaML checks.")
final class RulesCommand implements java.util.concurrent.Callable<Integer> {

    enum Format { text, json }

    @Option(names = { "-f", "--format" }, defaultValue = "text", description = "text or json (default: ${DEFAULT-VALUE}).")
    Format format;

    @Option(names = "--verbose", description = "Also print each rule's exact scope and what to change to satisfy it.")
    boolean verbose;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        if (format == Format.json) {
            json(out);
        } else {
            for (Rule rule : Rules.all()) {
                out.printf("%-7s %-8s %-29s %s%n", rule.id(), rule.severity().label(), rule.name(), rule.description());
                if (verbose) {
                    out.printf("%-46s scope: %s%n", "", rule.scope());
                    out.printf("%-46s fix: %s%n", "", rule.remediation());
                }
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    private static void json(PrintWriter out) {
        try {
            JsonWriter json = new JsonWriter(out);
            json.setIndent("  ");
            json.setHtmlSafe(false);
            json.beginArray();
            for (Rule rule : Rules.all()) {
                json.beginObject().name("id").value(rule.id()).name("name").value(rule.name())
                        .name("severity").value(rule.severity().label()).name("source").value(rule.source())
                        .name("context").value(rule.context()).name("description").value(rule.description())
                        .name("scope").value(rule.scope()).name("help").value(rule.remediation()).endObject();
            }
            json.endArray();
            json.flush();
            out.println();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
