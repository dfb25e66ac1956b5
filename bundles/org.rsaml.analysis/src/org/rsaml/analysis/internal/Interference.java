/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

/**
 * The interference sum_k ceil((w + J_k) / T_k) C_k of the entries, kept up to date as w grows:
 * each entry waits in a heap, keyed by the largest w its job count holds for, so a step touches
 * only the entries whose count changes (O(log n) each), not every entry. Over a whole busy
 * period that is one heap operation per interfering job released in it, instead of one pass over
 * all entries per step. Entries can be added and their costs changed while it is in use (a caller
 * walking down the priority levels keeps one for all its tasks, whose windows mostly grow from task
 * to task too); should w ever fall, the counts are recomputed from scratch.
 */
final class Interference {
    private final long[] period;
    private final long[] cost;
    private final long[] jitter;
    private int n;
    private final long[] jobs;
    /** The entry's count holds while w &lt;= limit: ceil((w + J) / T) = jobs. */
    private final long[] limit;
    private final int[] heap;
    /** The key of each heap place, {@code limit[heap[i]]}, kept beside it: the sifts read no other array. */
    private final long[] heapKey;
    private int size;
    private long w = Long.MIN_VALUE;
    private long sum;
    /** Counted for {@link AnalysisCounts}: evaluations at a window, and heap steps (entries recounted). */
    long evaluations;
    long steps;

    /** Over the first {@code n} entries of the arrays, which may grow up to their length through {@link #add}. */
    public Interference(long[] period, long[] cost, long[] jitter, int n) {
        this.period = period;
        this.cost = cost;
        this.jitter = jitter;
        this.n = n;
        this.jobs = new long[period.length];
        this.limit = new long[period.length];
        this.heap = new int[period.length];
        this.heapKey = new long[period.length];
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
        up(heapKey, heap, size++, limit[k], k);
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
        evaluations++;
        if (window < w) {
            w = Long.MIN_VALUE;
        }
        if (w == Long.MIN_VALUE) {
            sum = 0;
            size = 0;
            steps += n;
            for (int k = 0; k < n; k++) {
                count(k, window);
                sum = Math.addExact(sum, Math.multiplyExact(jobs[k], cost[k]));
                heap[size] = k;
                heapKey[size++] = limit[k];
            }
            for (int i = size / 2 - 1; i >= 0; i--) {
                down(i);
            }
            w = window;
            return sum;
        }
        w = window;
        while (size > 0 && heapKey[0] < window) {
            steps++;
            int k = heap[0];
            long before = jobs[k];
            count(k, window);
            sum = Math.addExact(sum, Math.multiplyExact(jobs[k] - before, cost[k]));
            down(0);
        }
        return sum;
    }

    /** The entry at place {@code i}, whose limit has grown, moved down to where its new key belongs. */
    private void down(int i) {
        int k = heap[i];
        down(heapKey, heap, size, i, limit[k], k);
    }

    /**
     * Puts {@code (key, item)} into the hole at place {@code i} of the min-heap {@code keys}/{@code items}
     * of {@code size} places, moving smaller children up until it fits.
     */
    static void down(long[] keys, int[] items, int size, int i, long key, int item) {
        while (true) {
            int child = 2 * i + 1;
            if (child >= size) {
                break;
            }
            if (child + 1 < size && keys[child + 1] < keys[child]) {
                child++;
            }
            if (keys[child] >= key) {
                break;
            }
            keys[i] = keys[child];
            items[i] = items[child];
            i = child;
        }
        keys[i] = key;
        items[i] = item;
    }

    /**
     * Puts {@code (key, item)} into the hole at place {@code i} (the heap's new last place) of the min-heap
     * {@code keys}/{@code items}, moving larger parents down until it fits.
     */
    static void up(long[] keys, int[] items, int i, long key, int item) {
        while (i > 0 && keys[(i - 1) / 2] > key) {
            keys[i] = keys[(i - 1) / 2];
            items[i] = items[(i - 1) / 2];
            i = (i - 1) / 2;
        }
        keys[i] = key;
        items[i] = item;
    }

    /**
     * The interference of a busy period's later jobs, continued from the first job's window of an
     * {@link Interference} without changing it (the next task's first job starts near where this one's
     * did): the entries whose counts change are taken from the first's heap as a tree, smallest first
     * (a place's children join a small heap of their own once the place is taken), and go on in that
     * small heap with their new counts. No copy of every entry: a step costs O(log s) for the s entries
     * the later jobs have touched.
     */
    static final class Later {
        private final Interference first;
        private final long[] jobs;
        private final long[] limit;
        /** The small heap: keys, and items (a place of the first's heap, or -(entry + 1)). */
        private long[] key = new long[64];
        private int[] item = new int[64];
        private int size;
        private long w = Long.MIN_VALUE;
        private long sum;
        /** Counted for {@link AnalysisCounts}, as the first's. */
        long evaluations;
        long steps;

        Later(Interference first) {
            this.first = first;
            this.jobs = new long[first.period.length];
            this.limit = new long[first.period.length];
        }

        /** From the first's present window and counts. */
        void start() {
            size = 0;
            w = first.w;
            sum = first.sum;
            if (w != Long.MIN_VALUE && first.size > 0) {
                push(first.heapKey[0], 0);
            }
        }

        /** The interference in a window of length {@code window}. */
        long at(long window) {
            try {
                return advance(window);
            } catch (ArithmeticException e) {
                w = Long.MIN_VALUE;
                throw e;
            }
        }

        private long advance(long window) {
            evaluations++;
            if (w == Long.MIN_VALUE || window < w) {
                // from scratch: every entry counted at the window (not met in a busy period's later jobs)
                size = 0;
                sum = 0;
                steps += first.n;
                for (int k = 0; k < first.n; k++) {
                    count(k, window);
                    sum = Math.addExact(sum, Math.multiplyExact(jobs[k], first.cost[k]));
                    push(limit[k], -(k + 1));
                }
                w = window;
                return sum;
            }
            w = window;
            while (size > 0 && key[0] < window) {
                steps++;
                int it = item[0];
                pop();
                int k;
                long before;
                if (it >= 0) {
                    // a place of the first's heap: its entry not yet touched here, its children next
                    k = first.heap[it];
                    before = first.jobs[k];
                    int child = 2 * it + 1;
                    if (child < first.size) {
                        push(first.heapKey[child], child);
                    }
                    if (child + 1 < first.size) {
                        push(first.heapKey[child + 1], child + 1);
                    }
                } else {
                    k = -it - 1;
                    before = jobs[k];
                }
                count(k, window);
                sum = Math.addExact(sum, Math.multiplyExact(jobs[k] - before, first.cost[k]));
                push(limit[k], -(k + 1));
            }
            return sum;
        }

        private void count(int k, long window) {
            long x = Math.addExact(window, first.jitter[k]);
            jobs[k] = x / first.period[k] + (x % first.period[k] == 0 ? 0 : 1);
            limit[k] = Math.subtractExact(Math.multiplyExact(jobs[k], first.period[k]), first.jitter[k]);
        }

        private void push(long k, int it) {
            if (size == key.length) {
                key = java.util.Arrays.copyOf(key, 2 * size);
                item = java.util.Arrays.copyOf(item, 2 * size);
            }
            up(key, item, size++, k, it);
        }

        private void pop() {
            size--;
            if (size == 0) {
                return;
            }
            down(key, item, size, 0, key[size], item[size]);
        }
    }
}
