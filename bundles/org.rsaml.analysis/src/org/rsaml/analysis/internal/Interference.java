/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

/**
 * The interference sum_k ceil((w + J_k) / T_k) C_k of the entries, kept up to date as w grows: each
 * entry waits in a {@link Calendar} by the largest w its job count holds for (its next release, at most
 * a period ahead), so a step touches only the entries whose count changes, not every entry, and costs
 * O(1) for each of them and for each bucket passed: over a whole busy period O(1) per interfering job
 * released in it, whatever the number of entries (a binary heap, before, paid O(log n) each). Entries
 * can be added and their costs changed while it is in use (a caller walking down the priority levels
 * keeps one for all its tasks, whose windows mostly grow from task to task too); when the releases get
 * denser than the buckets were cut for, the calendar is cut again, finer (at most once per halving);
 * should w ever fall, the counts are recomputed from scratch.
 */
public final class Interference {
    private final long[] period;
    private final long[] cost;
    private final long[] jitter;
    private int n;
    private final Calendar calendar;
    /** sum_k 1/T_k over the entries: the releases per nanosecond. */
    private double rate;
    private long w = Long.MIN_VALUE;
    private long sum;
    /** Counted for {@link AnalysisCounts}: evaluations at a window (the entries recounted: the calendar's steps). */
    long evaluations;

    /** Over the first {@code n} entries of the arrays, which may grow up to their length through {@link #add}. */
    public Interference(long[] period, long[] cost, long[] jitter, int n) {
        this.period = period;
        this.cost = cost;
        this.jitter = jitter;
        this.n = n;
        this.calendar = new Calendar(period.length);
        for (int k = 0; k < n; k++) {
            rate += 1.0 / period[k];
        }
    }

    /** The calendar, whose counts {@link AnalysisCounts} adds up. */
    public Calendar calendar() {
        return calendar;
    }

    /** Entry {@code k}, the next one, has been filled in (its cost may still be 0). */
    public void add(int k) {
        if (k != n) {
            throw new IllegalArgumentException("entries are added in order: " + k + " after " + n);
        }
        n++;
        rate += 1.0 / period[k];
        if (w == Long.MIN_VALUE) {
            return;
        }
        try {
            calendar.count(k, w, period, jitter);
            sum = Math.addExact(sum, Math.multiplyExact(calendar.jobs[k], cost[k]));
        } catch (ArithmeticException e) {
            w = Long.MIN_VALUE; // recomputed (and reported too large) by the next at()
            return;
        }
        if (Calendar.shiftFor(rate) < calendar.shift - 1) {
            recut(); // the releases got denser than the buckets: cut them finer, with k in
        } else {
            calendar.file(k);
        }
    }

    /** Entry {@code k}'s cost has just changed by {@code delta}. */
    public void costChanged(int k, long delta) {
        if (w == Long.MIN_VALUE) {
            return;
        }
        try {
            sum = Math.addExact(sum, Math.multiplyExact(calendar.jobs[k], delta));
        } catch (ArithmeticException e) {
            w = Long.MIN_VALUE;
        }
    }

    /** Every entry filed again in buckets cut for the present rate. */
    private void recut() {
        calendar.cut(Calendar.shiftFor(rate));
        for (int k = 0; k < n; k++) {
            calendar.file(k);
        }
    }

    /** The interference in a window of length {@code window}. */
    public long at(long window) {
        try {
            return advance(window);
        } catch (ArithmeticException e) {
            w = Long.MIN_VALUE; // the counts are half updated: recomputed next time
            throw e;
        }
    }

    private long advance(long window) {
        evaluations++;
        if (window < w) {
            w = Long.MIN_VALUE;
        }
        if (w == Long.MIN_VALUE) {
            sum = 0;
            calendar.steps += n;
            for (int k = 0; k < n; k++) {
                calendar.count(k, window, period, jitter);
                sum = Math.addExact(sum, Math.multiplyExact(calendar.jobs[k], cost[k]));
            }
            recut();
            w = window;
            return sum;
        }
        sum = calendar.advance(w, window, period, jitter, cost, sum);
        w = window;
        return sum;
    }

