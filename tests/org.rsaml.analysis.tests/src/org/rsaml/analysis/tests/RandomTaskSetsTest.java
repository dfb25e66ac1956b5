/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.SchedulingPolicy;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Verdict;

/**
 * The analysis against an independent simulation on random synchronous periodic task sets. The number
 * of sets and the seed come from the system properties {@code rsaml.analysis.sets} (default 2000) and
 * {@code rsaml.analysis.seed}; for a longer run:
 * {@code ./mvnw -o -pl tests/org.rsaml.analysis.tests -am verify -Drsaml.analysis.sets=100000 -Drsaml.analysis.seed=42}.
 */
class RandomTaskSetsTest {

    /** Periods divide 240, so a hyperperiod holds at most 240 time units. */
    private static final long[] PERIODS = { 2, 3, 4, 5, 6, 8, 10, 12, 15, 16, 20, 24, 30, 40, 48, 60, 80, 120, 240 };
    private static final long[] SCALES = { 1, 1_000, 1_000_000 };

    private static final int SETS = Integer.getInteger("rsaml.analysis.sets", 2000);
    private static final long SEED = Long.getLong("rsaml.analysis.seed", 20260101L);

    private enum Deadlines { IMPLICIT, CONSTRAINED, ARBITRARY }

    /** A random set with utilisation at most 1, distinct priorities in random order (not always monotonic). */
    private static List<Task> randomSet(Random random, Deadlines kind) {
        while (true) {
            int n = 1 + random.nextInt(6);
            long scale = SCALES[random.nextInt(SCALES.length)];
            double target = 0.3 + 0.7 * random.nextDouble();
            List<Integer> priorities = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                priorities.add(i);
            }
            Collections.shuffle(priorities, random);
            boolean monotonic = random.nextBoolean();
            List<Task> tasks = new ArrayList<>();
            double left = target;
            for (int i = 0; i < n; i++) {
                long period = PERIODS[random.nextInt(PERIODS.length)];
                double share = i == n - 1 ? left : left * random.nextDouble();
                left -= share;
                long cost = Math.max(1, Math.round(share * period));
                if (cost > period) {
                    cost = period;
                }
                long deadline = switch (kind) {
                    case IMPLICIT -> period;
                    case CONSTRAINED -> cost + (long) (random.nextDouble() * (period - cost + 1));
                    case ARBITRARY -> cost + (long) (random.nextDouble() * (3 * period - cost + 1));
                };
                deadline = Math.max(deadline, 1);
                tasks.add(new Task("t" + i, period * scale, deadline * scale, cost * scale, priorities.get(i)));
            }
            if (monotonic) {
                // deadline monotonic, ties by index
                List<Task> sorted = new ArrayList<>(tasks);
                sorted.sort((a, b) -> Long.compare(b.deadline(), a.deadline()));
                List<Task> ranked = new ArrayList<>();
                for (Task t : tasks) {
                    ranked.add(new Task(t.name(), t.period(), t.deadline(), t.cost(), sorted.indexOf(t)));
                }
                tasks = ranked;
            }
            long num = 0;
            long h = Simulator.hyperperiod(tasks);
            for (Task t : tasks) {
                num += t.cost() * (h / t.period());
            }
            if (num <= h) {
                return tasks;
            }
        }
    }

    private static void fixedPriorityAgreesWithSimulation(Deadlines kind, long seed) {
        Random random = new Random(seed);
        int misses = 0;
        for (int s = 0; s < SETS; s++) {
            List<Task> tasks = randomSet(random, kind);
            ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks);
            long[] simulated = Simulator.worstResponses(tasks, Simulator.Mode.FIXED_PRIORITY, Simulator.hyperperiod(tasks));
            boolean simMiss = false;
            for (int i = 0; i < tasks.size(); i++) {
                TaskResult r = result.tasks().get(i);
                if (r.responseTime().isEmpty() || r.responseTime().getAsLong() != simulated[i]) {
                    fail("set " + s + " (seed " + seed + "), " + kind + ", task " + tasks.get(i) + ": analysis " + r.responseTime()
                            + ", simulation " + simulated[i] + "; tasks " + tasks);
                }
                simMiss |= simulated[i] > tasks.get(i).deadline();
                assertEquals(simulated[i] > tasks.get(i).deadline() ? Verdict.MISSES : Verdict.MEETS, r.verdict(), "set " + s + " task " + tasks.get(i).name() + ": the verdict agrees with the simulated worst response " + simulated[i]);
            }
            assertEquals(simMiss ? Verdict.MISSES : Verdict.MEETS, result.verdict(), "set " + s + ": the processor's verdict agrees with the simulation");
            misses += simMiss ? 1 : 0;
        }
        // both outcomes must occur, or the comparison shows little
        assertTrue(misses > SETS / 20 && misses < SETS - SETS / 20, misses + " of " + SETS + " sets miss");
    }

    @Test
    void fixedPriorityConstrainedDeadlinesEqualSimulation() {
        fixedPriorityAgreesWithSimulation(Deadlines.CONSTRAINED, SEED);
    }

    @Test
    void fixedPriorityArbitraryDeadlinesEqualSimulation() {
        fixedPriorityAgreesWithSimulation(Deadlines.ARBITRARY, SEED + 1);
    }

    @Test
    void fixedPriorityImplicitDeadlinesEqualSimulation() {
        fixedPriorityAgreesWithSimulation(Deadlines.IMPLICIT, SEED + 2);
    }

    @Test
    void edfDemandTestEqualsSimulation() {
        for (Deadlines kind : Deadlines.values()) {
            Random random = new Random(SEED + 10 + kind.ordinal());
            int misses = 0;
            for (int s = 0; s < SETS; s++) {
                List<Task> tasks = randomSet(random, kind);
                ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.EDF, tasks);
                long[] simulated = Simulator.worstResponses(tasks, Simulator.Mode.EDF, Simulator.hyperperiod(tasks));
                boolean simMiss = false;
                for (int i = 0; i < tasks.size(); i++) {
                    simMiss |= simulated[i] > tasks.get(i).deadline();
                }
                misses += simMiss ? 1 : 0;
                if ((result.verdict() == Verdict.MISSES) != simMiss || result.verdict() == Verdict.NOT_ANALYSED) {
                    fail("set " + s + ", " + kind + ": analysis " + result.verdict() + " (" + result.explanation() + "), simulation "
                            + (simMiss ? "misses" : "meets") + "; tasks " + tasks);
                }
                if (simMiss) {
                    // the witness interval really is overloaded
                    assertTrue(result.demand().demand() > result.demand().interval(), result.demand().toString());
                }
            }
            if (kind != Deadlines.IMPLICIT) {
                assertTrue(misses > 0, kind + ": no set misses, the comparison shows little");
            } else {
                assertEquals(0, misses, "EDF with deadlines equal to periods and U <= 1 never misses");
            }
        }
    }

    /**
     * Releases of one module share its lock without priority inheritance: the analysis at the group's
     * lowest priority is an upper bound, so no simulated response exceeds it.
     */
    @Test
    void lockGroupsBoundSimulation() {
        Random random = new Random(SEED + 30);
        int grouped = 0;
        // a quarter of the sets: near full load, lock groups make busy periods long to iterate
        int sets = Math.max(1, SETS / 4);
        for (int s = 0; s < sets; s++) {
            List<Task> tasks = new ArrayList<>();
            for (Task t : randomSet(random, Deadlines.ARBITRARY)) {
                String group = random.nextInt(3) == 0 ? null : "m" + random.nextInt(2);
                tasks.add(new Task(t.name(), t.period(), t.deadline(), t.cost(), t.priority(), 0, group));
            }
            ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks);
            long[] simulated = Simulator.worstResponses(tasks, Simulator.Mode.FIXED_PRIORITY, Simulator.hyperperiod(tasks));
            for (int i = 0; i < tasks.size(); i++) {
                TaskResult r = result.tasks().get(i);
                if (r.responseTime().isPresent()) {
                    assertTrue(simulated[i] <= r.responseTime().getAsLong(), "set " + s + " task " + tasks.get(i) + ": simulated "
                            + simulated[i] + " > bound " + r.responseTime() + "; tasks " + tasks);
                    grouped += tasks.get(i).group() != null && simulated[i] > tasks.get(i).cost() ? 1 : 0;
                } else {
                    assertTrue(r.verdict() != Verdict.MEETS, r.explanation());
                }
                if (r.verdict() == Verdict.MEETS) {
                    assertTrue(simulated[i] <= tasks.get(i).deadline(), "set " + s + " task " + tasks.get(i).name() + ": a task the analysis says meets never misses in the simulation (" + simulated[i] + ")");
                }
            }
        }
        assertTrue(grouped > sets / 10, "too few grouped tasks were delayed: " + grouped);
    }

    /**
     * The runtime's SCHED_FIFO threads: higher priorities preempt, equal ones run first in, first out
     * (the simulator's fixed-priority mode, which breaks ties by release). With priorities that tie
     * (a third of the sets at one priority), the analysis, non-preemptive at the highest priority,
     * bounds the simulation.
     */
    @Test
    void firstInFirstOutAmongEqualsBoundsSimulation() {
        Random random = new Random(SEED + 30);
        for (int s = 0; s < SETS; s++) {
            boolean oneRank = random.nextInt(3) == 0;
            List<Task> tasks = new ArrayList<>();
            for (Task t : randomSet(random, Deadlines.ARBITRARY)) {
                tasks.add(new Task(t.name(), t.period(), t.deadline(), t.cost(), oneRank ? 1 : t.priority() / 2));
            }
            java.util.Set<String> fifo = new java.util.HashSet<>();
            tasks.forEach(t -> fifo.add(t.name()));
            ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks, fifo);
            long[] simulated = Simulator.worstResponses(tasks, Simulator.Mode.FIXED_PRIORITY, Simulator.hyperperiod(tasks));
            assertBoundsSimulation(s, tasks, result, simulated);
        }
    }

    /**
     * One rank, every task first in, first out (the runtime's SCHED_FIFO threads of one priority): a
     * job waits only for the jobs released before or with it, and the analysis is exact. For every
     * task, the simulation in which it comes last among the jobs released with it (the simulator
     * breaks ties by position, so it is moved to the end) reaches the analysed response exactly.
     */
    @Test
    void firstInFirstOutAtOneRankEqualsSimulation() {
        Random random = new Random(SEED + 31);
        int compared = 0;
        for (int s = 0; s < SETS / 2; s++) {
            List<Task> tasks = new ArrayList<>();
            for (Task t : randomSet(random, Deadlines.ARBITRARY)) {
                tasks.add(new Task(t.name(), t.period(), t.deadline(), t.cost(), 1));
            }
            java.util.Set<String> fifo = new java.util.HashSet<>();
            tasks.forEach(t -> fifo.add(t.name()));
            ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks, fifo);
            for (int i = 0; i < tasks.size(); i++) {
                TaskResult r = result.tasks().get(i);
                assertTrue(r.responseTime().isPresent(), "set " + s + ", " + r.task().name() + ": utilisation at most 1 has a bound: "
                        + r.explanation());
                List<Task> lastInTies = new ArrayList<>(tasks);
                lastInTies.add(lastInTies.remove(i));
                long[] simulated = Simulator.worstResponses(lastInTies, Simulator.Mode.FIXED_PRIORITY, Simulator.hyperperiod(tasks));
                assertEquals(r.responseTime().getAsLong(), simulated[tasks.size() - 1],
                        "set " + s + " " + tasks + ", " + r.task().name() + ": analysed response against the simulation");
                compared++;
            }
        }
        assertTrue(compared > SETS, "too few tasks compared: " + compared);
    }

    /**
     * A processor's top rank of thousands of FIFO releases is analysed in one pass over the level
     * (worst response, utilisation and the most delaying tasks computed once): its results, witnesses
     * included, are those of the per-task analysis that defines them, on random levels that meet, miss
     * (short deadlines) or overload.
     */
    @Test
    void firstInFirstOutLevelInOnePassEqualsThePerTaskAnalysis() {
        Random random = new Random(SEED + 32);
        int misses = 0;
        int overloads = 0;
        for (int s = 0; s < SETS; s++) {
            List<Task> level = new ArrayList<>();
            int n = 1 + random.nextInt(40);
            double load = s % 5 == 0 ? 1.3 : 0.9;
            for (int i = 0; i < n; i++) {
                long period = (1 + random.nextInt(200)) * 1_000L;
                long cost = random.nextInt(4) == 0 ? 0 : Math.max(1, (long) (load / n * period * random.nextDouble() * 2));
                long deadline = random.nextBoolean() ? period : Math.max(1, cost * (1 + random.nextInt(3)));
                level.add(new Task("t" + i, period, deadline, cost, 1));
            }
            TaskResult[] whole = org.rsaml.analysis.internal.FirstInFirstOut.of(level);
            for (int i = 0; i < n; i++) {
                TaskResult one = org.rsaml.analysis.internal.FirstInFirstOut.of(level, level.get(i));
                String where = "set " + s + ", task " + level.get(i) + " among " + level;
                assertEquals(one.responseTime(), whole[i].responseTime(), where);
                assertEquals(one.verdict(), whole[i].verdict(), where);
                assertEquals(one.explanation(), whole[i].explanation(), where);
                assertEquals(one.witness(), whole[i].witness(), where);
                misses += one.verdict() == Verdict.MISSES && one.responseTime().isPresent() ? 1 : 0;
                overloads += one.responseTime().isEmpty() ? 1 : 0;
            }
        }
        assertTrue(misses > 50 && overloads > 50, "random levels with misses (" + misses + ") and overloads (" + overloads + ")");
    }

    /**
     * The three tasks of one rank (all FIFO) from the timing documentation: C's worst response is
     * 36 ms, everything released with it (A's job of 1 ms, B's of 20 ms) and nothing released after
     * (not A's jobs at 10, 20 and 30 ms); the witness of its miss (deadline 30 ms) runs the jobs in
     * the order of their releases.
     */
    @Test
    void firstInFirstOutCountsOnlyJobsReleasedBeforeOrWith() {
        long ms = 1_000_000L;
        List<Task> tasks = List.of(new Task("A", 10 * ms, 40 * ms, ms, 1), new Task("B", 100 * ms, 100 * ms, 20 * ms, 1),
                new Task("C", 100 * ms, 30 * ms, 15 * ms, 1));
        ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks,
                java.util.Set.of("A", "B", "C"));
        TaskResult c = result.tasks().get(2);
        assertEquals(36 * ms, c.responseTime().getAsLong(), c.explanation());
        assertEquals(Verdict.MISSES, c.verdict(), c.explanation());
        assertEquals(Verdict.MEETS, result.tasks().get(0).verdict(), "A (36 ms, due in 40 ms): " + result.tasks().get(0).explanation());
        assertTrue(c.witness() != null && !c.witness().summary(), "the first miss has its schedule: " + c.witness());
        for (org.rsaml.analysis.Segment seg : c.witness().schedule()) {
            if (seg.start() < 36 * ms) {
                long released = seg.task().equals("A") ? seg.job() * 10 * ms : seg.job() * 100 * ms;
                assertTrue(released <= 0, "only jobs released with C's first run before it completes: " + c.witness().schedule());
            }
        }
        assertEquals(36 * ms, c.witness().completion(), "the witness ends when C completes: " + c.witness().schedule());
    }

    /** Non-preemptive analysis is an upper bound: no simulated response exceeds it. */
    @Test
    void nonPreemptiveBoundsSimulation() {
        Random random = new Random(SEED + 20);
        for (int s = 0; s < SETS; s++) {
            List<Task> tasks = randomSet(random, Deadlines.ARBITRARY);
            ProcessorResult result = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY_NON_PREEMPTIVE, tasks);
            long[] simulated = Simulator.worstResponses(tasks, Simulator.Mode.NON_PREEMPTIVE, Simulator.hyperperiod(tasks));
            assertBoundsSimulation(s, tasks, result, simulated);
        }
    }

    /**
     * The analysis bounds what the simulation saw: no simulated response above a task's bound, a task
     * without a bound is a miss, and a task that meets was never late in the simulation.
     */
    private static void assertBoundsSimulation(int set, List<Task> tasks, ProcessorResult result, long[] simulated) {
        for (int i = 0; i < tasks.size(); i++) {
            TaskResult r = result.tasks().get(i);
            if (r.verdict() == Verdict.NOT_ANALYSED) {
                continue;
            }
            if (r.responseTime().isPresent()) {
                assertTrue(simulated[i] <= r.responseTime().getAsLong(), "set " + set + " task " + tasks.get(i) + ": simulated "
                    + simulated[i] + " > bound " + r.responseTime() + "; tasks " + tasks);
            } else {
                assertEquals(Verdict.MISSES, r.verdict(), "set " + set + " task " + tasks.get(i).name() + ": a task without a bounded response time is a miss");
            }
            if (r.verdict() == Verdict.MEETS) {
                assertTrue(simulated[i] <= tasks.get(i).deadline(), "set " + set + " task " + tasks.get(i).name() + ": a task the analysis says meets never misses in the simulation (" + simulated[i] + ")");
            }
        }
    }
}
