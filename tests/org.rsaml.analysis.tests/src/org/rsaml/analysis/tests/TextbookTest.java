/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.BoundCheck;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.SchedulingPolicy;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.Witness;

/** Task sets from the literature, with their published response times checked number for number. */
class TextbookTest {

    private static final long MS = 1_000_000L;
    private static final long US = 1_000L;

    private static ProcessorResult analyse(SchedulingPolicy policy, Task... tasks) {
        return SchedulabilityAnalysis.analyse("cpu", policy, List.of(tasks));
    }

    private static TaskResult of(ProcessorResult r, String name) {
        return r.tasks().stream().filter(t -> t.task().name().equals(name)).findFirst().orElseThrow();
    }

    /**
     * A. Burns and A. Wellings, Real-Time Systems and Programming Languages, response-time analysis
     * worked example (after Joseph &amp; Pandya 1986 and Audsley et al. 1993): tasks a (T = 7, C = 3),
     * b (T = 12, C = 3), c (T = 20, C = 5) under rate-monotonic priorities have R = 3, 6 and 20; c
     * meets its deadline exactly, although U = 0.9345 is far above the Liu &amp; Layland bound 0.7798.
     */
    @Test
    void burnsWellingsResponseTimes() {
        ProcessorResult r = analyse(SchedulingPolicy.FIXED_PRIORITY, Task.implicit("a", 7 * MS, 3 * MS, 3),
                Task.implicit("b", 12 * MS, 3 * MS, 2), Task.implicit("c", 20 * MS, 5 * MS, 1));
        assertEquals(3 * MS, of(r, "a").responseTime().getAsLong(), "a, the highest rank, responds in its own 3 ms (Burns & Wellings: R = 3)");
        assertEquals(6 * MS, of(r, "b").responseTime().getAsLong(), "b responds in 6 ms: its 3 ms plus one job of a (R = 6)");
        assertEquals(20 * MS, of(r, "c").responseTime().getAsLong(), "c responds in 20 ms: exactly its deadline (R = 20)");
        assertEquals(0, of(r, "c").slack().getAsLong(), "c has no slack: it completes at its deadline");
        assertEquals(Verdict.MEETS, r.verdict(), "the set meets every deadline although U = 0.9345");
        BoundCheck ll = bound(r, "Liu & Layland");
        assertTrue(ll.applicable(), "Liu & Layland applies to independent implicit-deadline rate-monotonic tasks");
        assertFalse(ll.holds(), "U = 0.9345 is above n(2^(1/n) - 1) for n = 3");
        assertTrue(ll.sufficient(), "Liu & Layland is reported as a sufficient test only");
        assertEquals("U <= 0.7798", ll.limit(), "the bound for three tasks is n(2^(1/n) - 1) = 0.7798");
    }

    /**
     * J. P. Lehoczky, Fixed priority scheduling of periodic task sets with arbitrary deadlines, RTSS
     * 1990: tau1 (C = 26, T = D = 70), tau2 (C = 62, T = 100, D = 120), U = 0.9914. The first job of
     * tau2 is not its worst: the fifth job of the level-2 busy period has response time 118.
     */
    @Test
    void lehoczkyArbitraryDeadlines() {
        ProcessorResult r = analyse(SchedulingPolicy.FIXED_PRIORITY, new Task("tau1", 70 * MS, 70 * MS, 26 * MS, 2),
                new Task("tau2", 100 * MS, 120 * MS, 62 * MS, 1));
        assertEquals(26 * MS, of(r, "tau1").responseTime().getAsLong(), "tau1, the highest rank, responds in its own 26 ms");
        assertEquals(118 * MS, of(r, "tau2").responseTime().getAsLong(), "tau2's worst response is 118 ms, in the fifth job of its busy period (Lehoczky)");
        assertEquals(Verdict.MEETS, r.verdict(), "tau2 meets its 120 ms deadline");
        // with a deadline of 115 the fifth job misses, and the witness shows that job
        ProcessorResult tight = analyse(SchedulingPolicy.FIXED_PRIORITY, new Task("tau1", 70 * MS, 70 * MS, 26 * MS, 2),
                new Task("tau2", 100 * MS, 115 * MS, 62 * MS, 1));
        TaskResult tau2 = of(tight, "tau2");
        assertEquals(Verdict.MISSES, tau2.verdict(), "with a 115 ms deadline tau2's fifth job misses");
        Witness w = tau2.witness();
        assertEquals(4, w.job(), "the witness is the fifth job (index 4) of the busy period");
        assertEquals(400 * MS, w.release(), "the missing job is released at 400 ms");
        assertEquals(518 * MS, w.completion(), "the missing job completes at 518 ms, 3 ms past its deadline");
        assertTrue(tau2.explanation().contains("job 5 of its busy period"), tau2.explanation());
    }