    /**
     * Entries filed by the largest window their job count holds for, in buckets as wide as the mean gap
     * between the entries' releases (a power of two of nanoseconds, at most 1 / sum_k 1/T_k), so that a
     * bucket holds about one release, and at least twice as many buckets as entries: every limit lies at
     * most a period past the window, and an entry a round or more ahead is looked at and filed back once
     * per round, which the round's releases (about as many as the buckets) pay for.
     */
    public static final class Calendar {
        /** Per entry: its job count, and the largest window it holds for: ceil((w + J) / T) = jobs while w &lt;= limit. */
        final long[] jobs;
        final long[] limit;
        /** Per entry: the next entry of its bucket (-1: none); per bucket: its first entry. */
        final int[] next;
        final int[] head;
        final int mask;
        /** The bucket of a limit is (limit &gt;&gt; shift) &amp; mask. */
        int shift;
        /** Entries recounted, buckets passed and entries looked at in them, for {@link AnalysisCounts}. */
        long steps;
        long passed;
        long looked;

        /** For {@code size} entries, with at least twice as many buckets, all empty. */
        public Calendar(int size) {
            jobs = new long[size];
            limit = new long[size];
            next = new int[size];
            head = new int[Integer.highestOneBit(Math.max(1, size)) << 2]; // at least twice the entries
            mask = head.length - 1;
            java.util.Arrays.fill(head, -1);
        }

        /** Entry k's job count, as last counted. */
        public long jobs(int k) {
            return jobs[k];
        }

        /** The largest window entry k's job count holds for. */
        public long limit(int k) {
            return limit[k];
        }

        /** The number of buckets, a power of two. */
        public int buckets() {
            return head.length;
        }

        /** The width of a bucket is 2^shift ns. */
        public int shift() {
            return shift;
        }

        /** Entries recounted so far. */
        public long steps() {
            return steps;
        }

        /** Buckets passed so far. */
        public long passed() {
            return passed;
        }

        /** Entries looked at so far in the buckets passed (recounted or filed back). */
        public long looked() {
            return looked;
        }

        /** The shift whose buckets are no wider than the mean gap between releases, 1 / rate. */
        public static int shiftFor(double rate) {
            double gap = 1 / rate;
            return gap >= 0x1p62 ? 62 : Math.max(0, 63 - Long.numberOfLeadingZeros(Math.max(1, (long) gap)));
        }

        /** Empty, with buckets of width 2^shift. */
        public void cut(int shift) {
            java.util.Arrays.fill(head, -1);
            this.shift = shift;
        }

        /** The bucket a limit is filed in. */
        public int bucket(long limit) {
            return (int) (limit >> shift) & mask;
        }

        /** Entry k's job count at {@code window}, ceil((window + J_k) / T_k), and the largest window it holds for. */
        public void count(int k, long window, long[] period, long[] jitter) {
            long x = Math.addExact(window, jitter[k]);
            jobs[k] = x / period[k] + (x % period[k] == 0 ? 0 : 1);
            limit[k] = Math.subtractExact(Math.multiplyExact(jobs[k], period[k]), jitter[k]);
        }

        /** Entry k filed in the bucket of its limit. */
        public void file(int k) {
            int b = bucket(limit[k]);
            next[k] = head[b];
            head[b] = k;
        }

        /**
         * From window {@code w} (every filed limit at or above it) to {@code window}: the entries whose limit lies
         * below the window, which lie in the buckets from w's to (window - 1)'s (a round at most), recounted; the
         * interference {@code sum} changed by their new jobs.
         */
        public long advance(long w, long window, long[] period, long[] jitter, long[] cost, long sum) {
            if (window == w) {
                return sum;
            }
            long from = w >> shift;
            long buckets = Math.min(((window - 1) >> shift) - from + 1, head.length);
            passed += buckets;
            for (long i = 0; i < buckets; i++) {
                int b = (int) (from + i) & mask;
                int k = head[b];
                head[b] = -1;
                while (k >= 0) {
                    looked++;
                    int after = next[k];
                    if (limit[k] < window) {
                        steps++;
                        long before = jobs[k];
                        count(k, window, period, jitter);
                        sum = Math.addExact(sum, Math.multiplyExact(jobs[k] - before, cost[k]));
                    }
                    file(k);
                    k = after;
                }
            }
            return sum;
        }
    }

