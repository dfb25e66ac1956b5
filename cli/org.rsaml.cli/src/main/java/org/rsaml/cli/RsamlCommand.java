/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;

import picocli.CommandLine.Model.CommandSpec;

/**
 * What every subcommand of {@code rsaml} is given: the tool (working directory, --debug), its model (the options it
 * declares in its constructor, {@link CommandSpecs}) and its own streams.
 */
abstract class RsamlCommand implements Callable<Integer> {

    final RsamlCli parent;

    final CommandSpec spec;

    RsamlCommand(RsamlCli parent, String name, String... description) {
        this.parent = parent;
        this.spec = CommandSpecs.command(name, this, description);
        // -V prints the tool's version from every command.
        spec.versionProvider(parent.spec.versionProvider());
    }

    /** Standard output, as the embedding caller set it. */
    PrintWriter out() {
        return spec.commandLine().getOut();
    }

    /** Standard error, as the embedding caller set it. */
    PrintWriter err() {
        return spec.commandLine().getErr();
    }
}
