/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalLong;

import org.rsaml.analysis.Rational;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.Witness;
import org.rsaml.model.support.RsamlTimes;

/**
 * Exact response-time analysis for fixed priorities, preemptive (Joseph &amp; Pandya 1986; Audsley et
 * al. 1993; busy-period iteration for deadlines beyond the period after Lehoczky 1990 and Tindell et
 * al. 1994) and non-preemptive (the revised analysis of Davis, Burns, Bril &amp; Lukkien 2007, which
 * examines every job of the level-i busy period, not only the first).
 */
public final class ResponseTimes {

    /** A busy period with more jobs than this is not examined job by job (the verdict says so). */
    public static final long MAX_JOBS = 1_000_000;
    private static final long MAX_STEPS = 50_000_000;

    private ResponseTimes() {
    }

    /** Tasks that can delay {@code task}: every other task of higher or equal priority. */
    static List<Task> interfering(List<Task> tasks, Task task) {
        List<Task> hp = new ArrayList<>();
        for (Task t : tasks) {
            if (t != task && t.priority() >= task.priority()) {
                hp.add(t);
            }
        }
        return hp;
    }

    /** Whether some task can wait for a lower-priority member of its lock group. */
    public static boolean anyBlockedByLock(List<Task> tasks) {
        java.util.Map<String, Integer> lowest = new java.util.HashMap<>();
        for (Task t : tasks) {
            if (t.group() != null) {
                lowest.merge(t.group(), t.priority(), Math::min);
            }
        }
        for (Task t : tasks) {
            if (t.group() != null && lowest.get(t.group()) < t.priority()) {
                return true;
            }
        }
        return false;
    }

    /**
     * The lowest priority of the task's lock group: a lower-priority member holding the lock makes the
     * task wait, and whatever preempts that member delays the task too (no priority inheritance).
     */
    /** {@link #effectivePriority} of every task, in order: one pass over the lock groups, not one per task. */
    public static int[] effectivePriorities(List<Task> tasks) {
        java.util.Map<String, Integer> lowest = new java.util.HashMap<>();
        for (Task t : tasks) {
            if (t.group() != null) {
                lowest.merge(t.group(), t.priority(), Math::min);
            }
        }
        int[] effective = new int[tasks.size()];
        for (int i = 0; i < effective.length; i++) {
            Task t = tasks.get(i);
            effective[i] = t.group() == null ? t.priority() : Math.min(t.priority(), lowest.get(t.group()));
        }
        return effective;
    }

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
        double u = (double) task.cost() / task.period();
        for (Task t : others) {
            u += (double) t.cost() / t.period();
        }
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

    private static String levelOverload(Task task, List<Task> others) {
        double u = (double) task.cost() / task.period();
        for (Task t : others) {
            u += (double) t.cost() / t.period();
        }
        return "the tasks at or above its priority use " + String.format(java.util.Locale.ROOT, "%.4f", u)
                + " of the processor, more than all of it: its response time grows without bound";
    }

    /** Preemptive fixed priority, constrained or arbitrary deadlines, release jitter. */
    public static TaskResult preemptive(List<Task> tasks, Task task) {
        return preemptive(tasks, task, effectivePriority(tasks, task), 0, null);
    }

    /**
     * @param effective   the task's priority as analysed (see {@link #effectivePriority})
     * @param seed        a lower bound of the window the first job needs beyond its own cost: the
     *                    first-job window of a task p with hp(p) and p itself all delaying this task
     *                    (the window of this task is at least its cost plus p's); 0 when none is known
     * @param firstWindow when not null, receives this task's first-job window (or -1)
     */
    public static TaskResult preemptive(List<Task> tasks, Task task, int effective, long seed, long[] firstWindow) {
        if (firstWindow != null) {
            firstWindow[0] = -1;
        }
        List<Task> hp = new ArrayList<>();
        for (Task t : tasks) {
            if (t != task && t.priority() >= effective) {
                hp.add(t);
            }
        }
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
        return preemptive(task, effective, period, cost, jitter, n, seed, firstWindow, () -> hp);
    }

    /**
     * The same, with the interfering tasks given as (period, cost, jitter) entries; tasks of equal
     * period and jitter may be merged into one entry with the sum of their costs, which keeps the
     * iteration short for thousands of tasks with few distinct periods.
     *
     * @param interfering the interfering tasks themselves, asked for only for a miss's witness
     */
    public static TaskResult preemptive(Task task, int effective, long[] period, long[] cost, long[] jitter, int n, long seed,
            long[] firstWindow, java.util.function.Supplier<List<Task>> interfering) {
        return preemptive(task, effective, period, cost, jitter, n, seed, firstWindow, interfering,
                new Interference(period, cost, jitter, n), -1, Double.NaN);
    }

