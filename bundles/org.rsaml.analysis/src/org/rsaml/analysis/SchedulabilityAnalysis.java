/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.OptionalLong;
import java.util.Set;

import org.rsaml.analysis.internal.Bounds;
import org.rsaml.analysis.internal.FirstInFirstOut;
import org.rsaml.analysis.internal.MissWitnesses;
import org.rsaml.analysis.internal.NonPreemptive;
import org.rsaml.analysis.internal.PriorityLevels;
import org.rsaml.model.support.RsamlTimes;
import org.rsaml.analysis.internal.ProcessorDemand;
import org.rsaml.analysis.internal.ResponseTimes;
import org.rsaml.analysis.internal.Utilisation;

/**
 * Schedulability of the tasks of one processor, under the processor's policy. Each verdict is sound:
 * MEETS is a proof under the task model, MISSES comes with a witness, and whatever the analysis
 * cannot decide is NOT_ANALYSED with the reason.
 */
public final class SchedulabilityAnalysis {

    private SchedulabilityAnalysis() {
    }

    /**
     * @param processor the processor's name, for the result
     * @param policy    how it schedules
     * @param tasks     its tasks, with distinct names
     */
    public static ProcessorResult analyse(String processor, SchedulingPolicy policy, List<Task> tasks) {
        return analyse(processor, policy, tasks, Set.of());
    }

    /**
     * @param processor       the processor's name, for the result
     * @param policy          how it schedules
     * @param tasks           its tasks, with distinct names
     * @param runToCompletion under {@link SchedulingPolicy#FIXED_PRIORITY}, the names of the tasks whose
     *                        jobs no job of equal priority interrupts once started (threads under
     *                        SCHED_FIFO, which POSIX runs first in, first out among equal priorities);
     *                        when every task of the highest priority is one, nothing interrupts them
     *                        and they are analysed without preemption
     */
    public static ProcessorResult analyse(String processor, SchedulingPolicy policy, List<Task> tasks, Set<String> runToCompletion) {
        Set<String> names = new HashSet<>();
        for (Task t : tasks) {
            if (!names.add(t.name())) {
                throw new IllegalArgumentException("Processor '" + processor + "': two tasks are named '" + t.name() + "'");
            }
        }
        Utilisation u = new Utilisation(tasks);
        List<BoundCheck> bounds = Bounds.check(policy, tasks, u);
        if (tasks.isEmpty()) {
            return new ProcessorResult(processor, policy, List.of(), 0, bounds, Verdict.MEETS, "no tasks", null);
        }
        return switch (policy) {
            case FIXED_PRIORITY, FIXED_PRIORITY_NON_PREEMPTIVE -> fixedPriority(processor, policy, tasks, u, bounds, runToCompletion);
            case EDF -> edf(processor, tasks, u, bounds);
            default -> unanalysed(processor, policy, tasks, u, bounds);
        };
    }

    private static ProcessorResult fixedPriority(String processor, SchedulingPolicy policy, List<Task> tasks, Utilisation u,
            List<BoundCheck> bounds, Set<String> runToCompletion) {
        TaskResult[] byIndex = new TaskResult[tasks.size()];
        if (policy == SchedulingPolicy.FIXED_PRIORITY && ResponseTimes.anyBlockedByLock(tasks)) {
            lockGroups(tasks, byIndex);
        } else if (policy == SchedulingPolicy.FIXED_PRIORITY) {
            List<Integer> fifo = firstInFirstOutLevel(tasks, runToCompletion);
            preemptive(tasks, byIndex, fifo);
            firstInFirstOutAtTheTop(tasks, byIndex, fifo);
        } else {
            for (int i = 0; i < tasks.size(); i++) {
                byIndex[i] = NonPreemptive.of(tasks, tasks.get(i));
            }
        }
        scheduleTheFirstMiss(tasks, byIndex, policy, runToCompletion);
        List<TaskResult> results = List.of(byIndex);
        Verdict verdict = Verdict.MEETS;
        for (TaskResult r : results) {
            verdict = verdict.and(r.verdict());
        }
        long missed = results.stream().filter(r -> r.verdict() == Verdict.MISSES).count();
        long open = results.stream().filter(r -> r.verdict() == Verdict.NOT_ANALYSED).count();
        String method = policy == SchedulingPolicy.FIXED_PRIORITY ? "exact response-time analysis"
                : "non-preemptive response-time analysis";
        String explanation = switch (verdict) {
            case MEETS -> method + ": every task meets its deadline";
            case MISSES -> method + ": " + missed + " of " + tasks.size() + " tasks can miss their deadline";
            default -> method + ": " + open + " of " + tasks.size() + " tasks not analysed";
        };
        return new ProcessorResult(processor, policy, results, u.value, bounds, verdict, explanation, null);
    }

