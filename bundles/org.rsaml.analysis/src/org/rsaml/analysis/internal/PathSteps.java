/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

/**
 * The steps a latency requirement's path search takes before it stops ({@link PathSearch}): 1,000,000, or
 * another limit for one analysis on the calling thread, so that tests can compare the search in full with
 * the longest-path computation that takes over past the limit ({@link LongestPaths}).
 */
public final class PathSteps {

    /** Steps of the walk per requirement before it stops (said so, never a silent pass). */
    public static final int DEFAULT = 1_000_000;

    private static final ThreadLocal<Integer> LIMIT = ThreadLocal.withInitial(() -> DEFAULT);

    private PathSteps() {
    }

    /** An analysis run with a limit, as {@code () -> TimingAnalysis.analyse(architecture)}. */
    @FunctionalInterface
    public interface Analysis<T, E extends Exception> {
        T run() throws E;
    }

    /** The limit on this thread. */
    static int limit() {
        return LIMIT.get();
    }

    /** Runs {@code analysis} on this thread with the walk stopping after {@code steps} steps (0: at once). */
    public static <T, E extends Exception> T withLimit(int steps, Analysis<T, E> analysis) throws E {
        if (steps < 0) {
            throw new IllegalArgumentException("a step limit is zero or more, not " + steps);
        }
        int before = LIMIT.get();
        LIMIT.set(steps);
        try {
            return analysis.run();
        } finally {
            LIMIT.set(before);
        }
    }
}
