/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.SchedulingPolicy;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TimingText;
import org.rsaml.analysis.Verdict;

/** What cannot be proven is said plainly: never a silent pass. */
class VerdictTest {

    private static final long MS = 1_000_000L;

    @ParameterizedTest
    @EnumSource(value = SchedulingPolicy.class, names = { "LLF", "ROUND_ROBIN", "SJF", "OTHER" })
    void policiesWithoutSoundAnalysisAreNotAnalysed(SchedulingPolicy policy) {
        ProcessorResult r = SchedulabilityAnalysis.analyse("cpu", policy,
                List.of(Task.implicit("a", 10 * MS, 1 * MS, 1), Task.implicit("b", 20 * MS, 2 * MS, 1)));
        assertEquals(Verdict.NOT_ANALYSED, r.verdict(), policy + " has no sound analysis: the processor is reported as not analysed, not as meeting");
        assertTrue(r.explanation().startsWith("not analysed: "), r.explanation());
        for (TaskResult t : r.tasks()) {
            assertEquals(Verdict.NOT_ANALYSED, t.verdict(), policy + ": task " + t.task().name() + " is not analysed either");
            assertTrue(t.explanation().length() > 40, t.explanation());
        }
    }

    @ParameterizedTest
    @EnumSource(value = SchedulingPolicy.class, names = { "LLF", "ROUND_ROBIN", "SJF", "OTHER", "EDF" })
    void overloadIsAMissUnderAnyPolicy(SchedulingPolicy policy) {
        ProcessorResult r = SchedulabilityAnalysis.analyse("cpu", policy,
                List.of(Task.implicit("a", 10 * MS, 6 * MS, 1), Task.implicit("b", 20 * MS, 9 * MS, 1)));
        assertEquals(Verdict.MISSES, r.verdict(), policy + ": U = 1.05 > 1 misses whatever the scheduler");
        assertEquals("1.0500", r.utilisationText(), "the utilisation is shown to four places");
        assertTrue(r.demand().demand() > r.demand().interval(), r.demand().toString());
        assertTrue(r.explanation().contains("no scheduler can meet every deadline"), r.explanation());
    }

    /**
     * Releases of one module share the module's lock, without priority inheritance: the high-priority h
     * waits for l holding the lock while m preempts l, so h can take 2 + 10 + 5 = 17 ms, not 2 ms. Its
     * jobs held back then run back to back: m, below h, is bounded with h's jitter of 17 - 2 ms.
     */
    @Test
    void lockGroupDelaysItsHighPriorityMember() {
        Task h = new Task("h", 20 * MS, 20 * MS, 2 * MS, 3, 0, "module");
        Task m = Task.implicit("m", 20 * MS, 5 * MS, 2);
        Task l = new Task("l", 50 * MS, 50 * MS, 10 * MS, 1, 0, "module");
        ProcessorResult grouped = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, List.of(h, m, l));
        TaskResult hr = grouped.tasks().get(0);
        assertEquals(17 * MS, hr.responseTime().getAsLong(), "h waits for l holding the module's lock while m preempts l: 2 + 10 + 5 = 17 ms");
        assertEquals(Verdict.MEETS, hr.verdict(), "h still meets its 20 ms deadline");
        assertTrue(hr.explanation().contains("lock group 'module'"), hr.explanation());
        assertEquals(9 * MS, grouped.tasks().get(1).responseTime().getAsLong(), "m is bounded with h's jitter: 9 ms");
        assertEquals(19 * MS, grouped.tasks().get(2).responseTime().getAsLong(), "l responds in 19 ms");

