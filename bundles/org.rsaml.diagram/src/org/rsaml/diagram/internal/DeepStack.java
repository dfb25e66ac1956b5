/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.util.concurrent.Callable;

/**
 * Runs work whose recursion grows with the model (ELK's layered layout recurses along chains of nodes: its
 * Brandes-Köpf placement about once per module of a chain) on a thread of its own with a stack sized for the
 * model, so that a long legal chain is drawn instead of overflowing the caller's stack (a JVM's main thread has
 * 1 MiB unless {@code -Xss} says otherwise). The stack is only reserved address space until the recursion reaches it.
 */
public final class DeepStack {

    /** A thread's stack, in bytes, is never smaller than this (16 times a JVM's default). */
    static final long MINIMUM = 16L << 20;

    /**
     * Stack per element of the model, in bytes. Measured with ELK 0.12 on Temurin 25: a chain of 1,500 modules
     * (6,000 elements: modules, ports, connections) overflows a 1 MiB stack and is laid out with 2 MiB, a chain of
     * 20,000 (80,000 elements) overflows 12 MiB and is laid out with 24 MiB: 150 to 300 bytes per element; this is
     * three times the most, for other shapes and other JVMs.
     */
    static final long PER_ELEMENT = 1L << 10;

    /** No more than this is asked for, whatever the model (a chain of about 250,000 modules). */
    static final long MAXIMUM = 1L << 30;

    /** Overrides the stack, in MiB, for a model the sizing gets wrong ({@code -Drsaml.diagram.stackMiB=4096}). */
    public static final String PROPERTY = "rsaml.diagram.stackMiB";

    private DeepStack() {
    }

    /** The stack, in bytes, that work on a model of {@code elements} elements is given. */
    public static long bytesFor(long elements) {
        Long asked = Long.getLong(PROPERTY);
        if (asked != null && asked > 0) {
            return asked << 20;
        }
        return Math.min(MAXIMUM, Math.max(MINIMUM, elements * PER_ELEMENT));
    }

    /**
     * The result of {@code work} run on a thread with a stack of {@code stackBytes}; what it throws is thrown here
     * as it was thrown (a {@link StackOverflowError} too, for the caller to say which model was too deep).
     */
    public static <T> T call(String name, long stackBytes, Callable<T> work) {
        Object[] result = new Object[1];
        Throwable[] thrown = new Throwable[1];
        Thread thread = new Thread(null, () -> {
            try {
                result[0] = work.call();
            } catch (Throwable t) { // handed to the caller's thread, which rethrows it
                thrown[0] = t;
            }
        }, name, stackBytes);
        thread.setDaemon(true);
        thread.start();
        boolean interrupted = false;
        while (true) {
            try {
                thread.join();
                break;
            } catch (InterruptedException e) {
                // The work cannot be stopped halfway; finish it and keep the caller's interrupt.
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (thrown[0] instanceof RuntimeException e) {
            throw e;
        }
        if (thrown[0] instanceof Error e) {
            throw e;
        }
        if (thrown[0] != null) {
            throw new IllegalStateException(thrown[0]);
        }
        @SuppressWarnings("unchecked")
        T value = (T) result[0];
        return value;
    }
}
