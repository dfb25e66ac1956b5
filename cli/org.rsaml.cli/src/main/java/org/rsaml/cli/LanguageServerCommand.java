/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.FileDescriptor;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.PrintStream;
import java.util.concurrent.Callable;

import org.rsaml.report.ExitCodes;
import org.rsaml.text.ide.server.RsamlLanguageServer;

import picocli.CommandLine.Command;

/** {@code rsaml language-server}: the language server of textual models, on standard input and output. */
@Command(name = "language-server", mixinStandardHelpOptions = true,
        description = "Runs the language server of textual models (.rsa) on standard input and output (LSP), for editors such as VS Code.")
final class LanguageServerCommand implements Callable<Integer> {

    @Override
    public Integer call() throws InterruptedException {
        // Standard output carries the protocol only: whatever else prints goes to standard error.
        PrintStream protocol = new PrintStream(new FileOutputStream(FileDescriptor.out), true);
        System.setOut(System.err);
        RsamlLanguageServer.serve(new FileInputStream(FileDescriptor.in), protocol);
        return ExitCodes.OK;
    }
}
