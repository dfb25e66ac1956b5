/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;

import org.rsaml.analysis.Task;
import org.rsaml.analysis.Witness;

/**
 * The tasks that can delay the tasks of a processor as a walk down the priority levels meets them:
 * they join highest priority first and stay, one prefix shared by every task below instead of a list
 * built per task. It gives a miss's summary witness ({@link MissWitnesses#summary}, which passes over
 * every task that can delay the job) from a tree instead: the tasks sorted by period, each node
 * holding the largest cost and jitter of the tasks joined below it, so that a node bounds the delay
 * ceil((t + J) / T) C of every task below it at a completion t. A best-first search then finds the
 * {@link MissWitnesses#MAX_LISTED} most delaying tasks opening only the nodes whose bound can reach
 * them: O(log n) per task that joins, and per summary the nodes whose bound is not below the delays
 * listed, instead of O(n).
 */
final class DelayingTasks {

    /** Larger times fall back on the definition, whose arithmetic says when they are too large. */
    private static final long LIMIT = Long.MAX_VALUE / 4;

    private final List<Task> tasks;
    /** Leaves: a power of two, at least the number of tasks. */
    private final int leaves;
    /** The tree's leaf of each task (its rank by period, ties by index). */
    private final int[] leafOf;
    /** The task at each leaf, or -1. */
    private final int[] taskAt;
    /** Per node: the shortest period below it, of every task, joined or not (a bound for those joined). */
    private final long[] minPeriod;
    /** Per node: the largest cost of the joined tasks with a cost below it, 0 when none. */
    private final long[] maxCost;
    /** Per node: the largest jitter of those tasks. */
    private final long[] maxJitter;
    /** Per node: the largest utilisation C / T of those tasks, rounded up. */
    private final double[] maxUtilisation;
    private final List<Integer> joined = new ArrayList<>();
    private int withCost;
    private long longestPeriod;
    /** Counted for {@link AnalysisCounts}: summaries given from the tree, and the nodes their searches opened. */
    long summaries;
    long opened;

    /** Over {@code tasks}, none joined yet; their jitters are those the summaries count. */
    DelayingTasks(List<Task> tasks) {
        this.tasks = tasks;
        int n = tasks.size();
        int l = 1;
        while (l < n) {
            l <<= 1;
        }
        leaves = l;
        Integer[] byPeriod = new Integer[n];
        for (int i = 0; i < n; i++) {
            byPeriod[i] = i;
        }
        java.util.Arrays.sort(byPeriod, (a, b) -> Long.compare(tasks.get(a).period(), tasks.get(b).period()));
        leafOf = new int[n];
        taskAt = new int[leaves];
        java.util.Arrays.fill(taskAt, -1);
        minPeriod = new long[2 * leaves];
        java.util.Arrays.fill(minPeriod, Long.MAX_VALUE);
        maxCost = new long[2 * leaves];
        maxJitter = new long[2 * leaves];
        maxUtilisation = new double[2 * leaves];
        for (int r = 0; r < n; r++) {
            leafOf[byPeriod[r]] = r;
            taskAt[r] = byPeriod[r];
            minPeriod[leaves + r] = tasks.get(byPeriod[r]).period();
            longestPeriod = Math.max(longestPeriod, tasks.get(byPeriod[r]).period());
        }
        for (int v = leaves - 1; v >= 1; v--) {
            minPeriod[v] = Math.min(minPeriod[2 * v], minPeriod[2 * v + 1]);
        }
    }

    /** Task {@code i} (an index into the tasks) can delay every task analysed from now on. */
    void join(int i) {
        joined.add(i);
        Task t = tasks.get(i);
        if (t.cost() == 0) {
            return; // delays nothing
        }
        withCost++;
        int v = leaves + leafOf[i];
        maxCost[v] = t.cost();
        maxJitter[v] = t.jitter();
        maxUtilisation[v] = Math.nextUp((double) t.cost() / t.period());
        for (v >>= 1; v >= 1; v >>= 1) {
            maxCost[v] = Math.max(maxCost[2 * v], maxCost[2 * v + 1]);
            maxJitter[v] = Math.max(maxJitter[2 * v], maxJitter[2 * v + 1]);
            maxUtilisation[v] = Math.max(maxUtilisation[2 * v], maxUtilisation[2 * v + 1]);
        }
    }