    /**
     * The interference of a busy period's later jobs, continued from the first job's window of an
     * {@link Interference} without changing it (the next task's first job starts near where this one's
     * did): the first's buckets are read from its window on, and an entry whose count changes is taken
     * from them (marked taken) into a calendar of its own, cut as the first's, with its new count. No
     * copy of every entry: a step costs O(1) per entry whose count changes and per bucket passed.
     */
    public static final class Later {
        private final Interference first;
        private final Calendar own;
        /** The mark of the entries taken from the first since {@link #start}, and the entries taken, in order. */
        private final int[] taken;
        private int mark;
        private final int[] touched;
        private int touchedCount;
        /** The first of the first's buckets still to read (an unmasked index: the last one read may hold entries left). */
        private long firstFrom;
        /** Whether every entry is in this calendar (counted from scratch, or all taken from the first). */
        private boolean all;
        private long w = Long.MIN_VALUE;
        private long sum;
        /** Counted for {@link AnalysisCounts}, as the first's. */
        long evaluations;

        public Later(Interference first) {
            this.first = first;
            int size = first.period.length;
            this.own = new Calendar(size);
            this.taken = new int[size];
            this.touched = new int[size];
        }

        /** The calendar of the entries taken, whose counts {@link AnalysisCounts} adds up. */
        public Calendar calendar() {
            return own;
        }

        /** Empties this calendar: only the buckets of the entries it holds. */
        private void empty() {
            for (int i = 0; i < touchedCount; i++) {
                own.head[own.bucket(own.limit[touched[i]])] = -1;
            }
            touchedCount = 0;
        }

        /** From the first's present window and counts. */
        public void start() {
            empty();
            if (++mark == 0) {
                java.util.Arrays.fill(taken, 0);
                mark = 1;
            }
            w = first.w;
            sum = first.sum;
            own.shift = first.calendar.shift;
            all = w == Long.MIN_VALUE;
            firstFrom = all ? 0 : w >> own.shift;
        }

        /** The interference in a window of length {@code window}. */
        public long at(long window) {
            try {
                return advance(window);
            } catch (ArithmeticException e) {
                w = Long.MIN_VALUE;
                throw e;
            }
        }

        private void take(int k) {
            taken[k] = mark;
            touched[touchedCount++] = k;
        }

        private long advance(long window) {
            evaluations++;
            if (w == Long.MIN_VALUE || window < w) {
                // from scratch: every entry counted at the window (not met in a busy period's later jobs)
                empty();
                sum = 0;
                own.steps += first.n;
                own.shift = Calendar.shiftFor(first.rate);
                for (int k = 0; k < first.n; k++) {
                    own.count(k, window, first.period, first.jitter);
                    sum = Math.addExact(sum, Math.multiplyExact(own.jobs[k], first.cost[k]));
                    take(k);
                    own.file(k);
                }
                all = true;
                w = window;
                return sum;
            }
            if (window == w) {
                return sum;
            }
            // the entries taken before
            sum = own.advance(w, window, first.period, first.jitter, first.cost, sum);
            w = window;
            if (!all) {
                // the entries not taken yet: the first's buckets from where the last reading stopped (that bucket again) to
                // the window's, a round at most; an entry whose limit lies below the window is taken
                Calendar from = first.calendar;
                long to = (window - 1) >> from.shift;
                long last = Math.min(to, firstFrom + from.head.length - 1);
                own.passed += last - firstFrom + 1;
                for (long i = firstFrom; i <= last; i++) {
                    for (int k = from.head[(int) i & from.mask]; k >= 0; k = from.next[k]) {
                        own.looked++;
                        if (taken[k] != mark && from.limit[k] < window) {
                            own.steps++;
                            take(k);
                            own.count(k, window, first.period, first.jitter);
                            sum = Math.addExact(sum, Math.multiplyExact(own.jobs[k] - from.jobs[k], first.cost[k]));
                            own.file(k);
                        }
                    }
                }
                // the entries left lie in the window's bucket or after it (their limits are not below the window)
                firstFrom = to;
                all = touchedCount == first.n;
            }
            return sum;
        }
    }
}
