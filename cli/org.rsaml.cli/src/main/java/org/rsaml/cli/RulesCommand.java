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

import picocli.CommandLine.Model.OptionSpec;

/** {@code rsaml rules}: the rules RsaML checks, from the rule catalogue: id, severity, description, scope, fix. */
final class RulesCommand extends RsamlCommand {

    static final String NAME = "rules";

    enum Format { text, json }

    private final OptionSpec format = CommandSpecs.option(Format.class, "FORMAT", "-f", "--format").defaultValue("text")
            .description("text or json (default: ${DEFAULT-VALUE}).").build();

    private final OptionSpec verbose = CommandSpecs.flag("--verbose")
            .description("Also print each rule's exact scope and what to change to satisfy it.").build();

    RulesCommand(RsamlCli parent) {
        super(parent, NAME, "Lists the rules RsaML checks.");
        spec.addOption(format).addOption(verbose);
        CommandSpecs.standardHelpOptions(spec);
    }

    @Override
    public Integer call() {
        PrintWriter out = out();
        if (format.getValue() == Format.json) {
            try {
                RuleList.json(Rules.all(), out);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        } else {
            RuleList.text(Rules.all(), CommandSpecs.given(verbose), out);
        }
        out.flush();
        return ExitCodes.OK;
    }
}
