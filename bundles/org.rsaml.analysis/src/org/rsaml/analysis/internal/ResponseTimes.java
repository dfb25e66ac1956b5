/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalLong;

import org.rsaml.analysis.Rational;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Verdict;

/**
 * What the fixed-priority response-time analyses share: their limits, which tasks delay which (the
 * priorities as analysed, lock groups included), the level's utilisation against 1, and the verdicts
 * they give without an iteration. The analyses themselves: {@link Preemptive} (one task, its busy
 * period), {@link PriorityLevels} (every task of a processor, highest priority first),
 * {@link NonPreemptive}, {@link FirstInFirstOut}; their witnesses: {@link MissWitnesses}.
 */
public final class ResponseTimes {

    /** A busy period with more jobs than this is not examined job by job (the verdict says so). */
    public static final long MAX_JOBS = 1_000_000;
    /** Iteration steps per task before giving up (said so). */
    static final long MAX_STEPS = 50_000_000;

    private ResponseTimes() {
    }

    /** Tasks that can delay {@code task}: every other task of higher or equal priority. */
    static List<Task> interfering(List<Task> tasks, Task task) {
        return interfering(tasks, task, task.priority());
    }

    /** Every task but {@code task} of priority {@code priority} or higher, in their order. */
    static List<Task> interfering(List<Task> tasks, Task task, int priority) {
        List<Task> hp = new ArrayList<>();
        for (Task t : tasks) {
            if (t != task && t.priority() >= priority) {
                hp.add(t);
            }
        }
        return hp;
    }

    /** Whether some task can wait for a lower-priority member of its lock group. */
    public static boolean anyBlockedByLock(List<Task> tasks) {
        Map<String, Integer> lowest = lowestOfGroups(tasks);
        for (Task t : tasks) {
            if (t.group() != null && lowest.get(t.group()) < t.priority()) {
                return true;
            }
        }
        return false;
    }

    private static Map<String, Integer> lowestOfGroups(List<Task> tasks) {
        Map<String, Integer> lowest = new HashMap<>();
        for (Task t : tasks) {
            if (t.group() != null) {
                lowest.merge(t.group(), t.priority(), Math::min);
            }
        }
        return lowest;
    }

    /**
     * The priority each task is analysed at, in order: the lowest priority of its lock group (a
     * lower-priority member holding the lock makes it wait, and whatever preempts that member delays
     * it too: no priority inheritance), else its own. One pass over the lock groups, not one per task.
     */
    public static int[] effectivePriorities(List<Task> tasks) {
        Map<String, Integer> lowest = lowestOfGroups(tasks);
        int[] effective = new int[tasks.size()];
        for (int i = 0; i < effective.length; i++) {
            Task t = tasks.get(i);
            effective[i] = t.group() == null ? t.priority() : Math.min(t.priority(), lowest.get(t.group()));
        }
        return effective;
    }

    /** {@link #effectivePriorities} of one task. */
    public static int effectivePriority(List<Task> tasks, Task task) {
        int p = task.priority();
        if (task.group() != null) {
            for (Task t : tasks) {
                if (task.group().equals(t.group())) {
                    p = Math.min(p, t.priority());
                }
            }
        }
        return p;
    }

    /**
     * The utilisation of the task and the others, compared with 1 (as compareTo does). In floating
     * point when clearly away from 1; exactly (fractions whose denominators can grow large) only near it.
     */
    static int utilisationVersusOne(Task task, List<Task> others) {
        double u = utilisation(task, others);
        if (u > 1 + 1e-9) {
            return 1;
        }
        if (u < 1 - 1e-9) {
            return -1;
        }
        Rational exact = Rational.of(task.cost(), task.period());
        for (Task t : others) {
            exact = exact.plus(Rational.of(t.cost(), t.period()));
        }
        return exact.compareTo(Rational.ONE);
    }

    /** The utilisation of the task and the entries (period, cost) compared with 1, exactly near 1. */
    static int levelVersusOne(Task task, long[] period, long[] cost, int n) {
        double u = (double) task.cost() / task.period();
        for (int k = 0; k < n; k++) {
            u += (double) cost[k] / period[k];
        }
        if (u > 1 + 1e-9) {
            return 1;
        }
        if (u < 1 - 1e-9) {
            return -1;
        }
        Rational exact = Rational.of(task.cost(), task.period());
        for (int k = 0; k < n; k++) {
            exact = exact.plus(Rational.of(cost[k], period[k]));
        }
        return exact.compareTo(Rational.ONE);
    }

    static double utilisation(Task task, List<Task> others) {
        double u = (double) task.cost() / task.period();
        for (Task t : others) {
            u += (double) t.cost() / t.period();
        }
        return u;
    }

    /** The verdict of a task whose level (it and every task that can delay it) uses more than the processor. */
    static TaskResult overloaded(Task task, double levelUtilisation) {
        return new TaskResult(task, OptionalLong.empty(), Verdict.MISSES, "the tasks at or above its priority use "
                + String.format(Locale.ROOT, "%.4f", levelUtilisation)
                + " of the processor, more than all of it: its response time grows without bound", null);
    }

    static TaskResult notAnalysed(Task task, String why) {
        return new TaskResult(task, OptionalLong.empty(), Verdict.NOT_ANALYSED, "not analysed: " + why, null);
    }
}
