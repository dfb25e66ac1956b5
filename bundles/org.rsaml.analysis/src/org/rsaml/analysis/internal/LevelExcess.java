/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

/**
 * The busy period of one priority level shared by the tasks tied at that level: the level's demand
 * I(t) = sum_k ceil((t + J_k) / T_k) C_k over every task at or above it (the tied tasks included), from
 * the critical instant to the end of the level's busy period L (the least t &gt; 0 with I(t) = t), as
 * pieces between releases, with a tree of the minimum of I(t) - t over the pieces.
 * <p>
 * A tied task i's job q completes at the least t &ge; s with (q + 1) C_i + I(t) - ceil((t + J_i) / T_i) C_i
 * &le; t (its own jobs taken out of the level's demand), where s is where its iteration starts: the fixed
 * point that iteration reaches. Between two releases of task i that is I(t) - t &le; d for a constant d, which
 * the tree answers in O(log p) for p pieces. So every tied task reads the one walk of the level instead of
 * walking the interference of the whole busy period itself (n tied tasks: O(p log p + sum_i Q_i log p) for
 * Q_i jobs of task i, instead of O(n p)). Where the answer would lie beyond L (a start above the
 * least fixed point) it says so ({@link #UNKNOWN}) and the task iterates itself.
 */
final class LevelExcess {

    /** No answer within the level's busy period. */
    static final long UNKNOWN = -1;

    /** At most this many releases within the busy period are kept (else {@link #of} gives none). */
    static final int MAX_PIECES = 4_000_000;

    /** Piece p is (left[p], left[p + 1]] (the last one ends at {@code end}); the demand is constant on it. */
    private final long[] left;
    private final long[] demand;
    private final long end;
    private final int pieces;
    /** Minimum over each node's pieces of demand - (right end), the least value of I(t) - t on them. */
    private final long[] tree;
    private final int leaves;

    private LevelExcess(long[] left, long[] demand, int pieces, long end) {
        this.left = left;
        this.demand = demand;
        this.pieces = pieces;
        this.end = end;
        int size = 1;
        while (size < pieces) {
            size <<= 1;
        }
        leaves = size;
        tree = new long[2 * size];
        java.util.Arrays.fill(tree, Long.MAX_VALUE);
        for (int p = 0; p < pieces; p++) {
            tree[size + p] = demand[p] - right(p);
        }
        for (int v = size - 1; v >= 1; v--) {
            tree[v] = Math.min(tree[2 * v], tree[2 * v + 1]);
        }
    }

    private long right(int p) {
        return p + 1 < pieces ? left[p + 1] : end;
    }

    /**
     * The level of the first {@code n} entries (period, cost, jitter): every task at or above it, the
     * tied ones included, with their full costs. None (null) when its busy period has no end within reach
     * (utilisation not clearly below 1), holds more than {@link #MAX_PIECES} releases, or its figures come
     * near the range of a long.
     */
    static LevelExcess of(long[] period, long[] cost, long[] jitter, int n, double utilisation) {
        if (!(utilisation < 1 - 1e-6) || n == 0) {
            return null;
        }
        try {
            long demand0 = 0;
            double rate = 0;
            double spread = 0;
            long maxTerm = 0;
            for (int k = 0; k < n; k++) {
                if (period[k] <= 0 || jitter[k] < 0 || cost[k] < 0) {
                    return null;
                }
                demand0 = Math.addExact(demand0, Math.multiplyExact(jitter[k] / period[k] + 1, cost[k]));
                rate += 1.0 / period[k];
                spread += (double) jitter[k] / period[k] + 1;
                maxTerm = Math.max(maxTerm, Math.max(period[k], jitter[k]));
            }
            if (demand0 == 0) {
                return null;
            }
            // the busy period: the least fixed point of I, iterated from the demand at 0+ (I's value
            // there, a lower bound), stopped once the releases it holds could pass the limit
            Interference demand = new Interference(period, cost, jitter, n);
            long t = demand0;
            while (true) {
                if (t * rate + spread > MAX_PIECES || t > Long.MAX_VALUE / 8 || maxTerm > Long.MAX_VALUE / 8) {
                    return null;
                }
                long next = demand.at(t);
                if (next == t) {
                    break;
                }
                if (next < t) {
                    return null; // cannot happen for a nondecreasing I iterated from below
                }
                t = next;
            }
            long end = t;
            // the releases in (0, end), merged by time: each entry's next release in a heap
            int[] heap = new int[n];
            long[] next = new long[n];
            int size = 0;
            for (int k = 0; k < n; k++) {
                if (cost[k] == 0) {
                    continue;
                }
                next[k] = Math.subtractExact(Math.multiplyExact(jitter[k] / period[k] + 1, period[k]), jitter[k]);
                if (next[k] < end) {
                    heap[size] = k;
                    up(heap, next, size++);
                }
            }
            long[] left = new long[1024];
            long[] level = new long[1024];
            int pieces = 1;
            left[0] = 0;
            level[0] = demand0;
            long current = demand0;
            long events = 0;
            while (size > 0) {
                if (++events > MAX_PIECES) {
                    return null;
                }
                int k = heap[0];
                long at = next[k];
                current = Math.addExact(current, cost[k]);
                next[k] = Math.addExact(at, period[k]);
                if (next[k] >= end) {
                    heap[0] = heap[--size];
                }
                down(heap, next, size, 0);
                if (left[pieces - 1] == at) {
                    level[pieces - 1] = current;
                    continue;
                }
                if (pieces == MAX_PIECES) {
                    return null;
                }
                if (pieces == left.length) {
                    int grown = (int) Math.min(MAX_PIECES, 2L * pieces);
                    left = java.util.Arrays.copyOf(left, grown);
                    level = java.util.Arrays.copyOf(level, grown);
                }
                left[pieces] = at;
                level[pieces++] = current;
            }
            if (current != end) {
                return null; // the last piece's demand is I(end) = end
            }
            return new LevelExcess(left, level, pieces, end);
        } catch (ArithmeticException e) {
            return null;
        }
    }