    /**
     * Preemptive fixed priorities without lock waits, highest priority first, the tasks that can delay
     * a task joining once as the priority falls ({@link PriorityLevels}).
     */
    private static void preemptive(List<Task> tasks, TaskResult[] byIndex, List<Integer> firstInFirstOut) {
        PriorityLevels.analyse(tasks, new HashSet<>(firstInFirstOut), byIndex);
    }

    /**
     * A critical-instant schedule costs a simulation over every task that can delay the job: only the
     * highest-priority task that misses its deadline gets one (the tasks it delays can wait for it too);
     * the others keep their summary witness, the jobs of each task that can delay them.
     */
    private static void scheduleTheFirstMiss(List<Task> tasks, TaskResult[] byIndex, SchedulingPolicy policy,
            Set<String> runToCompletion) {
        int first = -1;
        for (int i = 0; i < byIndex.length; i++) {
            if (byIndex[i].verdict() == Verdict.MISSES && byIndex[i].witness() != null
                    && (first < 0 || tasks.get(i).priority() > tasks.get(first).priority())) {
                first = i;
            }
        }
        if (first < 0) {
            return;
        }
        Task t = tasks.get(first);
        TaskResult r = byIndex[first];
        List<Task> scope = tasks;
        int effective = t.priority();
        boolean preemptive = policy == SchedulingPolicy.FIXED_PRIORITY;
        boolean fifo = false;
        if (preemptive && ResponseTimes.anyBlockedByLock(tasks)) {
            effective = ResponseTimes.effectivePriority(tasks, t);
        } else if (preemptive) {
            List<Integer> level = firstInFirstOutLevel(tasks, runToCompletion);
            if (level.contains(first)) {
                scope = level.stream().map(tasks::get).toList();
                preemptive = false;
                fifo = true;
            }
        }
        byIndex[first] = new TaskResult(r.task(), r.responseTime(), r.verdict(), r::explanation,
                MissWitnesses.schedule(scope, t, effective, r.witness().job(), preemptive, fifo));
    }

    /**
     * Tasks of equal priority delay each other; the preemptive analysis counts every job of theirs
     * released until the analysed job completes, which is sound whatever order they run in (round
     * robin included). At the highest priority, jobs that run first in, first out among their equals
     * are interrupted by nothing: a job waits only for the jobs released before or with it (lower
     * priorities are preempted, so they cannot block), which {@link FirstInFirstOut}
     * analyses exactly.
     */
    private static void firstInFirstOutAtTheTop(List<Task> tasks, TaskResult[] byIndex, List<Integer> level) {
        List<Task> equals = level.stream().map(tasks::get).toList();
        TaskResult[] results = FirstInFirstOut.of(equals);
        for (int k = 0; k < level.size(); k++) {
            int i = level.get(k);
            TaskResult r = results[k];
            byIndex[i] = new TaskResult(r.task(), r.responseTime(), r.verdict(), () -> r.explanation()
                    + " (first in, first out among the tasks of its priority, the highest: nothing interrupts it once started)",
                    r.witness());
        }
    }

    /** The indices of the tasks of the highest priority when there are several and all run first in, first out; else none. */
    private static List<Integer> firstInFirstOutLevel(List<Task> tasks, Set<String> runToCompletion) {
        int top = Integer.MIN_VALUE;
        for (Task t : tasks) {
            top = Math.max(top, t.priority());
        }
        List<Integer> level = new ArrayList<>();
        for (int i = 0; i < tasks.size(); i++) {
            if (tasks.get(i).priority() == top) {
                if (!runToCompletion.contains(tasks.get(i).name())) {
                    return List.of();
                }
                level.add(i);
            }
        }
        return level.size() < 2 ? List.of() : level;
    }

