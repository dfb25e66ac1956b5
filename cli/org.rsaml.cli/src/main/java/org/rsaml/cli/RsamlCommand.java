/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** What every subcommand of {@code rsaml} is given: the tool (working directory, --debug) and its own streams. */
abstract class RsamlCommand implements Callable<Integer> {

    @ParentCommand
    RsamlCli parent;

    @Spec
    CommandSpec spec;

    /** Standard output, as the embedding caller set it. */
    PrintWriter out() {
        return spec.commandLine().getOut();
    }

    /** Standard error, as the embedding caller set it. */
    PrintWriter err() {
        return spec.commandLine().getErr();
    }
}