    private static void up(int[] heap, long[] key, int i) {
        int k = heap[i];
        while (i > 0 && key[heap[(i - 1) / 2]] > key[k]) {
            heap[i] = heap[(i - 1) / 2];
            i = (i - 1) / 2;
        }
        heap[i] = k;
    }

    private static void down(int[] heap, long[] key, int size, int i) {
        if (size == 0) {
            return;
        }
        int k = heap[i];
        while (true) {
            int child = 2 * i + 1;
            if (child >= size) {
                break;
            }
            if (child + 1 < size && key[heap[child + 1]] < key[heap[child]]) {
                child++;
            }
            if (key[heap[child]] >= key[k]) {
                break;
            }
            heap[i] = heap[child];
            i = child;
        }
        heap[i] = k;
    }

    /** The least t &ge; {@code from}, t in (0, end], with I(t) - t &le; {@code d}; else {@link #UNKNOWN}. */
    long firstAtMost(long from, long d) {
        if (from <= 0 || from > end) {
            return UNKNOWN;
        }
        // the piece holding from: the last whose left end lies below it
        int lo = 0;
        int hi = pieces - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (left[mid] < from) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        long t = Math.max(from, demand[lo] - d);
        if (t <= right(lo)) {
            return t;
        }
        int p = firstFrom(lo + 1, d);
        return p < 0 ? UNKNOWN : Math.max(left[p] + 1, demand[p] - d);
    }

    /** The first piece at or after {@code from} whose least I(t) - t is at most {@code d}, or -1. */
    private int firstFrom(int from, long d) {
        if (from >= pieces) {
            return -1;
        }
        // climb from the leaf while the subtrees to the right of the path hold nothing
        int v = leaves + from;
        if (tree[v] <= d) {
            return from;
        }
        while (true) {
            // move to the next subtree to the right
            while ((v & 1) == 1) {
                v >>= 1;
                if (v == 0) {
                    return -1;
                }
            }
            v++;
            if (tree[v] <= d) {
                break;
            }
        }
        while (v < leaves) {
            v = tree[2 * v] <= d ? 2 * v : 2 * v + 1;
        }
        return v - leaves < pieces ? v - leaves : -1;
    }

    /** The level as the tied task whose own jobs in it have this period, jitter and cost sees it. */
    Tied of(long period, long jitter, long removed) {
        return new Tied(period, jitter, removed);
    }

    /** The level seen by one of its tied tasks. */
    final class Tied {
        private final long period;
        private final long jitter;
        private final long removed;
        /** Whether every window asked for was found in the level's walk (else the task iterated itself). */
        boolean answered = true;

        private Tied(long period, long jitter, long removed) {
            this.period = period;
            this.jitter = jitter;
            this.removed = removed;
        }

        /** {@link LevelExcess#window} of this task. */
        long window(long q, long own, long start) {
            long w = LevelExcess.this.window(q, own, start, period, jitter, removed);
            answered &= w != UNKNOWN;
            return w;
        }
    }

    /**
     * Job {@code q}'s window of a tied task (cost {@code own} per job, its iteration starting at {@code start}),
     * whose own jobs in the level's demand have period {@code period}, jitter {@code jitter} and cost
     * {@code removed}: the least t &ge; start with (q + 1) own + I(t) - ceil((t + jitter) / period) removed &le; t;
     * else {@link #UNKNOWN}.
     */
    long window(long q, long own, long start, long period, long jitter, long removed) {
        long t = start;
        long jobs = Math.multiplyExact(q + 1, own);
        while (t > 0 && t <= end) {
            long x = Math.addExact(t, jitter);
            long count = x / period + (x % period == 0 ? 0 : 1);
            long segmentEnd = Math.subtractExact(Math.multiplyExact(count, period), jitter);
            long found = firstAtMost(t, Math.subtractExact(Math.multiplyExact(count, removed), jobs));
            if (found == UNKNOWN) {
                return UNKNOWN;
            }
            if (found <= segmentEnd) {
                return found;
            }
            t = segmentEnd + 1;
        }
        return UNKNOWN;
    }

    /** The releases (pieces of constant demand) of the level's busy period. */
    int pieces() {
        return pieces;
    }

    /** The end of the level's busy period. */
    long end() {
        return end;
    }
}