    /**
     * The same, for a caller that walks the priority levels down and keeps what does not change from
     * task to task: the interference of the entries (kept up to date as they are added and their costs
     * change, see {@link Interference#add} and {@link Interference#costChanged}), and, for the task's
     * level, the sum of the entries' costs ({@code base}, or -1 to sum them here) and the utilisation of
     * the task and the entries ({@code levelUtilisation}, or NaN; decided exactly here when near 1).
     * Without them each task costs a pass over every entry, quadratic in the number of distinct periods.
     */
    public static TaskResult preemptive(Task task, int effective, long[] period, long[] cost, long[] jitter, int n, long seed,
            long[] firstWindow, java.util.function.Supplier<List<Task>> interfering, Interference interference, long base,
            double levelUtilisation) {
        if (firstWindow != null) {
            firstWindow[0] = -1;
        }
        Task analysed = effective == task.priority() ? task
                : new Task(task.name(), task.period(), task.deadline(), task.cost(), effective, task.jitter(), task.group());
        int level = Double.isNaN(levelUtilisation) || Math.abs(levelUtilisation - 1) <= 1e-9 ? levelVersusOne(task, period, cost, n)
                : levelUtilisation > 1 ? 1 : -1;
        if (level > 0) {
            return new TaskResult(task, OptionalLong.empty(), Verdict.MISSES, levelOverload(task, interfering.get()), null);
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
            for (long q = 0;; q++) {
                if (q >= MAX_JOBS) {
                    return notAnalysed(task, "its busy period holds more than " + MAX_JOBS + " of its jobs");
                }
                long own = Math.multiplyExact(q + 1, task.cost());
                // Job q's window is at least job q-1's plus one more cost (its least fixed point is above
                // that), so the window only grows through the busy period and the interference follows it.
                long start = Math.addExact(own, q == 0 ? Math.max(base, seed) : base);
                w = q == 0 ? start : Math.max(start, Math.addExact(w, task.cost()));
                while (true) {
                    if (++steps > MAX_STEPS) {
                        return notAnalysed(task, "the response-time iteration did not settle within " + MAX_STEPS + " steps");
                    }
                    long next = Math.addExact(own, interference.at(w));
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
            TaskResult r = result(analysed, worst, worstJob, worst <= task.deadline() ? List.of() : interfering.get(), null, true);
            String lock = analysed == task ? ""
                    : " (waiting for its lock group '" + task.group() + "', as if at priority " + effective + ")";
            return new TaskResult(task, r.responseTime(), r.verdict(), r.explanation() + lock, r.witness());
        } catch (ArithmeticException e) {
            return notAnalysed(task, new Arith.TooLarge().getMessage());
        }
    }

    /**
     * The interference sum_k ceil((w + J_k) / T_k) C_k of the entries, kept up to date as w grows:
     * each entry waits in a heap, keyed by the largest w its job count holds for, so a step touches
     * only the entries whose count changes (O(log n) each), not every entry. Over a whole busy
     * period that is one heap operation per interfering job released in it, instead of one pass over
     * all entries per step. Entries can be added and their costs changed while it is in use (a caller
     * walking down the priority levels keeps one for all its tasks, whose windows mostly grow from task
     * to task too); should w ever fall, the counts are recomputed from scratch.
     */
    public static final class Interference {
        private final long[] period;
        private final long[] cost;
        private final long[] jitter;
        private int n;
        private final long[] jobs;
        /** The entry's count holds while w &lt;= limit: ceil((w + J) / T) = jobs. */
        private final long[] limit;
        private final int[] heap;
        private int size;
        private long w = Long.MIN_VALUE;
        private long sum;

        /** Over the first {@code n} entries of the arrays, which may grow up to their length through {@link #add}. */
        public Interference(long[] period, long[] cost, long[] jitter, int n) {
            this.period = period;
            this.cost = cost;
            this.jitter = jitter;
            this.n = n;
            this.jobs = new long[period.length];
            this.limit = new long[period.length];
            this.heap = new int[period.length];
        }

        /** Entry {@code k}, the next one, has been filled in (its cost may still be 0). */
        public void add(int k) {
            if (k != n) {
                throw new IllegalArgumentException("entries are added in order: " + k + " after " + n);
            }
            n++;
            if (w == Long.MIN_VALUE) {
                return;
            }
            try {
                count(k, w);
                sum = Math.addExact(sum, Math.multiplyExact(jobs[k], cost[k]));
            } catch (ArithmeticException e) {
                w = Long.MIN_VALUE; // recomputed (and reported too large) by the next at()
                return;
            }
            int i = size++;
            while (i > 0 && limit[heap[(i - 1) / 2]] > limit[k]) {
                heap[i] = heap[(i - 1) / 2];
                i = (i - 1) / 2;
            }
            heap[i] = k;
        }

        /** Entry {@code k}'s cost has just changed by {@code delta}. */
        public void costChanged(int k, long delta) {
            if (w == Long.MIN_VALUE) {
                return;
            }
            try {
                sum = Math.addExact(sum, Math.multiplyExact(jobs[k], delta));
            } catch (ArithmeticException e) {
                w = Long.MIN_VALUE;
            }
        }

        private void count(int k, long window) {
            long x = Math.addExact(window, jitter[k]);
            jobs[k] = x / period[k] + (x % period[k] == 0 ? 0 : 1);
            limit[k] = Math.subtractExact(Math.multiplyExact(jobs[k], period[k]), jitter[k]);
        }

        /** The interference in a window of length {@code window}. */
        long at(long window) {
            try {
                return advance(window);
            } catch (ArithmeticException e) {
                w = Long.MIN_VALUE; // the counts are half updated: recomputed next time
                throw e;
            }
        }

        private long advance(long window) {
            if (window < w) {
                w = Long.MIN_VALUE;
            }
            if (w == Long.MIN_VALUE) {
                sum = 0;
                size = 0;
                for (int k = 0; k < n; k++) {
                    count(k, window);
                    sum = Math.addExact(sum, Math.multiplyExact(jobs[k], cost[k]));
                    heap[size++] = k;
                }
                for (int i = size / 2 - 1; i >= 0; i--) {
                    down(i);
                }
                w = window;
                return sum;
            }
            w = window;
            while (size > 0 && limit[heap[0]] < window) {
                int k = heap[0];
                long before = jobs[k];
                count(k, window);
                sum = Math.addExact(sum, Math.multiplyExact(jobs[k] - before, cost[k]));
                down(0);
            }
            return sum;
        }

        private void down(int i) {
            int k = heap[i];
            long key = limit[k];
            while (true) {
                int child = 2 * i + 1;
                if (child >= size) {
                    break;
                }
                if (child + 1 < size && limit[heap[child + 1]] < limit[heap[child]]) {
                    child++;
                }
                if (limit[heap[child]] >= key) {
                    break;
                }
                heap[i] = heap[child];
                i = child;
            }
            heap[i] = k;
        }
    }

    /** The utilisation of the task and the entries compared with 1, exactly near 1. */
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

    /**
     * Tasks of one priority that run first in, first out, with nothing above them and nothing below
     * that can block them (the runtime's SCHED_FIFO threads of a processor's highest rank): a job
     * waits for exactly the jobs of the level released before or with it and not yet done. A job
     * released at t in a busy period that began at s completes by s plus the work released in
     * [s, t], at most sum_j (floor((t - s)/T_j) + 1) C_j &lt;= sum_j C_j + U (t - s); with U &lt;= 1 its
     * response is therefore at most sum_j C_j, and all the tasks released together, the analysed one
     * last among them, reach it. So the worst response of every task of the level is the sum of their
     * costs (exact), and with U &gt; 1 there is no bound. Tasks with release jitter (lock groups) get
     * {@link #nonPreemptive}, which bounds it.
     */
    public static TaskResult firstInFirstOut(List<Task> level, Task task) {
        List<Task> others = interfering(level, task);
        boolean jitter = task.jitter() > 0 || others.stream().anyMatch(t -> t.jitter() > 0);
        if (jitter) {
            return nonPreemptive(level, task);
        }
        if (utilisationVersusOne(task, others) > 0) {
            return new TaskResult(task, OptionalLong.empty(), Verdict.MISSES, levelOverload(task, others), null);
        }
        try {
            long worst = task.cost();
            for (Task t : others) {
                worst = Arith.add(worst, t.cost());
            }
            TaskResult r = result(task, worst, 0, others, null, false);
            if (r.witness() == null) {
                return r;
            }
            // one job of each other task delays it: the one released with it
            List<Task> delaying = new ArrayList<>(others.stream().filter(t -> t.cost() > 0).toList());
            delaying.sort((a, b) -> Long.compare(b.cost(), a.cost()));
            java.util.Map<String, Long> listed = new java.util.LinkedHashMap<>();
            for (Task t : delaying.subList(0, Math.min(MAX_LISTED, delaying.size()))) {
                listed.put(t.name(), 1L);
            }
            Witness w = new Witness(task.name(), 0, 0, worst, List.of(), listed, null, false, delaying.size() - listed.size());
            return new TaskResult(task, r.responseTime(), r.verdict(), r.explanation(), w);
        } catch (ArithmeticException e) {
            return notAnalysed(task, new Arith.TooLarge().getMessage());
        }
    }

    /**
     * {@link #firstInFirstOut(List, Task)} of every task of the level, in its order, in time linear in
     * the level's size: the worst response (the sum of the level's costs) and the level's utilisation are
     * the same for every task, and the tasks that delay the most are one sorted list, so nothing is
     * recomputed per task (thousands of FIFO releases at a processor's top rank cost n², not n, that way).
     */
    public static TaskResult[] firstInFirstOut(List<Task> level) {
        TaskResult[] out = new TaskResult[level.size()];
        if (level.stream().anyMatch(t -> t.jitter() > 0)) {
            for (int i = 0; i < out.length; i++) {
                out[i] = nonPreemptive(level, level.get(i));
            }
            return out;
        }
        if (level.isEmpty()) {
            return out;
        }
        if (utilisationVersusOne(level.get(0), level.subList(1, level.size())) > 0) {
            String overload = levelOverload(level.get(0), level.subList(1, level.size())); // the whole level's, as for each task
            for (int i = 0; i < out.length; i++) {
                out[i] = new TaskResult(level.get(i), OptionalLong.empty(), Verdict.MISSES, overload, null);
            }
            return out;
        }
        long sum = 0;
        try {
            for (Task t : level) {
                sum = Arith.add(sum, t.cost());
            }
        } catch (ArithmeticException e) {
            for (int i = 0; i < out.length; i++) {
                out[i] = notAnalysed(level.get(i), new Arith.TooLarge().getMessage());
            }
            return out;
        }
        // the tasks that delay the most, most first (a stable sort: ties in the level's order), one more than a witness lists
        List<Task> delaying = new ArrayList<>(level.stream().filter(t -> t.cost() > 0).toList());
        delaying.sort((a, b) -> Long.compare(b.cost(), a.cost()));
        List<Task> top = delaying.subList(0, Math.min(MAX_LISTED + 1, delaying.size()));
        for (int i = 0; i < out.length; i++) {
            Task task = level.get(i);
            TaskResult r = result(task, sum, 0, List.of(), null, false);
            if (r.witness() == null) {
                out[i] = r;
                continue;
            }
            java.util.Map<String, Long> listed = new java.util.LinkedHashMap<>();
            for (Task t : top) {
                if (t != task && listed.size() < MAX_LISTED) {
                    listed.put(t.name(), 1L);
                }
            }
            int others = delaying.size() - (task.cost() > 0 ? 1 : 0);
            Witness w = new Witness(task.name(), 0, 0, sum, List.of(), listed, null, false, others - listed.size());
            out[i] = new TaskResult(task, r.responseTime(), r.verdict(), r.explanation(), w);
        }
        return out;
    }

    /**
     * Non-preemptive fixed priority: a job, once started, runs to completion, so a lower-priority job
     * started just before can block it. Equal priorities are served first-in first-out, which the
     * analysis bounds by counting them as interfering (jobs released until the job starts, not only
     * before its release: sound, not exact; {@link #firstInFirstOut} is exact where it applies).
     */
    public static TaskResult nonPreemptive(List<Task> tasks, Task task) {
        List<Task> hp = interfering(tasks, task);
        Task blocker = null;
        for (Task t : tasks) {
            if (t.priority() < task.priority() && (blocker == null || t.cost() > blocker.cost())) {
                blocker = t;
            }
        }
        long blocking = blocker == null ? 0 : blocker.cost();
        if (blocking == 0) {
            blocker = null;
        }
        int level = utilisationVersusOne(task, hp);
        if (level > 0) {
            return new TaskResult(task, OptionalLong.empty(), Verdict.MISSES, levelOverload(task, hp), null);
        }
        if (level == 0 && blocking > 0) {
            return notAnalysed(task, "the tasks at or above its priority use all of the processor and a lower-priority job"
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
                if (++steps > MAX_STEPS) {
                    return notAnalysed(task, "the busy-period iteration did not settle within " + MAX_STEPS + " steps");
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
            if (jobs > MAX_JOBS) {
                return notAnalysed(task, "its busy period holds more than " + MAX_JOBS + " of its jobs");
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
                    if (++steps > MAX_STEPS) {
                        return notAnalysed(task, "the response-time iteration did not settle within " + MAX_STEPS + " steps");
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
            return result(task, worst, worstJob, hp, blocker, false);
        } catch (ArithmeticException e) {
            return notAnalysed(task, new Arith.TooLarge().getMessage());
        }
    }

    private static TaskResult result(Task task, long worst, long job, List<Task> hp, Task blocker, boolean preemptive) {
        String where = job == 0 ? "its first job after the critical instant"
                : "job " + (job + 1) + " of its busy period (an earlier job delays it)";
        if (worst <= task.deadline()) {
            return new TaskResult(task, OptionalLong.of(worst), Verdict.MEETS,
                    "worst-case response time " + RsamlTimes.text(worst) + " (" + where + ") within its deadline of "
                            + RsamlTimes.text(task.deadline()),
                    null);
        }
        Witness witness = summary(task, worst, job, hp, blocker);
        return new TaskResult(task, OptionalLong.of(worst), Verdict.MISSES,
                "worst-case response time " + RsamlTimes.text(worst) + " (" + where + ") exceeds its deadline of "
                        + RsamlTimes.text(task.deadline()) + " by " + RsamlTimes.text(worst - task.deadline()),
                witness);
    }

    /** Tasks a summary witness lists by name, those that delay it most; the others are counted. */
    public static final int MAX_LISTED = 20;

    /**
     * The witness of a miss without its schedule (which costs a simulation): per interfering task, its
     * jobs released from the critical instant until the job completes, the most delaying first.
     */
    private static Witness summary(Task task, long worst, long job, List<Task> hp, Task blocker) {
        long release = Arith.mul(task.period(), job);
        long completion = Arith.add(release, worst - task.jitter());
        List<long[]> counts = new ArrayList<>(); // index, jobs, delay
        for (int k = 0; k < hp.size(); k++) {
            Task t = hp.get(k);
            long jobs = Arith.ceilDiv(Arith.add(completion, t.jitter()), t.period());
            if (jobs > 0 && t.cost() > 0) {
                counts.add(new long[] { k, jobs, Arith.mul(jobs, t.cost()) });
            }
        }
        // the MAX_LISTED that delay most, most first, ties in their order: as a stable sort of all would list
        // them, without sorting thousands for each task that misses
        java.util.Comparator<long[]> listedFirst = (a, b) -> a[2] != b[2] ? Long.compare(b[2], a[2]) : Long.compare(a[0], b[0]);
        java.util.PriorityQueue<long[]> kept = new java.util.PriorityQueue<>(listedFirst.reversed());
        for (long[] c : counts) {
            kept.add(c);
            if (kept.size() > MAX_LISTED) {
                kept.poll();
            }
        }
        List<long[]> top = new ArrayList<>(kept);
        top.sort(listedFirst);
        java.util.Map<String, Long> listed = new java.util.LinkedHashMap<>();
        for (long[] c : top) {
            listed.put(hp.get((int) c[0]).name(), c[1]);
        }
        return new Witness(task.name(), job, release, completion, List.of(), listed, blocker == null ? null : blocker.name(), false,
                counts.size() - listed.size());
    }

    /**
     * The critical-instant schedule of job {@code job} of the task, among the tasks of {@code scope}:
     * preemptive, everything at or above {@code effective} delaying it; or non-preemptive, everything at
     * or above its priority, after the longest lower-priority job.
     */
    public static Witness schedule(List<Task> scope, Task task, int effective, long job, boolean preemptive) {
        return schedule(scope, task, effective, job, preemptive, false);
    }

    /**
     * The same; with {@code firstInFirstOut} (non-preemptive only), equal priorities run in the order
     * of their releases, the analysed task last among those released with it.
     */
    public static Witness schedule(List<Task> scope, Task task, int effective, long job, boolean preemptive,
            boolean firstInFirstOut) {
        Task analysed = effective == task.priority() ? task
                : new Task(task.name(), task.period(), task.deadline(), task.cost(), effective, task.jitter(), task.group());
        List<Task> hp = new ArrayList<>();
        Task blocker = null;
        for (Task t : scope) {
            if (t != task && t.priority() >= (preemptive ? effective : task.priority())) {
                hp.add(t);
            } else if (!preemptive && t.priority() < task.priority() && t.cost() > 0 && (blocker == null || t.cost() > blocker.cost())) {
                blocker = t;
            }
        }
        return CriticalInstant.schedule(analysed, hp, blocker, job, preemptive, firstInFirstOut);
    }

    static TaskResult notAnalysed(Task task, String why) {
        return new TaskResult(task, OptionalLong.empty(), Verdict.NOT_ANALYSED, "not analysed: " + why, null);
    }
}