        ProcessorResult apart = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY,
                List.of(Task.implicit("h", 20 * MS, 2 * MS, 3), m, Task.implicit("l", 50 * MS, 10 * MS, 1)));
        assertEquals(2 * MS, apart.tasks().get(0).responseTime().getAsLong(), "without a shared lock h responds in its own 2 ms");
        assertEquals(7 * MS, apart.tasks().get(1).responseTime().getAsLong(), "without a shared lock m responds in 7 ms (h preempts once)");

        // with a deadline of 10 ms h can miss it; then nothing below it is bounded, and that is said
        ProcessorResult late = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY,
                List.of(new Task("h", 20 * MS, 10 * MS, 2 * MS, 3, 0, "module"), m, l));
        assertEquals(Verdict.MISSES, late.tasks().get(0).verdict(), "with a 10 ms deadline h can miss waiting for its lock");
        assertEquals(Verdict.NOT_ANALYSED, late.tasks().get(1).verdict(), "nothing below a task that misses on its lock is bounded");
        assertTrue(late.tasks().get(1).explanation().contains("'h' can be late waiting for its lock group"), late.tasks().get(1).explanation());
    }

    /**
     * A schedule per miss would cost a simulation each: only the highest-priority task that misses gets
     * its critical-instant schedule; the others list the jobs that can delay them, the most delaying first.
     * hi takes 6 ms of every 10; lo1 .. lo30 take 2 ms once a second, due in 20 ms, lo1 highest: lo4 completes
     * at 8 + 2 * 6 = 20 ms and meets, lo5 at 10 + 3 * 6 = 28 ms and misses, lo6 at 30 ms.
     */
    @Test
    void onlyTheHighestPriorityMissGetsItsSchedule() {
        List<Task> tasks = new java.util.ArrayList<>();
        tasks.add(Task.implicit("hi", 10 * MS, 6 * MS, 100));
        for (int i = 1; i <= 30; i++) {
            tasks.add(new Task("lo" + i, 1000 * MS, 20 * MS, 2 * MS, 31 - i));
        }
        ProcessorResult r = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY, tasks);
        assertEquals(Verdict.MEETS, r.tasks().get(4).verdict(), "lo4 completes at 20 ms and meets its deadline");
        TaskResult lo5 = r.tasks().get(5);
        assertEquals(Verdict.MISSES, lo5.verdict(), "lo5 completes at 28 ms, past its 20 ms deadline");
        assertEquals(28 * MS, lo5.witness().completion(), "lo5's schedule shows its job completing at 28 ms");
        assertEquals(false, lo5.witness().summary(), "lo5, the highest-priority miss, gets a full schedule, not a summary");
        assertEquals(28 * MS, lo5.witness().schedule().get(lo5.witness().schedule().size() - 1).end(), "lo5's schedule ends when its job completes");

        TaskResult lo6 = r.tasks().get(6);
        assertEquals(30 * MS, lo6.responseTime().getAsLong(), "lo6 completes by 30 ms");
        assertTrue(lo6.witness().summary(), "lo6, a lower-priority miss, gets only a summary of what delays it");
        assertEquals(30 * MS, lo6.witness().completion(), "lo6's summary completes by 30 ms");
        assertEquals(java.util.Map.of("hi", 3L, "lo1", 1L, "lo2", 1L, "lo3", 1L, "lo4", 1L, "lo5", 1L), lo6.witness().preemptions(), "lo6's summary lists each delaying task with its job count");
        assertEquals("hi", lo6.witness().preemptions().keySet().iterator().next(), "the most delaying first");

        TaskResult lo30 = r.tasks().get(30);
        assertEquals(Verdict.MISSES, lo30.verdict(), "lo30 misses its deadline");
        assertEquals(20, lo30.witness().preemptions().size(), "a summary lists at most 20 delaying tasks");
        assertEquals(10, lo30.witness().unlisted(), "hi and lo1 .. lo29: 30 tasks delay it, 20 listed");
        long full = r.tasks().stream().filter(t -> t.witness() != null && !t.witness().summary()).count();
        assertEquals(1, full, "exactly one task on the processor gets its full schedule");

        ArchitectureTiming timing = new ArchitectureTiming("a", List.of(new ProcessorTiming("cpu", null, r, List.of(), List.of())),
                List.of(), List.of());
        String text = TimingText.render("m.rsaml", timing);
        assertTrue(text.contains("job 1 of lo6 released at 0 ns, completes by 30 ms; delayed by at most hi x3, lo1 x1, lo2 x1, lo3 x1,"
                + " lo4 x1, lo5 x1 (only the highest-priority task that misses on a processor gets its schedule)"), text);
        assertTrue(text.contains(" and 10 other tasks (only the highest-priority"), text);
    }

    @Test
    void llfUtilisationIsNecessaryOnly() {
        ProcessorResult r = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.LLF, List.of(Task.implicit("a", 10 * MS, 5 * MS, 1)));
        assertEquals(Verdict.NOT_ANALYSED, r.verdict(), "LLF is not analysed: its utilisation test is necessary only");
        assertTrue(r.bounds().get(0).holds(), "U = 0.5 passes LLF's necessary utilisation test");
        assertTrue(r.explanation().contains("least laxity first"), r.explanation());
    }

    @Test
    void overloadedFixedPriorityTaskHasNoBoundedResponseTime() {
        ProcessorResult r = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY,
                List.of(Task.implicit("a", 10 * MS, 6 * MS, 2), Task.implicit("b", 20 * MS, 9 * MS, 1)));
        TaskResult b = r.tasks().get(1);
        assertEquals(Verdict.MISSES, b.verdict(), "b, overloaded under a, misses");
        assertTrue(b.responseTime().isEmpty(), "b's response time is unbounded: none is shown");
        assertTrue(b.explanation().contains("grows without bound"), b.explanation());
        assertEquals(Verdict.MEETS, r.tasks().get(0).verdict(), "a, the higher priority, still meets");
    }

    @Test
    void timesBeyondSixtyFourBitsAreNotAnalysed() {
        // b's response time, 2^62 ns of work plus 1.5 * 2^62 ns of release jitter, exceeds 2^63 ns
        long big = 1L << 62;
        ProcessorResult r = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY,
                List.of(new Task("a", big, big, big / 2, 2), new Task("b", big, Long.MAX_VALUE, big / 2, 1, big + big / 2)));
        TaskResult b = r.tasks().get(1);
        assertEquals(Verdict.NOT_ANALYSED, b.verdict(), "a response time beyond 2^63 ns is reported as not analysed, not as a wrong number");
        assertTrue(b.explanation().contains("2^63 ns"), b.explanation());
    }

    @Test
    void equalPrioritiesDelayEachOther() {
        // run first-in first-out at one priority: either can be released just after the other
        ProcessorResult r = SchedulabilityAnalysis.analyse("cpu", SchedulingPolicy.FIXED_PRIORITY,
                List.of(Task.implicit("a", 10 * MS, 3 * MS, 1), Task.implicit("b", 10 * MS, 4 * MS, 1)));
        assertEquals(7 * MS, r.tasks().get(0).responseTime().getAsLong(), "a waits for b released just before it at the same priority: 3 + 4 = 7 ms");
        assertEquals(7 * MS, r.tasks().get(1).responseTime().getAsLong(), "b waits for a released just before it at the same priority: 4 + 3 = 7 ms");
    }

    @Test
    void badTasksAreRefusedWithTheirName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Task("scan", 0, 1, 1, 1), "a task with period 0 is refused");
        assertEquals("Task 'scan': the period must be positive, not 0 ns", e.getMessage(), "the refusal names the task and the bad period");
        IllegalArgumentException dup = assertThrows(IllegalArgumentException.class, () -> SchedulabilityAnalysis.analyse("cpu0",
                SchedulingPolicy.EDF, List.of(Task.implicit("x", 5, 1, 1), Task.implicit("x", 6, 1, 1))), "two tasks with one name on a processor are refused");
        assertEquals("Processor 'cpu0': two tasks are named 'x'", dup.getMessage(), "the refusal names the processor and the duplicated task");
    }

    @Test
    void noTasksMeetTrivially() {
        assertEquals(Verdict.MEETS, SchedulabilityAnalysis.analyse("idle", SchedulingPolicy.FIXED_PRIORITY, List.of()).verdict(), "a processor with no tasks meets trivially");
    }
}