    /**
     * R. I. Davis, A. Burns, R. J. Bril and J. J. Lukkien, Controller Area Network (CAN) schedulability
     * analysis: refuted, revisited and revised, Real-Time Systems 35(3), 2007: messages A (T = 2.5 ms),
     * B and C (T = 3.5 ms, D = 3.25 ms), each taking 1 ms without preemption. Looking at the first
     * instance only, C would take 3 ms; its second instance in the busy period takes 3.5 ms and misses.
     */
    @Test
    void davisNonPreemptiveCorrection() {
        ProcessorResult r = analyse(SchedulingPolicy.FIXED_PRIORITY_NON_PREEMPTIVE,
                new Task("A", 2500 * US, 2500 * US, 1 * MS, 3), new Task("B", 3500 * US, 3250 * US, 1 * MS, 2),
                new Task("C", 3500 * US, 3250 * US, 1 * MS, 1));
        assertEquals(2 * MS, of(r, "A").responseTime().getAsLong(), "A responds in 2 ms: its own 1 ms plus 1 ms blocking by a lower-priority message");
        assertEquals(3 * MS, of(r, "B").responseTime().getAsLong(), "B responds in 3 ms");
        TaskResult c = of(r, "C");
        assertEquals(3500 * US, c.responseTime().getAsLong(), "C's second instance takes 3.5 ms (Davis et al.'s correction), not the first instance's 3 ms");
        assertEquals(Verdict.MISSES, c.verdict(), "C misses its 3.25 ms deadline");
        assertEquals(-250 * US, c.slack().getAsLong(), "C misses its deadline by 250 us");
        Witness w = c.witness();
        assertEquals(1, w.job(), "the second instance is the one that misses");
        assertEquals(7 * MS, w.completion(), "the missing instance completes at 7 ms");
        assertEquals(Map.of("A", 2L, "B", 1L), w.preemptions(), "the witness shows what delayed C: two A messages and one B");
        assertEquals(Verdict.MISSES, r.verdict(), "the message set misses a deadline");
    }

    /**
     * G. Buttazzo, Hard Real-Time Computing Systems (Springer), chapter on EDF, as taught in G.
     * Lipari's course "Earliest Deadline First" (Scuola Superiore Sant'Anna): tau1 = (1, 4),
     * tau2 = (2, 6), tau3 = (3, 8), U = 23/24. Rate monotonic misses a deadline of tau3; EDF
     * meets every deadline (U &le; 1 with deadlines equal to periods).
     */
    @Test
    void buttazzoRateMonotonicVersusEdf() {
        Task[] set = { Task.implicit("tau1", 4 * MS, 1 * MS, 3), Task.implicit("tau2", 6 * MS, 2 * MS, 2),
                Task.implicit("tau3", 8 * MS, 3 * MS, 1) };
        ProcessorResult rm = analyse(SchedulingPolicy.FIXED_PRIORITY, set);
        assertEquals("0.9583", rm.utilisationText(), "U = 23/24 shown to four places");
        assertEquals(1 * MS, of(rm, "tau1").responseTime().getAsLong(), "tau1 responds in its own 1 ms under rate monotonic");
        assertEquals(3 * MS, of(rm, "tau2").responseTime().getAsLong(), "tau2 responds in 3 ms under rate monotonic");
        TaskResult tau3 = of(rm, "tau3");
        assertEquals(Verdict.MISSES, tau3.verdict(), "tau3 misses its deadline under rate monotonic (Buttazzo)");
        assertEquals(10 * MS, tau3.responseTime().getAsLong(), "tau3 completes at 10 ms, 2 ms after its deadline");
        // the witness: three jobs of tau1 and two of tau2 preempt tau3 before it completes at 10 ms
        Witness w = tau3.witness();
        assertEquals(Map.of("tau1", 3L, "tau2", 2L), w.preemptions(), "the witness shows three tau1 jobs and two tau2 jobs preempting tau3");
        assertEquals(10 * MS, w.completion(), "the witness's job completes at 10 ms");
        assertEquals(10 * MS, w.schedule().get(w.schedule().size() - 1).end(), "the witness's schedule ends when the job completes");
        assertFalse(w.truncated(), "the witness's schedule is complete, not cut short");

        ProcessorResult edf = analyse(SchedulingPolicy.EDF, set);
        assertEquals(Verdict.MEETS, edf.verdict(), "the same set meets every deadline under EDF (U <= 1, implicit deadlines)");
        assertNull(edf.demand(), "with implicit deadlines and U <= 1 EDF needs no processor-demand table");
    }

