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
        int i = size++;
        while (i > 0 && heapKey[(i - 1) / 2] > limit[k]) {
            heap[i] = heap[(i - 1) / 2];
            heapKey[i] = heapKey[(i - 1) / 2];
            i = (i - 1) / 2;
        }
        heap[i] = k;
        heapKey[i] = limit[k];
    }

    /**
     * Takes the state of {@code other}, an interference over the same entries: the later jobs of a busy
     * period continue from its first job's window without moving {@code other} there and back (the next
     * task's first job starts near where this one's did), at the cost of a copy instead of a recount.
     */
    void copyFrom(Interference other) {
        if (other.period != period || other.cost != cost || other.jitter != jitter) {
            throw new IllegalArgumentException("not the same entries");
        }
        n = other.n;
        size = other.size;
        w = other.w;
        sum = other.sum;
        System.arraycopy(other.jobs, 0, jobs, 0, n);
        System.arraycopy(other.limit, 0, limit, 0, n);
        System.arraycopy(other.heap, 0, heap, 0, size);
        System.arraycopy(other.heapKey, 0, heapKey, 0, size);
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
            if (child + 1 < size && heapKey[child + 1] < heapKey[child]) {
                child++;
            }
            if (heapKey[child] >= key) {
                break;
            }
            heap[i] = heap[child];
            heapKey[i] = heapKey[child];
            i = child;
        }
        heap[i] = k;
        heapKey[i] = key;
    }
}
