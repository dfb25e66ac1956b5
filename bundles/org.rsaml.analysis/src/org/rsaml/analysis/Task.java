/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

/**
 * A recurring task on one processor: released every {@code period} (for a sporadic task, its minimum
 * inter-arrival time), each job needing at most {@code cost} of processor time and due
 * {@code deadline} after its release. All times are integer nanoseconds. A larger {@code priority}
 * preempts a smaller one (as POSIX real-time priorities do); tasks of equal priority are assumed to
 * delay each other, whatever the order the platform picks between them. {@code jitter} is the
 * latest a release can come after its nominal instant (0 for a timer-driven release).
 *
 * @param name     shown in results and witnesses
 * @param period   T &gt; 0
 * @param deadline D &gt; 0, may be shorter or longer than the period
 * @param cost     C &ge; 0, the worst-case execution time
 * @param priority fixed priority under fixed-priority policies, ignored by EDF
 * @param jitter   J &ge; 0, release jitter
 * @param group    tasks of one group exclude each other through a lock without priority inheritance
 *                 (null: none); under preemptive fixed priorities each is analysed at the lowest
 *                 priority of its group, with every task at or above that priority delaying it
 */
public record Task(String name, long period, long deadline, long cost, int priority, long jitter, String group) {

    public Task {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("A task needs a name");
        }
        if (period <= 0) {
            throw new IllegalArgumentException("Task '" + name + "': the period must be positive, not " + period + " ns");
        }
        if (deadline <= 0) {
            throw new IllegalArgumentException("Task '" + name + "': the deadline must be positive, not " + deadline + " ns");
        }
        if (cost < 0) {
            throw new IllegalArgumentException("Task '" + name + "': the cost must not be negative, not " + cost + " ns");
        }
        if (jitter < 0) {
            throw new IllegalArgumentException("Task '" + name + "': the release jitter must not be negative, not " + jitter + " ns");
        }
    }

    /** A task that shares no lock. */
    public Task(String name, long period, long deadline, long cost, int priority, long jitter) {
        this(name, period, deadline, cost, priority, jitter, null);
    }

    /** A task without release jitter that shares no lock. */
    public Task(String name, long period, long deadline, long cost, int priority) {
        this(name, period, deadline, cost, priority, 0, null);
    }

    /** A task whose deadline is its period. */
    public static Task implicit(String name, long period, long cost, int priority) {
        return new Task(name, period, period, cost, priority, 0, null);
    }
}
