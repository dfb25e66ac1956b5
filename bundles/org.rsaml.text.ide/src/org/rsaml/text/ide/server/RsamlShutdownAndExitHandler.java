/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import org.eclipse.xtext.ide.server.ILanguageServerShutdownAndExitHandler;

/**
 * {@code shutdown} then {@code exit} ends the server with 0; {@code exit} without {@code shutdown}, or the
 * editor closing the connection first, with 1 (as the LSP specification asks), said on standard error.
 */
public class RsamlShutdownAndExitHandler implements ILanguageServerShutdownAndExitHandler {

    private volatile boolean shutDown;

    @Override
    public void shutdown() {
        shutDown = true;
    }

    boolean isShutDown() {
        return shutDown;
    }

    /** The exit code now, said on standard error when it is not 0 ({@code how} says how the session ended). */
    int exitCode(String how) {
        if (shutDown) {
            return 0;
        }
        ServerLog.problem(how + " without a shutdown request before it: exit code 1");
        return 1;
    }

    @Override
    public void exit() {
        System.exit(exitCode("exit notification"));
    }
}