    /** The tasks joined so far but {@code self}, in the order of the tasks (a pass over them). */
    List<Task> joinedBut(int self) {
        List<Task> hp = new ArrayList<>();
        for (int i : joined.stream().sorted().toList()) {
            if (i != self) {
                hp.add(tasks.get(i));
            }
        }
        return hp;
    }

    /**
     * {@link MissWitnesses#summary} of task {@code self} (with the analysed task's values {@code task})
     * among the tasks joined but itself, equal to it (same tasks listed, same jobs, same order, same
     * count of the others).
     */
    Witness summary(Task task, int self, long worst, long job) {
        long release = Arith.mul(task.period(), job);
        long completion = Arith.add(release, worst - task.jitter());
        if (completion <= 0 || completion > LIMIT || maxJitter[1] > LIMIT || longestPeriod > LIMIT) {
            return MissWitnesses.summary(task, worst, job, joinedBut(self), null);
        }
        // best first: the largest bound; at equal bounds a node before a task (it may hold an equal delay
        // of an earlier task), and tasks in their order, as the definition lists ties
        PriorityQueue<long[]> open = new PriorityQueue<>((a, b) -> a[0] != b[0] ? Long.compare(b[0], a[0])
                : a[1] != b[1] ? Long.compare(a[1], b[1]) : Long.compare(a[2], b[2]));
        summaries++;
        open.add(new long[] { bound(1, completion), 0, 1 }); // {bound, 0: node 1: task, node or task index}
        Map<String, Long> listed = new LinkedHashMap<>();
        while (!open.isEmpty() && listed.size() < MissWitnesses.MAX_LISTED) {
            long[] e = open.poll();
            if (e[0] <= 0) {
                break; // nothing left with a cost
            }
            if (e[1] == 1) {
                Task t = tasks.get((int) e[2]);
                listed.put(t.name(), Arith.ceilDiv(Arith.add(completion, t.jitter()), t.period()));
                continue;
            }
            int v = (int) e[2];
            opened++;
            if (v >= leaves) {
                int i = taskAt[v - leaves];
                if (i != self && i >= 0 && maxCost[v] > 0) {
                    Task t = tasks.get(i);
                    long jobs = Arith.ceilDiv(Arith.add(completion, t.jitter()), t.period());
                    open.add(new long[] { Arith.mul(jobs, t.cost()), 1, i });
                }
                continue;
            }
            for (int c = 2 * v; c <= 2 * v + 1; c++) {
                if (maxCost[c] > 0) {
                    open.add(new long[] { bound(c, completion), 0, c });
                }
            }
        }
        int others = withCost - (self >= 0 && tasks.get(self).cost() > 0 && maxCost[leaves + leafOf[self]] > 0 ? 1 : 0);
        return new Witness(task.name(), job, release, completion, List.of(), listed, null, false, others - listed.size());
    }

    /**
     * At least the delay ceil((t + J) / T) C of every joined task below node v at completion t: the
     * smaller of ceil((t + J_max) / T_min) C_max and U_max (t + J_max) + C_max (every count is at most
     * (t + J) / T + 1), saturated rather than overflowing.
     */
    private long bound(int v, long t) {
        long x = t + maxJitter[v];
        long jobs = x / minPeriod[v] + 1;
        long byCount = jobs > Long.MAX_VALUE / maxCost[v] ? Long.MAX_VALUE : jobs * maxCost[v];
        double share = maxUtilisation[v] * (double) x * (1 + 1e-9) + 1;
        long byShare = share >= 0x1p62 ? Long.MAX_VALUE : (long) Math.ceil(share) + maxCost[v];
        return Math.min(byCount, byShare);
    }
}
