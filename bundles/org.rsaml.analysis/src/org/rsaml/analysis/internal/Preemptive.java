/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.List;
import java.util.function.Supplier;

import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Witness;

/**
 * Exact response-time analysis of one task under preemptive fixed priorities (Joseph &amp; Pandya
 * 1986; Audsley et al. 1993), with release jitter and deadlines beyond the period by iterating over
 * every job of the task's level-i busy period (Lehoczky 1990; Tindell et al. 1994). The interfering
 * tasks come as (period, cost, jitter) entries, tasks of equal period and jitter merged into one.
 */
public final class Preemptive {

    private Preemptive() {
    }

    /**
     * The task among {@code tasks}, analysed at priority {@code effective} (see
     * {@link ResponseTimes#effectivePriorities}): every other task at or above it delays it. The
     * definition the faster {@link PriorityLevels} is held to; a pass over every task.
     */
    public static TaskResult of(List<Task> tasks, Task task, int effective) {
        List<Task> hp = ResponseTimes.interfering(tasks, task, effective);
        int n = hp.size();
        long[] period = new long[n];
        long[] cost = new long[n];
        long[] jitter = new long[n];
        for (int k = 0; k < n; k++) {
            Task t = hp.get(k);
            period[k] = t.period();
            cost[k] = t.cost();
            jitter[k] = t.jitter();
        }
        return of(task, effective, new Interference(period, cost, jitter, n), null, null, period, cost, n, -1, Double.NaN, 0, null,
                () -> ResponseTimes.utilisation(task, hp), (worst, job) -> MissWitnesses.summary(task, worst, job, hp, null));
    }

    /** A miss's summary witness, of job {@code job} with response {@code worst}. */
    interface Summary {
        Witness of(long worst, long job);
    }

    /**
     * @param interference     the entries' interference (a caller walking down the priority levels
     *                         keeps one for all its tasks, see {@link Interference})
     * @param later            when not null, the interference of the jobs after the first, continued from
     *                         the first's window without moving {@code interference}, so that it stays at
     *                         the first job's window, where the next task starts
     * @param tied             when not null, the busy period of the task's level shared by the tasks tied
     *                         at it ({@link LevelExcess}): each job's window read from it instead of iterated,
     *                         the same fixed point from the same start (else the task iterates itself)
     * @param period           the entries' periods, for the level's utilisation when it is near 1
     * @param cost             the entries' costs, likewise
     * @param n                how many entries there are
     * @param base             the sum of the entries' costs, or -1 to sum them here
     * @param levelUtilisation the utilisation of the task and the entries, or NaN (decided exactly
     *                         here when near 1)
     * @param seed             a lower bound of the window the first job needs beyond its own cost: the
     *                         first-job window of a task p with hp(p) and p itself all delaying this task
     *                         (the window of this task is at least its cost plus p's); 0 when none is known
     * @param firstWindow      when not null, receives this task's first-job window (or -1); when it has three
     *                         places, also the jobs of its busy period examined and the last job's window
     *                         (for {@link AnalysisCounts})
     * @param overload         the level's utilisation as the verdict of an overload states it
     * @param summary          the witness of a miss
     */
    static TaskResult of(Task task, int effective, Interference interference, Interference.Later later, LevelExcess.Tied tied, long[] period, long[] cost, int n, long base,
            double levelUtilisation, long seed, long[] firstWindow, Supplier<Double> overload, Summary summary) {
        if (firstWindow != null) {
            java.util.Arrays.fill(firstWindow, -1);
        }
        Task analysed = effective == task.priority() ? task
                : new Task(task.name(), task.period(), task.deadline(), task.cost(), effective, task.jitter(), task.group());
        int level = Double.isNaN(levelUtilisation) || Math.abs(levelUtilisation - 1) <= 1e-9
                ? ResponseTimes.levelVersusOne(task, period, cost, n)
                : levelUtilisation > 1 ? 1 : -1;
        if (level > 0) {
            return ResponseTimes.overloaded(task, overload.get());
        }
        try {
            if (base < 0) {
                base = 0;
                for (int k = 0; k < n; k++) {
                    base = Math.addExact(base, cost[k]);
                }
            }
            long worst = -1;
            long worstJob = 0;
            long steps = 0;
            long w = -1;
            boolean moved = false;
            long q = 0;
            for (;; q++) {
                if (q >= ResponseTimes.MAX_JOBS) {
                    return ResponseTimes.notAnalysed(task, "its busy period holds more than " + ResponseTimes.MAX_JOBS + " of its jobs");
                }
                long own = Math.multiplyExact(q + 1, task.cost());
                if (q == 1 && later != null && tied == null) {
                    later.start();
                    moved = true;
                }
                // Job q's window is at least job q-1's plus one more cost (its least fixed point is above
                // that), so the window only grows through the busy period and the interference follows it.
                long start = Math.addExact(own, q == 0 ? Math.max(base, seed) : base);
                w = q == 0 ? start : Math.max(start, Math.addExact(w, task.cost()));
                if (tied != null) {
                    // within the level's busy period the iteration below takes fewer steps than the level has
                    // releases (each step past a job's first takes in a release), so no limit can cut it short
                    long read = tied.window(q, task.cost(), w);
                    if (read == LevelExcess.UNKNOWN) {
                        return of(task, effective, interference, later, null, period, cost, n, base, levelUtilisation, seed, firstWindow,
                                overload, summary);
                    }
                    w = read;
                }
                while (tied == null) {
                    if (++steps > ResponseTimes.MAX_STEPS) {
                        return ResponseTimes.notAnalysed(task, "the response-time iteration did not settle within "
                                + ResponseTimes.MAX_STEPS + " steps");
                    }
                    long next = Math.addExact(own, moved ? later.at(w) : interference.at(w));
                    if (next == w) {
                        break;
                    }
                    w = next;
                }
                if (q == 0 && firstWindow != null) {
                    firstWindow[0] = w;
                }
                long response = Math.addExact(w - Math.multiplyExact(q, task.period()), task.jitter());
                if (response > worst) {
                    worst = response;
                    worstJob = q;
                }
                // the level-i busy period ends before the next job is released
                if (Math.addExact(w, task.jitter()) <= Math.multiplyExact(q + 1, task.period())) {
                    break;
                }
            }
            if (firstWindow != null && firstWindow.length >= 3) {
                firstWindow[1] = q + 1;
                firstWindow[2] = w;
            }
            long worstResponse = worst;
            long job = worstJob;
            TaskResult r = MissWitnesses.result(analysed, worst, worstJob, () -> summary.of(worstResponse, job));
            return analysed == task ? r : new TaskResult(task, r.responseTime(), r.verdict(), () -> r.explanation()
                    + " (waiting for its lock group '" + task.group() + "', as if at priority " + effective + ")", r.witness());
        } catch (ArithmeticException e) {
            return ResponseTimes.notAnalysed(task, new Arith.TooLarge().getMessage());
        }
    }
}
