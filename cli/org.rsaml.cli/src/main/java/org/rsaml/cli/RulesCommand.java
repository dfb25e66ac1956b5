/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;

import org.rsaml.report.ExitCodes;
import org.rsaml.report.RuleList;
import org.rsaml.validation.Rules;

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
            try {
                RuleList.json(Rules.all(), out);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        } else {
            RuleList.text(Rules.all(), verbose, out);
        }
        out.flush();
        return ExitCodes.OK;
    }
}
