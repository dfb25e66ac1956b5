/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.io.PrintStream;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * What the language server tells the person running it, on standard error (standard output carries the
 * protocol): one line per problem, {@code rsaml language-server: ...}, never a stack trace. LSP4J reports a
 * failed request through {@code java.util.logging} with the exception's trace; here its message is the line.
 */
final class ServerLog {

    static final String PREFIX = "rsaml language-server: ";

    private static volatile PrintStream err = System.err;

    /** Held here: java.util.logging keeps loggers only weakly, and a collected one would forget this setup. */
    private static final Logger LSP4J = Logger.getLogger("org.eclipse.lsp4j");

    private ServerLog() {
    }

    static void problem(String message) {
        err.println(PREFIX + message);
    }

    /** Routes LSP4J's log records through {@link #problem}, each as one line. */
    static void install(PrintStream stderr) {
        err = stderr;
        Logger lsp4j = LSP4J;
        for (Handler h : lsp4j.getHandlers()) {
            lsp4j.removeHandler(h);
        }
        lsp4j.setUseParentHandlers(false);
        lsp4j.setLevel(Level.WARNING);
        lsp4j.addHandler(new Handler() {
            @Override
            public void publish(LogRecord record) {
                if (isLoggable(record)) {
                    problem(lineOf(record));
                }
            }

            @Override
            public void flush() {
                err.flush();
            }

            @Override
            public void close() {
            }
        });
    }

    private static String lineOf(LogRecord record) {
        Throwable cause = record.getThrown();
        while (cause != null && cause.getCause() != null && cause.getCause() != cause) {
            cause = cause.getCause();
        }
        String message = record.getMessage() == null ? "" : record.getMessage();
        if (cause != null && cause.getMessage() != null && !message.contains(cause.getMessage())) {
            message = message + ": " + cause.getMessage();
        }
        return message.replace('\n', ' ');
    }
}