    /** Rounds of the jitter iteration for lock groups before giving up (said so). */
    private static final int MAX_ROUNDS = 1000;

    /**
     * With lock groups a task can be held back by a lower-priority lock holder and then run its
     * delayed jobs back to back: to the tasks below it, it interferes as if released with a jitter
     * of its response time minus its cost (holistic analysis, Tindell &amp; Clark 1994). Iterated
     * until the jitters settle; the response times are then upper bounds, not exact.
     */
    private static void lockGroups(List<Task> tasks, TaskResult[] byIndex) {
        int n = tasks.size();
        int[] effective = ResponseTimes.effectivePriorities(tasks);
        Task[] view = tasks.toArray(new Task[0]);
        for (int round = 0; round < MAX_ROUNDS; round++) {
            PriorityLevels.analyse(java.util.Arrays.asList(view), tasks, effective, Set.of(), byIndex);
            boolean changed = false;
            List<Integer> late = new ArrayList<>();
            for (int j = 0; j < n; j++) {
                Task t = tasks.get(j);
                if (effective[j] >= t.priority()) {
                    continue;
                }
                if (byIndex[j].responseTime().isEmpty() || byIndex[j].verdict() == Verdict.MISSES) {
                    late.add(j);
                    continue;
                }
                long jitter = Math.max(t.jitter(), byIndex[j].responseTime().getAsLong() - t.cost());
                if (jitter > view[j].jitter()) {
                    view[j] = new Task(t.name(), t.period(), t.deadline(), t.cost(), t.priority(), jitter, t.group());
                    changed = true;
                }
            }
            if (!late.isEmpty()) {
                unsettled(tasks, byIndex, effective, late);
                return;
            }
            if (!changed) {
                return;
            }
        }
        for (int i = 0; i < n; i++) {
            byIndex[i] = new TaskResult(tasks.get(i), OptionalLong.empty(), Verdict.NOT_ANALYSED, "not analysed: with the lock groups,"
                    + " the response times did not settle within " + MAX_ROUNDS + " rounds", null);
        }
    }

    /**
     * Some tasks held back by their lock can be late, so their late jobs can pile up and run back to
     * back: no bound holds for a task that one of them, or any task held back by a lock, can delay (the
     * jitters have not settled). Such a task that already misses its deadline misses it still.
     */
    private static void unsettled(List<Task> tasks, TaskResult[] byIndex, int[] effective, List<Integer> late) {
        String who = "'" + tasks.get(late.get(0)).name() + "'";
        // a task is exposed when another task held back by its lock is at or above its priority as analysed:
        // the two highest priorities of those held back tell, for every task, in one pass
        int first = -1;
        int second = -1;
        for (int j = 0; j < tasks.size(); j++) {
            if (effective[j] < tasks.get(j).priority()) {
                if (first < 0 || tasks.get(j).priority() > tasks.get(first).priority()) {
                    second = first;
                    first = j;
                } else if (second < 0 || tasks.get(j).priority() > tasks.get(second).priority()) {
                    second = j;
                }
            }
        }
        for (int i = 0; i < tasks.size(); i++) {
            int above = i != first ? first : second;
            boolean exposed = above >= 0 && tasks.get(above).priority() >= effective[i];
            if (!exposed) {
                continue;
            }
            TaskResult r = byIndex[i];
            byIndex[i] = r.verdict() == Verdict.MISSES
                    ? new TaskResult(r.task(), OptionalLong.empty(), Verdict.MISSES, () -> r.explanation()
                            + " (at least; tasks that wait for their lock groups can delay it further)", null)
                    : new TaskResult(r.task(), OptionalLong.empty(), Verdict.NOT_ANALYSED, "not analysed: " + who
                            + " can be late waiting for its lock group, and then run its late jobs back to back", null);
        }
    }

