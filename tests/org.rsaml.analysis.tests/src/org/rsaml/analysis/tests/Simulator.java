/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import java.util.ArrayList;
import java.util.List;

import org.rsaml.analysis.Task;

/**
 * A discrete-event simulation of synchronous periodic tasks on one processor, written apart from the
 * analysis (it shares only the Task record): it plays every job released in [0, horizon) and records
 * each one's response time. Jobs of tasks in one lock group exclude each other: a job takes the
 * group's lock when it first runs and keeps it, preempted or not, until it completes; a job waiting
 * for the lock does not run, whatever its priority (no priority inheritance). With utilisation at most 1 and every task released at 0, the schedule
 * repeats after the hyperperiod, so one hyperperiod shows every response time there is.
 */
final class Simulator {

    enum Mode { FIXED_PRIORITY, NON_PREEMPTIVE, EDF }

    private Simulator() {
    }

    private static final class Job {
        final int task;
        final long release;
        final long deadline;
        long left;

        Job(int task, long release, long deadline, long left) {
            this.task = task;
            this.release = release;
            this.deadline = deadline;
            this.left = left;
        }
    }

    /** Worst response time per task over the jobs released in [0, horizon); all of them run to the end. */
    static long[] worstResponses(List<Task> tasks, Mode mode, long horizon) {
        int n = tasks.size();
        long[] worst = new long[n];
        List<Job> pending = new ArrayList<>();
        long[] next = new long[n];
        long now = 0;
        Job current = null;
        // per lock group, the job that holds its lock (it took it when it first ran, until it completes)
        java.util.Map<String, Job> holders = new java.util.HashMap<>();
        while (true) {
            for (int i = 0; i < n; i++) {
                while (next[i] <= now && next[i] < horizon) {
                    pending.add(new Job(i, next[i], next[i] + tasks.get(i).deadline(), tasks.get(i).cost()));
                    next[i] += tasks.get(i).period();
                }
            }
            long release = Long.MAX_VALUE;
            for (int i = 0; i < n; i++) {
                if (next[i] < horizon) {
                    release = Math.min(release, next[i]);
                }
            }
            if (mode != Mode.NON_PREEMPTIVE || current == null || current.left == 0) {
                current = pick(pending, tasks, mode, holders);
            }
            if (current == null) {
                if (release == Long.MAX_VALUE) {
                    return worst;
                }
                now = release;
                continue;
            }
            String group = tasks.get(current.task).group();
            if (group != null) {
                holders.put(group, current);
            }
            long until = mode == Mode.NON_PREEMPTIVE ? now + current.left : Math.min(now + current.left, release);
            current.left -= until - now;
            now = until;
            if (current.left == 0) {
                pending.remove(current);
                if (group != null) {
                    holders.remove(group);
                }
                worst[current.task] = Math.max(worst[current.task], now - current.release);
            }
        }
    }

    private static Job pick(List<Job> pending, List<Task> tasks, Mode mode, java.util.Map<String, Job> holders) {
        Job best = null;
        for (Job j : pending) {
            if (j.left == 0) {
                continue;
            }
            String group = tasks.get(j.task).group();
            Job holder = group == null ? null : holders.get(group);
            if (holder != null && holder != j) {
                continue; // waits for the lock (no priority inheritance)
            }
            if (best == null || before(j, best, tasks, mode)) {
                best = j;
            }
        }
        // zero-cost jobs complete at once
        for (Job j : new ArrayList<>(pending)) {
            if (j.left == 0 && j != best) {
                pending.remove(j);
            }
        }
        return best;
    }

    private static boolean before(Job a, Job b, List<Task> tasks, Mode mode) {
        if (mode == Mode.EDF) {
            if (a.deadline != b.deadline) {
                return a.deadline < b.deadline;
            }
        } else {
            int pa = tasks.get(a.task).priority();
            int pb = tasks.get(b.task).priority();
            if (pa != pb) {
                return pa > pb;
            }
        }
        if (a.release != b.release) {
            return a.release < b.release;
        }
        return a.task < b.task;
    }

    static long hyperperiod(List<Task> tasks) {
        long h = 1;
        for (Task t : tasks) {
            h = h / gcd(h, t.period()) * t.period();
        }
        return h;
    }

    private static long gcd(long a, long b) {
        return b == 0 ? a : gcd(b, a % b);
    }
}
