/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalLong;
import java.util.PriorityQueue;
import java.util.function.Supplier;

import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.Witness;
import org.rsaml.model.support.RsamlTimes;

/**
 * A response time as a verdict, and the evidence of a miss: a summary (per task that can delay the
 * job, its jobs released from the critical instant until the job completes, the most delaying first)
 * for every task that misses, and the critical-instant schedule, which costs a simulation, for the one
 * a processor shows in full.
 */
public final class MissWitnesses {

    /** Tasks a summary witness lists by name, those that delay it most; the others are counted. */
    public static final int MAX_LISTED = 20;

    /** The most delaying first; ties in the order of the tasks ({@code [index, jobs, delay]}). */
    static final Comparator<long[]> LISTED_FIRST = (a, b) -> a[2] != b[2] ? Long.compare(b[2], a[2]) : Long.compare(a[0], b[0]);

    private MissWitnesses() {
    }

    /**
     * The verdict of a task whose worst response is {@code worst}, that of job {@code job} of its busy
     * period; on a miss, with the witness {@code summary} gives (asked for only then).
     */
    static TaskResult result(Task task, long worst, long job, Supplier<Witness> summary) {
        boolean meets = worst <= task.deadline();
        // worded when first asked for: most verdicts of a large architecture are never read
        return new TaskResult(task, OptionalLong.of(worst), meets ? Verdict.MEETS : Verdict.MISSES, () -> {
            String where = job == 0 ? "its first job after the critical instant"
                    : "job " + (job + 1) + " of its busy period (an earlier job delays it)";
            return meets
                    ? "worst-case response time " + RsamlTimes.text(worst) + " (" + where + ") within its deadline of "
                            + RsamlTimes.text(task.deadline())
                    : "worst-case response time " + RsamlTimes.text(worst) + " (" + where + ") exceeds its deadline of "
                            + RsamlTimes.text(task.deadline()) + " by " + RsamlTimes.text(worst - task.deadline());
        }, meets ? null : summary.get());
    }

    /**
     * The witness of a miss without its schedule: per interfering task of {@code hp}, its jobs released
     * from the critical instant until the job completes, the {@link #MAX_LISTED} most delaying first
     * (ties in their order), the others counted. This is the definition; {@link DelayingTasks} gives the
     * same without a pass over every task.
     */
    static Witness summary(Task task, long worst, long job, List<Task> hp, Task blocker) {
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
        // the MAX_LISTED that delay most, as a stable sort of all would list them, without sorting thousands
        PriorityQueue<long[]> kept = new PriorityQueue<>(LISTED_FIRST.reversed());
        for (long[] c : counts) {
            kept.add(c);
            if (kept.size() > MAX_LISTED) {
                kept.poll();
            }
        }
        List<long[]> top = new ArrayList<>(kept);
        top.sort(LISTED_FIRST);
        Map<String, Long> listed = new LinkedHashMap<>();
        for (long[] c : top) {
            listed.put(hp.get((int) c[0]).name(), c[1]);
        }
        return new Witness(task.name(), job, release, completion, List.of(), listed, blocker == null ? null : blocker.name(), false,
                counts.size() - listed.size());
    }

    /**
     * The critical-instant schedule of job {@code job} of the task, among the tasks of {@code scope}:
     * preemptive, everything at or above {@code effective} delaying it; or non-preemptive, everything at
     * or above its priority, after the longest lower-priority job. With {@code firstInFirstOut}
     * (non-preemptive only), equal priorities run in the order of their releases, the analysed task last
     * among those released with it.
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
}