    /**
     * C. L. Liu and J. W. Layland, Scheduling algorithms for multiprogramming in a hard-real-time
     * environment, JACM 20(1), 1973: the rate-monotonic bound n(2^(1/n) - 1), 0.828 for two tasks and
     * 0.780 for three, is sufficient only; a harmonic set at U = 1 fails it yet is schedulable.
     */
    @Test
    void liuLaylandBoundIsSufficientOnly() {
        ProcessorResult two = analyse(SchedulingPolicy.FIXED_PRIORITY, Task.implicit("x", 4 * MS, 1 * MS, 2),
                Task.implicit("y", 6 * MS, 3 * MS, 1));
        assertEquals("U <= 0.8284", bound(two, "Liu & Layland").limit(), "the bound for two tasks is 2(2^(1/2) - 1) = 0.8284");
        assertTrue(bound(two, "Liu & Layland").holds(), "U = 0.75");
        assertTrue(bound(two, "hyperbolic").holds(), "1.25 * 1.5 = 1.875");
        assertEquals(Verdict.MEETS, two.verdict(), "x and y meet their deadlines");

        ProcessorResult harmonic = analyse(SchedulingPolicy.FIXED_PRIORITY, Task.implicit("h1", 2 * MS, 1 * MS, 3),
                Task.implicit("h2", 4 * MS, 1 * MS, 2), Task.implicit("h3", 8 * MS, 2 * MS, 1));
        assertEquals("1.0000", harmonic.utilisationText(), "the harmonic set has U = 1");
        assertFalse(bound(harmonic, "Liu & Layland").holds(), "the harmonic set at U = 1 fails Liu & Layland");
        assertFalse(bound(harmonic, "hyperbolic").holds(), "the harmonic set at U = 1 fails the hyperbolic bound");
        assertEquals(8 * MS, of(harmonic, "h3").responseTime().getAsLong(), "h3 responds in 8 ms, exactly its period");
        assertEquals(Verdict.MEETS, harmonic.verdict(), "the harmonic set is schedulable although both bounds fail: they are sufficient only");

        // the hyperbolic bound accepts what Liu & Layland rejects (Bini, Buttazzo & Buttazzo 2003)
        ProcessorResult hyp = analyse(SchedulingPolicy.FIXED_PRIORITY, Task.implicit("p", 10 * MS, 6 * MS, 2),
                Task.implicit("q", 20 * MS, 5 * MS, 1));
        assertFalse(bound(hyp, "Liu & Layland").holds(), "U = 0.85 > 0.8284");
        assertTrue(bound(hyp, "hyperbolic").holds(), "1.6 * 1.25 = 2");
    }

    @Test
    void boundsDoNotApplyOutsideTheirAssumptions() {
        ProcessorResult dm = analyse(SchedulingPolicy.FIXED_PRIORITY, new Task("x", 10 * MS, 5 * MS, 1 * MS, 2),
                Task.implicit("y", 20 * MS, 1 * MS, 1));
        BoundCheck ll = bound(dm, "Liu & Layland");
        assertFalse(ll.applicable(), "Liu & Layland does not apply to a task whose deadline differs from its period");
        assertTrue(ll.note().contains("'x' has a deadline other than its period"), ll.note());
        ProcessorResult inverted = analyse(SchedulingPolicy.FIXED_PRIORITY, Task.implicit("x", 10 * MS, 1 * MS, 1),
                Task.implicit("y", 20 * MS, 1 * MS, 2));
        assertFalse(bound(inverted, "hyperbolic").applicable(), "the hyperbolic bound does not apply when priorities are not rate monotonic");
        assertNotNull(bound(inverted, "utilisation"), "the plain utilisation check is still reported");
    }

    private static BoundCheck bound(ProcessorResult r, String name) {
        return r.bounds().stream().filter(b -> b.name().equals(name)).findFirst().orElseThrow();
    }
}
