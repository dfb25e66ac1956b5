/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalLong;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.SchedulingPolicy;
import org.rsaml.analysis.Task;

/**
 * The preemptive fixed-priority analysis keeps its interference up to date as the window grows
 * (merged entries, a heap of the next job releases, windows carried from job to job and seeded from
 * the level above). Here it is compared with the textbook iteration, written out plainly (every
 * interfering task, the whole sum each step, each job's window restarted from its own cost plus the
 * others' first jobs), on random sets where that shortcut could go wrong: many distinct periods,
 * utilisation close to 1, release jitter, arbitrary deadlines and tied priorities. The response times
 * must be identical.
 */
class ResponseTimeIterationTest {

    private static final long SEED = 20261126L;

    @Test
    void responseTimesEqualTheTextbookIteration() {
        Random random = new Random(SEED);
        int compared = 0;
        int longBusyPeriods = 0;
        for (int set = 0; set < 400; set++) {
            List<Task> tasks = randomSet(random, set);
            ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks, Set.of());
            for (int i = 0; i < tasks.size(); i++) {
                Task t = tasks.get(i);
                long[] jobs = new long[1];
                OptionalLong expected = textbook(tasks, t, jobs);
                if (expected.isEmpty()) {
                    continue; // the level is overloaded or the iteration is too long for the plain version
                }
                OptionalLong actual = result.tasks().get(i).responseTime();
                int s = set;
                assertEquals(expected, actual, () -> "set " + s + ", task " + t + " among " + tasks);
                compared++;
                if (jobs[0] > 1) {
                    longBusyPeriods++;
                }
            }
        }
        assertTrue(compared > 3000, "response times compared: " + compared);
        assertTrue(longBusyPeriods > 100, "tasks whose busy period holds several of their jobs: " + longBusyPeriods);
    }

    /** Up to 40 tasks, distinct periods from 10 to 10,000, utilisation 0.5 to 0.999, some jitter, ties. */
    private static List<Task> randomSet(Random random, int set) {
        int n = 1 + random.nextInt(40);
        double target = 0.5 + 0.499 * random.nextDouble();
        List<Task> tasks = new ArrayList<>();
        double left = target;
        for (int i = 0; i < n; i++) {
            long period = 10 + random.nextInt(9_991);
            double share = i == n - 1 ? left : left * random.nextDouble() * 0.5;
            left -= share;
            long cost = Math.max(1, Math.min(period, (long) Math.floor(share * period)));
            long deadline = switch (random.nextInt(3)) {
                case 0 -> period;
                case 1 -> Math.max(cost, period / 2);
                default -> period * (2 + random.nextInt(3));
            };
            long jitter = random.nextInt(4) == 0 ? random.nextInt((int) Math.min(period, 500)) : 0;
            int priority = random.nextInt(set % 2 == 0 ? n : Math.max(1, n / 3)); // odd sets: many ties
            tasks.add(new Task("t" + i, period, deadline, cost, priority, jitter));
        }
        return tasks;
    }

    /** Joseph &amp; Pandya with Lehoczky's busy period and Tindell's jitter, as in a textbook; empty when it does not settle. */
    private static OptionalLong textbook(List<Task> tasks, Task task, long[] jobsExamined) {
        List<Task> hp = new ArrayList<>();
        double u = (double) task.cost() / task.period();
        for (Task t : tasks) {
            if (t != task && t.priority() >= task.priority()) {
                hp.add(t);
                u += (double) t.cost() / t.period();
            }
        }
        if (u > 1 - 1e-6) {
            return OptionalLong.empty();
        }
        long worst = -1;
        long steps = 0;
        for (long q = 0;; q++) {
            long w = (q + 1) * task.cost();
            for (Task t : hp) {
                w += t.cost();
            }
            while (true) {
                if (++steps > 2_000_000) {
                    return OptionalLong.empty();
                }
                long next = (q + 1) * task.cost();
                for (Task t : hp) {
                    long x = w + t.jitter();
                    next += (x / t.period() + (x % t.period() == 0 ? 0 : 1)) * t.cost();
                }
                if (next == w) {
                    break;
                }
                w = next;
            }
            worst = Math.max(worst, w - q * task.period() + task.jitter());
            if (w + task.jitter() <= (q + 1) * task.period()) {
                jobsExamined[0] = q + 1;
                return OptionalLong.of(worst);
            }
        }
    }
}
