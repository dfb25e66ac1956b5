/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.FileDescriptor;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.PrintStream;

import org.rsaml.text.ide.server.RsamlLanguageServer;

/** {@code rsaml language-server}: the language server of textual models, on standard input and output. */
final class LanguageServerCommand extends RsamlCommand {

    static final String NAME = "language-server";

    LanguageServerCommand(RsamlCli parent) {
        super(parent, NAME, "Runs the language server of textual models (.rsa) on standard input and output (LSP), for editors such as VS Code.");
        CommandSpecs.standardHelpOptions(spec);
    }

    @Override
    public Integer call() throws InterruptedException {
        // Standard output carries the protocol only: whatever else prints goes to standard error.
        PrintStream protocol = new PrintStream(new FileOutputStream(FileDescriptor.out), true);
        PrintStream stderr = System.err;
        System.setOut(stderr);
        return RsamlLanguageServer.serve(new FileInputStream(FileDescriptor.in), protocol, stderr);
    }
}
