/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.io.InterruptedIOException;
import java.util.concurrent.CancellationException;

/**
 * Where a long step of a command (reading a model, validating it, writing what it produces) ends when the thread running
 * it has been interrupted: the resident process ({@code RSAML_DAEMON=1}) interrupts a command whose client went away, so
 * that it stops at once and writes nothing more, as a JVM of its own stops on Ctrl-C. A thread that is not interrupted
 * passes through unchanged: a command in a JVM of its own is never interrupted.
 */
public final class Interruptions {

    private Interruptions() {
    }

    /** Ends the step in progress when its thread has been interrupted (the interrupt stays set for the next check). */
    public static void check() {
        if (Thread.currentThread().isInterrupted()) {
            throw new CancellationException("the command was stopped");
        }
    }

    /** As {@link #check()}, for a step that writes files: no file is written or replaced once its thread is interrupted. */
    public static void checkWrite() throws InterruptedIOException {
        if (Thread.currentThread().isInterrupted()) {
            throw new InterruptedIOException("the command was stopped");
        }
    }
}
