/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.SchedulingPolicy;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.internal.AnalysisCounts;
import org.rsaml.analysis.internal.Preemptive;
import org.rsaml.analysis.internal.PriorityLevels;
import org.rsaml.analysis.internal.ResponseTimes;

/**
 * The walk down the priority levels (the tasks that can delay a task joining once, their
 * interference, costs, utilisation and first windows carried from task to task, a miss's summary
 * drawn from a tree of them) against the exact iteration of each task over the list of the tasks that
 * can delay it, rebuilt for that task ({@link Preemptive#of(List, Task, int)}): every task's result
 * must be the same, response time, verdict, explanation and witness, on seeded random sets with many
 * distinct periods, utilisation near and above 1, tied priorities, release jitter, lock groups and a
 * first-in-first-out top rank. The number of sets and the seed are those of {@link RandomTaskSetsTest}
 * ({@code rsaml.analysis.sets}, {@code rsaml.analysis.seed}).
 */
class PriorityLevelsTest {

    private static final int SETS = Integer.getInteger("rsaml.analysis.sets", 2000);
    private static final long SEED = Long.getLong("rsaml.analysis.seed", 20260101L) + 40;

    /** Up to 60 tasks, periods from 10 to 10,000 (many distinct, some repeated), utilisation 0.5 to 1.1. */
    private static List<Task> randomSet(Random random, boolean jitter) {
        int n = 1 + random.nextInt(60);
        double target = 0.5 + 0.6 * random.nextDouble();
        int priorities = 1 + random.nextInt(random.nextBoolean() ? n : Math.max(1, n / 4)); // some sets: many ties
        long[] few = { 100, 250, 400, 1000 };
        List<Task> tasks = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            long period = random.nextInt(4) == 0 ? few[random.nextInt(few.length)] : 10 + random.nextInt(9_991);
            long cost = random.nextInt(10) == 0 ? 0 : Math.max(1, Math.min(period, (long) (target / n * period * 2 * random.nextDouble())));
            long deadline = switch (random.nextInt(3)) {
                case 0 -> period;
                case 1 -> Math.max(1, Math.max(cost, period / 2));
                default -> period * (2 + random.nextInt(3));
            };
            long j = jitter && random.nextInt(3) == 0 ? random.nextInt((int) Math.min(period, 500)) : 0;
            String group = jitter && random.nextInt(3) == 0 ? "m" + random.nextInt(4) : null;
            tasks.add(new Task("t" + i, period, deadline, cost, random.nextInt(priorities), j, group));
        }
        return tasks;
    }

    /** The per-task definition, with {@code delaying} as the others delay it and {@code task} as it is itself. */
    private static TaskResult definition(List<Task> delaying, int i, Task task, int effective) {
        List<Task> view = new ArrayList<>(delaying);
        view.set(i, task);
        return Preemptive.of(view, task, effective);
    }

    private static void assertSame(TaskResult expected, TaskResult actual, String where) {
        assertEquals(expected.responseTime(), actual.responseTime(), () -> "response time of " + where);
        assertEquals(expected.verdict(), actual.verdict(), () -> "verdict of " + where);
        assertEquals(expected.explanation(), actual.explanation(), () -> "explanation of " + where);
        assertEquals(expected.witness(), actual.witness(), () -> "witness of " + where);
    }

    /**
     * The walk itself, on random delaying views (release jitter, lock groups analysed at their lowest
     * priority, tasks skipped) against the per-task definition.
     */
    @Test
    void walkEqualsTheExactIterationOfEachTask() {
        Random random = new Random(SEED);
        int compared = 0;
        int summaries = 0;
        int overloads = 0;
        int severalJobs = 0;
        int sets = Math.max(1, SETS / 8); // an eighth: each task's definition is a pass over the set
        for (int s = 0; s < sets; s++) {
            List<Task> own = randomSet(random, s % 2 == 1);
            // as the lock-group rounds see them: some tasks delay the others with more jitter than their own
            List<Task> delaying = new ArrayList<>();
            for (Task t : own) {
                long extra = random.nextInt(5) == 0 ? random.nextInt((int) Math.min(t.period(), 300)) : 0;
                delaying.add(new Task(t.name(), t.period(), t.deadline(), t.cost(), t.priority(), t.jitter() + extra, t.group()));
            }
            int[] effective = ResponseTimes.effectivePriorities(own);
            Set<Integer> skipped = new HashSet<>();
            if (random.nextInt(4) == 0) {
                skipped.add(random.nextInt(own.size()));
            }
            TaskResult[] walked = new TaskResult[own.size()];
            PriorityLevels.analyse(delaying, own, effective, skipped, walked);
            for (int i = 0; i < own.size(); i++) {
                if (skipped.contains(i)) {
                    assertEquals(null, walked[i], "a skipped task is left to another analysis");
                    continue;
                }
                TaskResult expected = definition(delaying, i, own.get(i), effective[i]);
                assertSame(expected, walked[i], "set " + s + ", task " + own.get(i) + " (as if at " + effective[i] + ") among " + delaying);
                compared++;
                summaries += expected.witness() != null ? 1 : 0;
                overloads += expected.verdict() == Verdict.MISSES && expected.responseTime().isEmpty() ? 1 : 0;
                severalJobs += expected.explanation().contains("of its busy period") ? 1 : 0;
            }
        }
        assertTrue(compared > sets * 10, "tasks compared: " + compared);
        assertTrue(summaries > sets / 2, "misses with a summary witness: " + summaries);
        assertTrue(overloads > sets / 4, "overloaded levels: " + overloads);
        assertTrue(severalJobs > sets / 10, "worst responses later in the busy period: " + severalJobs);
    }

    /**
     * Levels of many tied tasks (at least {@link PriorityLevels#SHARED_LEVEL}, which read their windows
     * from one walk of the level's busy period) with a few tasks above and below them, release jitter,
     * lock groups and several jobs in a busy period: every task's result equals the per-task definition.
     * The level's walk answers for most of the tied tasks (counted): where it has no answer a task iterates
     * itself, which is the definition, so a walk that never answered would pass the comparison alone.
     */
    @Test
    void tiedLevelsEqualTheExactIterationOfEachTask() {
        Random random = new Random(SEED + 2);
        AnalysisCounts counts = new AnalysisCounts();
        int tied = 0;
        int severalJobs = 0;
        int sets = Math.max(1, SETS / 20);
        for (int s = 0; s < sets; s++) {
            int n = PriorityLevels.SHARED_LEVEL + random.nextInt(60);
            double target = 0.3 + 0.75 * random.nextDouble();
            List<Task> own = new ArrayList<>();
            List<Task> delaying = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                long period = random.nextInt(3) == 0 ? 100 * (1 + random.nextInt(4)) : 10 + random.nextInt(5_000);
                long cost = random.nextInt(12) == 0 ? 0 : Math.max(1, Math.min(period, (long) (target / n * period * 2 * random.nextDouble())));
                long deadline = random.nextInt(3) == 0 ? period * (1 + random.nextInt(3)) : Math.max(1, period / (1 + random.nextInt(3)));
                int priority = random.nextInt(5) == 0 ? random.nextInt(5) : 2; // most at rank 2
                long j = s % 2 == 1 && random.nextInt(3) == 0 ? random.nextInt((int) Math.min(period, 400)) : 0;
                String group = s % 2 == 1 && random.nextInt(4) == 0 ? "m" + random.nextInt(3) : null;
                Task t = new Task("t" + i, period, deadline, cost, priority, j, group);
                own.add(t);
                long extra = s % 2 == 1 && random.nextInt(5) == 0 ? random.nextInt((int) Math.min(period, 200)) : 0;
                delaying.add(new Task(t.name(), period, deadline, cost, priority, j + extra, group));
            }
            int[] effective = ResponseTimes.effectivePriorities(own);
            TaskResult[] walked = new TaskResult[n];
            counts.during(() -> {
                PriorityLevels.analyse(delaying, own, effective, Set.of(), walked);
                return null;
            });
            for (int i = 0; i < n; i++) {
                TaskResult expected = definition(delaying, i, own.get(i), effective[i]);
                assertSame(expected, walked[i], "set " + s + ", task " + own.get(i) + " (as if at " + effective[i] + ") among " + delaying);
                tied += effective[i] == 2 ? 1 : 0;
                severalJobs += expected.explanation().contains("of its busy period") ? 1 : 0;
            }
        }
        assertTrue(tied > sets * PriorityLevels.SHARED_LEVEL / 2, "tasks compared at the tied level: " + tied);
        assertTrue(severalJobs > sets / 10, "worst responses later in the busy period: " + severalJobs);
        assertTrue(counts.levelsWalked > 0 && counts.tiedDecided > 0,
                "the tied levels' walk decided no task, every one iterated itself: " + counts);
        assertTrue(counts.tiedDecided > counts.tiedIterated,
                "the tied levels' walk answered for fewer tasks than iterated themselves: " + counts);
    }

    /**
     * Through the public analysis (a first-in-first-out top rank left to its own analysis): each
     * other task's result equals the per-task definition, but the witness
     * of the processor's first miss, which gets its critical-instant schedule instead of a summary.
     */
    @Test
    void processorAnalysisEqualsTheExactIterationOfEachTask() {
        Random random = new Random(SEED + 1);
        int compared = 0;
        int sets = Math.max(1, SETS / 16);
        for (int s = 0; s < sets; s++) {
            List<Task> tasks = randomSet(random, false);
            Set<String> fifo = new HashSet<>();
            if (s % 3 == 0) {
                int top = tasks.stream().mapToInt(Task::priority).max().getAsInt();
                tasks.stream().filter(t -> t.priority() == top).forEach(t -> fifo.add(t.name()));
            }
            ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks, fifo);
            boolean fifoLevel = fifo.size() >= 2;
            for (int i = 0; i < tasks.size(); i++) {
                Task t = tasks.get(i);
                if (fifoLevel && fifo.contains(t.name())) {
                    continue; // the first-in-first-out analysis, held to its definition in RandomTaskSetsTest
                }
                TaskResult expected = Preemptive.of(tasks, t, t.priority());
                TaskResult actual = result.tasks().get(i);
                String where = "set " + s + ", task " + t + " among " + tasks;
                if (actual.witness() != null && !actual.witness().summary()) {
                    assertEquals(expected.responseTime(), actual.responseTime(), where);
                    assertEquals(expected.explanation(), actual.explanation(), where);
                    assertEquals(expected.witness().job(), actual.witness().job(), where);
                } else {
                    assertSame(expected, actual, where);
                }
                compared++;
            }
        }
        assertTrue(compared > sets * 10, "tasks compared: " + compared);
    }
}