    private static ProcessorResult edf(String processor, List<Task> tasks, Utilisation u, List<BoundCheck> bounds) {
        ProcessorDemand.Outcome outcome = ProcessorDemand.decide(tasks, u);
        List<TaskResult> results = new ArrayList<>();
        if (outcome.undecided() != null) {
            for (Task t : tasks) {
                results.add(new TaskResult(t, OptionalLong.empty(), Verdict.NOT_ANALYSED, "not analysed: " + outcome.undecided(), null));
            }
            return new ProcessorResult(processor, SchedulingPolicy.EDF, results, u.value, bounds, Verdict.NOT_ANALYSED,
                    "processor-demand test not decided: " + outcome.undecided(), null);
        }
        if (outcome.feasible()) {
            for (Task t : tasks) {
                results.add(new TaskResult(t, OptionalLong.empty(), Verdict.MEETS,
                        "meets its deadline: the processor-demand test holds (response time not computed under EDF)", null));
            }
            return new ProcessorResult(processor, SchedulingPolicy.EDF, results, u.value, bounds, Verdict.MEETS,
                    "processor-demand test (QPA): every interval holds its demand, so EDF meets every deadline", null);
        }
        DemandWitness w = outcome.witness();
        for (Task t : tasks) {
            if (w != null && w.jobs().containsKey(t.name())) {
                results.add(new TaskResult(t, OptionalLong.empty(), Verdict.MISSES, "can miss its deadline: its "
                        + w.jobs().get(t.name()) + " job(s) due within the first " + RsamlTimes.text(w.interval())
                        + " are part of a demand of " + RsamlTimes.text(w.demand()) + " that does not fit", null));
            } else {
                results.add(new TaskResult(t, OptionalLong.empty(), Verdict.NOT_ANALYSED,
                        "not analysed individually: under an EDF overload any task can be late", null));
            }
        }
        return new ProcessorResult(processor, SchedulingPolicy.EDF, results, u.value, bounds, Verdict.MISSES,
                overload(u, w), w);
    }

    private static String overload(Utilisation u, DemandWitness w) {
        String head = u.versusOne() > 0 ? "utilisation " + String.format(java.util.Locale.ROOT, "%.4f", u.value) + " exceeds 1"
                : "processor-demand test (QPA) fails";
        if (w == null) {
            return head + ": no scheduler can meet every deadline";
        }
        return head + ": jobs released and due within the first " + RsamlTimes.text(w.interval()) + " need "
                + RsamlTimes.text(w.demand()) + ", so no scheduler can meet every deadline";
    }

    private static ProcessorResult unanalysed(String processor, SchedulingPolicy policy, List<Task> tasks, Utilisation u,
            List<BoundCheck> bounds) {
        // Infeasible for every scheduler is infeasible for this one: the demand test still decides misses.
        ProcessorDemand.Outcome outcome = ProcessorDemand.decide(tasks, u);
        List<TaskResult> results = new ArrayList<>();
        String reason = switch (policy) {
            case LLF -> "least laxity first: utilisation <= 1 is only necessary, and the runtime's laxity scheduling"
                    + " (its time quantum, its ties) is not modelled";
            case ROUND_ROBIN -> "round robin: the response time depends on the time slice and the order of the queue,"
                    + " which the model does not give";
            case SJF -> "shortest job first: a job can wait for ever behind shorter ones, so no bound follows from the task model";
            default -> policy.label() + ": nothing is known of how it picks jobs";
        };
        if (!outcome.feasible() && outcome.undecided() == null) {
            DemandWitness w = outcome.witness();
            for (Task t : tasks) {
                boolean involved = w != null && w.jobs().containsKey(t.name());
                results.add(new TaskResult(t, OptionalLong.empty(), involved ? Verdict.MISSES : Verdict.NOT_ANALYSED,
                        involved ? "can miss its deadline: " + overload(u, w) : "not analysed: " + reason, null));
            }
            return new ProcessorResult(processor, policy, results, u.value, bounds, Verdict.MISSES, overload(u, w), w);
        }
        for (Task t : tasks) {
            results.add(new TaskResult(t, OptionalLong.empty(), Verdict.NOT_ANALYSED, "not analysed: " + reason, null));
        }
        return new ProcessorResult(processor, policy, results, u.value, bounds, Verdict.NOT_ANALYSED,
                "not analysed: " + reason + " (the tasks pass the necessary demand test)", null);
    }
}
