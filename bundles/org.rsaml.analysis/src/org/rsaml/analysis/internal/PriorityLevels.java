/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;

/**
 * The preemptive response times of every task of a processor, highest priority first, each equal to
 * {@link Preemptive#of(List, Task, int)}'s but without a pass over the tasks that can delay it. The
 * tasks that can delay a task are the prefix of the tasks in priority order: they join once, as the
 * priority falls, and everything that follows from them is kept up to date as they join instead of
 * rebuilt per task:
 * <ul>
 * <li>one entry per distinct (period, jitter), whose interference {@link Interference} keeps as the
 * window grows, within a task's busy period and from task to task (the first jobs' windows grow from
 * task to task; the later jobs of a long busy period continue from it without moving it
 * ({@link Interference.Later}), so that the next task does not start below where the interference stands);</li>
 * <li>the sum of their costs (the first window's floor) and their utilisation (the level's overload);</li>
 * <li>a lower bound of the next level's first window: this level's;</li>
 * <li>the tasks themselves, by period, for a miss's summary witness ({@link DelayingTasks}).</li>
 * </ul>
 */
public final class PriorityLevels {

    /** From this many tasks analysed at one priority on, they read their windows from the level's one walk. */
    public static final int SHARED_LEVEL = 16;

    private PriorityLevels() {
    }

    /** Every task of {@code tasks} but those of {@code skipped} (indices), at its own priority, into {@code out}. */
    public static void analyse(List<Task> tasks, Set<Integer> skipped, TaskResult[] out) {
        int[] priority = new int[tasks.size()];
        for (int i = 0; i < priority.length; i++) {
            priority[i] = tasks.get(i).priority();
        }
        analyse(tasks, tasks, priority, skipped, out);
    }

    /**
     * @param delaying  the tasks as they delay the others (with the release jitter a lock wait gives them)
     * @param own       the same tasks as each is analysed itself
     * @param effective the priority each is analysed at ({@link ResponseTimes#effectivePriorities}):
     *                  every other task at or above it delays it
     * @param skipped   the indices of tasks not to analyse (they still delay the others)
     * @param out       receives each task's result at its index
     */
    public static void analyse(List<Task> delaying, List<Task> own, int[] effective, Set<Integer> skipped, TaskResult[] out) {
        int n = delaying.size();
        Integer[] byPriority = sortedDescending(n, i -> delaying.get(i).priority());
        Integer[] byEffective = sortedDescending(n, i -> effective[i]);
        Map<Long, Integer> slot = new HashMap<>();
        long[] period = new long[n];
        long[] cost = new long[n];
        long[] jitter = new long[n];
        int[] entryOf = new int[n];
        int entries = 0;
        Interference interference = new Interference(period, cost, jitter, 0);
        Interference.Later later = new Interference.Later(interference);
        DelayingTasks prefix = new DelayingTasks(delaying);
        // the sum of all costs at or above the level (-1 once too large to add), and their utilisation
        long total = 0;
        double utilisation = 0;
        long seed = 0;
        int seedLevel = Integer.MAX_VALUE;
        long[] window = new long[3]; // the first job's window, the jobs of the busy period, the last job's window
        AnalysisCounts counts = AnalysisCounts.current();
        int joined = 0;
        int analysed = 0;
        while (joined < n) {
            int level = delaying.get(byPriority[joined]).priority();
            // the whole level first: tasks of equal priority delay each other
            for (; joined < n && delaying.get(byPriority[joined]).priority() == level; joined++) {
                int i = byPriority[joined];
                Task t = delaying.get(i);
                Integer e = t.jitter() == 0 ? slot.get(t.period()) : null;
                if (e == null) {
                    e = entries++;
                    period[e] = t.period();
                    jitter[e] = t.jitter();
                    if (t.jitter() == 0) {
                        slot.put(t.period(), e);
                    }
                    interference.add(e);
                }
                cost[e] = Math.addExact(cost[e], t.cost());
                interference.costChanged(e, t.cost());
                entryOf[i] = e;
                prefix.join(i);
                total = total < 0 || total > Long.MAX_VALUE - t.cost() ? -1 : total + t.cost();
                utilisation += (double) t.cost() / t.period();
            }
            long levelWindow = -1;
            int ties = 0;
            for (int a = analysed; a < n && effective[byEffective[a]] >= level; a++) {
                ties += skipped.contains(byEffective[a]) ? 0 : 1;
            }
            // many tasks analysed at one level share its busy period: one walk of it for all of them
            LevelExcess excess = ties >= SHARED_LEVEL ? LevelExcess.of(period, cost, jitter, entries, utilisation) : null;
            if (counts != null && excess != null) {
                counts.levelsWalked++;
                counts.levelReleases += excess.pieces();
            }
            for (; analysed < n && effective[byEffective[analysed]] >= level; analysed++) {
                int i = byEffective[analysed];
                if (skipped.contains(i)) {
                    continue; // analysed otherwise (first in, first out at the top rank: nothing above seeds the level below)
                }
                Task t = own.get(i);
                long c = delaying.get(i).cost();
                cost[entryOf[i]] -= c;
                interference.costChanged(entryOf[i], -c);
                double u = utilisation;
                // the level above seeds a task that did not delay it (a task of a lock group analysed below its
                // own priority may have: then its window need not be above theirs)
                long floor = delaying.get(i).priority() < seedLevel ? seed : 0;
                LevelExcess.Tied tied = excess == null ? null : excess.of(period[entryOf[i]], jitter[entryOf[i]], c);
                out[i] = Preemptive.of(t, effective[i], interference, later, tied, period, cost, entries, total < 0 ? -1 : total - c, utilisation,
                        floor, window, () -> u, (worst, job) -> prefix.summary(t, i, worst, job));
                cost[entryOf[i]] += c;
                interference.costChanged(entryOf[i], c);
                levelWindow = Math.max(levelWindow, window[0]);
                if (counts != null) {
                    count(counts, out[i], tied, window);
                }
            }
            // the next level's first job needs at least this level's window beyond its own cost
            seed = Math.max(0, levelWindow);
            seedLevel = level;
        }
        if (counts != null) {
            counts.iterations += interference.evaluations + later.evaluations;
            counts.firstJobSteps += interference.calendar().steps;
            counts.laterJobSteps += later.calendar().steps;
            counts.bucketsPassed += interference.calendar().passed + later.calendar().passed;
            counts.entriesLookedAt += interference.calendar().looked + later.calendar().looked;
            counts.summaries += prefix.summaries;
            counts.nodesOpened += prefix.opened;
        }
    }

    private static void count(AnalysisCounts counts, TaskResult result, LevelExcess.Tied tied, long[] window) {
        counts.tasks++;
        boolean iterated = window[1] > 0;
        counts.overloaded += !iterated && result.responseTime().isEmpty() && result.verdict() == org.rsaml.analysis.Verdict.MISSES ? 1 : 0;
        counts.jobs += Math.max(0, window[1]);
        counts.longestBusyPeriod = Math.max(counts.longestBusyPeriod, window[2]);
        if (tied != null && iterated) {
            if (tied.answered) {
                counts.tiedDecided++;
            } else {
                counts.tiedIterated++;
            }
        }
    }

    private static Integer[] sortedDescending(int n, java.util.function.IntUnaryOperator key) {
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> Integer.compare(key.applyAsInt(b), key.applyAsInt(a)));
        return order;
    }
}
