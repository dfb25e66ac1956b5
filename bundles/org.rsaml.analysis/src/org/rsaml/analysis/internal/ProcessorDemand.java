/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.analysis.DemandWitness;
import org.rsaml.analysis.Task;

/**
 * The processor-demand criterion (Baruah, Rosier &amp; Howell 1990) decided by Quick convergence
 * Processor-demand Analysis, QPA (Zhang &amp; Burns 2009), for constrained and arbitrary deadlines:
 * the tasks can be scheduled by EDF, and by no scheduler otherwise, iff every interval [0, t] holds
 * the demand h(t) of the jobs released and due within it. Release jitter shortens a deadline by the
 * jitter.
 */
public final class ProcessorDemand {

    private static final long MAX_STEPS = 10_000_000;

    private ProcessorDemand() {
    }

    /** The outcome: feasible, infeasible with a witness, or undecided with a reason. */
    public record Outcome(boolean feasible, DemandWitness witness, String undecided) {
    }

    /** h(t): the processor time needed by jobs both released and due within [0, t]. */
    public static long demand(List<Task> tasks, long t) {
        long h = 0;
        for (Task task : tasks) {
            h = Arith.add(h, Arith.mul(jobs(task, t), task.cost()));
        }
        return h;
    }

    private static long jobs(Task task, long t) {
        long due = task.deadline() - task.jitter();
        return t < due ? 0 : Math.floorDiv(t - due, task.period()) + 1;
    }

    private static DemandWitness witness(List<Task> tasks, long t) {
        Map<String, Long> jobs = new LinkedHashMap<>();
        for (Task task : tasks) {
            long n = jobs(task, t);
            if (n > 0 && task.cost() > 0) {
                jobs.put(task.name(), n);
            }
        }
        return new DemandWitness(t, demand(tasks, t), jobs);
    }

    /** The latest absolute deadline d = k T + D - J (k &ge; 0) not after x, or Long.MIN_VALUE if none. */
    private static long latestDeadlineAtMost(List<Task> tasks, long x) {
        long best = Long.MIN_VALUE;
        for (Task task : tasks) {
            long due = task.deadline() - task.jitter();
            if (due <= x) {
                best = Math.max(best, Arith.add(due, Arith.mul(Math.floorDiv(x - due, task.period()), task.period())));
            }
        }
        return best;
    }

    public static Outcome decide(List<Task> tasks, Utilisation utilisation) {
        try {
            for (Task task : tasks) {
                long due = task.deadline() - task.jitter();
                if (task.cost() > 0 && due < task.cost()) {
                    long t = Math.max(0, due);
                    return new Outcome(false, witness(tasks, t), null);
                }
            }
            if (utilisation.versusOne() > 0) {
                return new Outcome(false, overloadWitness(tasks, utilisation), null);
            }
            // synchronous busy period
            long busy = 0;
            for (Task task : tasks) {
                busy = Arith.add(busy, task.cost());
            }
            long steps = 0;
            while (true) {
                if (++steps > MAX_STEPS) {
                    return new Outcome(false, null, "the busy-period iteration did not settle within " + MAX_STEPS + " steps");
                }
                long next = 0;
                for (Task task : tasks) {
                    next = Arith.add(next, Arith.mul(Arith.ceilDiv(Arith.add(busy, task.jitter()), task.period()), task.cost()));
                }
                if (next == busy) {
                    break;
                }
                busy = next;
            }
            long limit = busy;
            if (utilisation.clearlyBelowOne()) {
                // La (Zhang & Burns): max(D - T, sum (T - D) U / (1 - U)), D shortened by the jitter; any
                // larger bound is as exact, so floating point rounded up generously is safe
                double sum = 0;
                long la = Long.MIN_VALUE;
                for (Task task : tasks) {
                    long due = task.deadline() - task.jitter();
                    la = Math.max(la, due - task.period());
                    sum += (double) (task.period() - due) * task.cost() / task.period();
                }
                double bound = Math.ceil(sum / (1 - utilisation.value) * (1 + 1e-9)) + 1;
                if (bound < 0x1p62) {
                    la = Math.max(la, (long) bound);
                    limit = Math.min(limit, la);
                }
            }
            long dmin = Long.MAX_VALUE;
            for (Task task : tasks) {
                dmin = Math.min(dmin, task.deadline() - task.jitter());
            }
            long t = latestDeadlineAtMost(tasks, limit);
            while (t != Long.MIN_VALUE) {
                if (++steps > MAX_STEPS) {
                    return new Outcome(false, null, "the demand test did not settle within " + MAX_STEPS + " steps");
                }
                long h = demand(tasks, t);
                if (h > t) {
                    return new Outcome(false, witness(tasks, t), null);
                }
                if (h <= dmin) {
                    break;
                }
                t = h < t ? h : latestDeadlineAtMost(tasks, t - 1);
            }
            return new Outcome(true, null, null);
        } catch (ArithmeticException e) {
            return new Outcome(false, null, new Arith.TooLarge().getMessage());
        }
    }

    /**
     * With U &gt; 1 the demand h(t) &gt; U t - sum C (D - J) / T, which exceeds t from
     * t = sum C (D - J) / T / (U - 1) on.
     */
    private static DemandWitness overloadWitness(List<Task> tasks, Utilisation utilisation) {
        double offset = 0;
        long start = 0;
        for (Task task : tasks) {
            long due = Math.max(0, task.deadline() - task.jitter());
            offset += (double) task.cost() * due / task.period();
            start = Math.max(start, due);
        }
        double guess = Math.ceil(offset / (utilisation.value - 1) * (1 + 1e-9)) + 1;
        long t = Math.max(start, guess >= 0x1p61 ? Long.MAX_VALUE / 4 : (long) guess);
        // the guess comes from floating point: confirm it, doubling while not overloaded
        for (int i = 0; i < 64 && t < Long.MAX_VALUE / 4; i++, t *= 2) {
            long at = latestDeadlineAtMost(tasks, t);
            if (at != Long.MIN_VALUE && demand(tasks, at) > at) {
                return witness(tasks, at);
            }
            if (demand(tasks, t) > t) {
                return witness(tasks, t);
            }
        }
        return null;
    }
}
