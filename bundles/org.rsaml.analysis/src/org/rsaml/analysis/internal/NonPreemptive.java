/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.List;

import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;

/**
 * Non-preemptive fixed priority: a job, once started, runs to completion, so a lower-priority job
 * started just before can block it (the revised analysis of Davis, Burns, Bril &amp; Lukkien 2007,
 * which examines every job of the level-i busy period, not only the first). Equal priorities are
 * served first-in first-out, which the analysis bounds by counting them as interfering (jobs released
 * until the job starts, not only before its release: sound, not exact; {@link FirstInFirstOut} is
 * exact where it applies).
 */
public final class NonPreemptive {

    private NonPreemptive() {
    }

    public static TaskResult of(List<Task> tasks, Task task) {
        List<Task> hp = ResponseTimes.interfering(tasks, task);
        Task found = null;
        for (Task t : tasks) {
            if (t.priority() < task.priority() && (found == null || t.cost() > found.cost())) {
                found = t;
            }
        }
        long blocking = found == null ? 0 : found.cost();
        Task blocker = blocking == 0 ? null : found;
        int level = ResponseTimes.utilisationVersusOne(task, hp);
        if (level > 0) {
            return ResponseTimes.overloaded(task, ResponseTimes.utilisation(task, hp));
        }
        if (level == 0 && blocking > 0) {
            return ResponseTimes.notAnalysed(task, "the tasks at or above its priority use all of the processor and a lower-priority job"
                    + " can block it, so its busy period need not end");
        }
        try {
            long steps = 0;
            // length of the level-i busy period, blocking included
            long length = blocking + task.cost();
            for (Task t : hp) {
                length = Arith.add(length, t.cost());
            }
            while (true) {
                if (++steps > ResponseTimes.MAX_STEPS) {
                    return ResponseTimes.notAnalysed(task, "the busy-period iteration did not settle within " + ResponseTimes.MAX_STEPS
                            + " steps");
                }
                long next = Arith.add(blocking,
                        Arith.mul(Arith.ceilDiv(Arith.add(length, task.jitter()), task.period()), task.cost()));
                for (Task t : hp) {
                    next = Arith.add(next, Arith.mul(Arith.ceilDiv(Arith.add(length, t.jitter()), t.period()), t.cost()));
                }
                if (next == length) {
                    break;
                }
                length = next;
            }
            long jobs = Math.max(1, Arith.ceilDiv(Arith.add(length, task.jitter()), task.period()));
            if (jobs > ResponseTimes.MAX_JOBS) {
                return ResponseTimes.notAnalysed(task, "its busy period holds more than " + ResponseTimes.MAX_JOBS + " of its jobs");
            }
            long worst = -1;
            long worstJob = 0;
            for (long q = 0; q < jobs; q++) {
                long own = Arith.add(blocking, Arith.mul(q, task.cost()));
                long w = own;
                for (Task t : hp) {
                    w = Arith.add(w, t.cost());
                }
                while (true) {
                    if (++steps > ResponseTimes.MAX_STEPS) {
                        return ResponseTimes.notAnalysed(task, "the response-time iteration did not settle within "
                                + ResponseTimes.MAX_STEPS + " steps");
                    }
                    long next = own;
                    for (Task t : hp) {
                        next = Arith.add(next,
                                Arith.mul(Math.floorDiv(Arith.add(w, t.jitter()), t.period()) + 1, t.cost()));
                    }
                    if (next == w) {
                        break;
                    }
                    w = next;
                }
                long response = Arith.add(Arith.add(task.jitter(), w - Arith.mul(q, task.period())), task.cost());
                if (response > worst) {
                    worst = response;
                    worstJob = q;
                }
            }
            long worstResponse = worst;
            long job = worstJob;
            return MissWitnesses.result(task, worst, worstJob, () -> MissWitnesses.summary(task, worstResponse, job, hp, blocker));
        } catch (ArithmeticException e) {
            return ResponseTimes.notAnalysed(task, new Arith.TooLarge().getMessage());
        }
    }
}
