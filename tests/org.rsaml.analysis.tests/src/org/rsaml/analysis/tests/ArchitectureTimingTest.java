/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.SchedulingPolicy;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingModelException;
import org.rsaml.analysis.TimingText;
import org.rsaml.analysis.Verdict;
import org.rsaml.model.Architecture;
import org.rsaml.model.Processor;
import org.rsaml.model.RsamlFactory;
import org.rsaml.validation.ModelLoader;

/** The timing of the examples, with the task set taken from the generator's execution plan. */
class ArchitectureTimingTest {

    private static final long MS = 1_000_000L;

    static Architecture example(String name) throws Exception {
        Path root = Path.of(System.getProperty("rsaml.root", "../.."));
        return ModelLoader.load(root.resolve("examples").resolve(name), "examples/" + name).architecture();
    }

    static Architecture fixture(String name) throws Exception {
        Path root = Path.of(System.getProperty("rsaml.root", "../.."));
        String path = "tests/org.rsaml.analysis.tests/resources/" + name;
        return ModelLoader.load(root.resolve(path), path).architecture();
    }

    private static ProcessorTiming processor(ArchitectureTiming timing, String name) {
        return timing.processors().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    private static TaskResult task(ProcessorTiming p, String name) {
        return p.result().tasks().stream().filter(t -> t.task().name().equals(name)).findFirst().orElseThrow();
    }

    @Test
    void twoProcessorsAndALatencyThatHolds() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(example("mobile-base-latency.rsaml"));
        assertEquals(List.of("core0", "core1"), timing.processors().stream().map(ProcessorTiming::name).toList(), "mobile-base-latency's two processors are analysed, in the model's order");
        ProcessorTiming core0 = timing.processors().get(0);
        assertEquals(SchedulingPolicy.FIXED_PRIORITY, core0.result().policy(), "core0 is analysed as fixed-priority (rate monotonic)");
        // rate monotonic: the odometry (5 ms) preempts the controller (10 ms) once
        assertEquals(1 * MS, task(core0, "control/odometry.integrate").responseTime().getAsLong(), "the odometry (5 ms, highest rank) responds within its own 1 ms");
        assertEquals(3 * MS, task(core0, "control/velocityController.control").responseTime().getAsLong(), "the velocity controller responds in 3 ms: its own 2 ms plus one odometry preemption");
        ProcessorTiming core1 = timing.processors().get(1);
        assertEquals(4 * MS, task(core1, "navigation/obstacleDetector.detect").responseTime().getAsLong(), "the obstacle detector, alone at its rank on core1, responds in its 4 ms");
        // the planner (30 ms every 100 ms) is preempted by two detector jobs
        assertEquals(38 * MS, task(core1, "navigation/pathPlanner.plan").responseTime().getAsLong(), "the path planner responds in 38 ms: its 30 ms plus two detector preemptions");
        assertEquals(Verdict.MEETS, timing.verdict(), "every task of mobile-base-latency meets its deadline");

        LatencyResult l = timing.latencies().get(0);
        assertEquals("scanToWheels", l.name(), "the model's latency requirement is reported by its name");
        assertEquals(Verdict.MEETS, l.verdict(), l.explanation());
        assertEquals(37 * MS, l.reactionNs(), "the worst reaction from scan to wheels is 37 ms");
        assertEquals(List.of("navigation/obstacleDetector", "control/velocityController"), l.worstPath().stream().map(Hop::label).toList(), "the worst path runs from the obstacle detector to the velocity controller");
        assertEquals(20 * MS, l.worstPath().get(0).waitNs(), "the detector's input waits up to one period (20 ms) on the worst path");
        assertEquals(4 * MS, l.worstPath().get(0).responseNs(), "the detector's hop costs its response time (4 ms)");
        assertEquals(13 * MS, l.worstPath().get(1).totalNs(), "the controller's hop costs 13 ms in all (wait and response)");
    }

    @Test
    void aSlowerDetectorMissesTheRequirement() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(example("mobile-base-latency-missed.rsaml"));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(Verdict.MISSES, l.verdict(), "the slower detector makes the reaction exceed the 50 ms requirement: " + l.explanation());
        assertEquals(57 * MS, l.reactionNs(), "the worst reaction with the slower detector is 57 ms");
        assertTrue(l.explanation().contains("57 ms, more than 50 ms"), l.explanation());
        assertEquals(Verdict.MISSES, timing.verdict(), "a missed latency requirement makes the whole architecture miss");
        String text = TimingText.render("m.rsaml", timing);
        assertTrue(text.contains("navigation/obstacleDetector: +44 ms (wait 40 ms + response 4 ms)"), text);
    }

    /** The paper's experiment 3: the six instructions' start dates count as execution; the interpreter reacts aperiodically. */
    @Test
    void experimentThree() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(example("exp3-task-interpreter.rsaml"));
        assertEquals(1, timing.processors().size(), "exp3 has no deployment: one processor");
        ProcessorTiming p = timing.processors().get(0);
        assertEquals(TimingAnalysis.DEFAULT_PROCESSOR, p.name(), "an architecture without processors is analysed on the default processor");
        TaskResult exec = task(p, "motionControl/motionController.executeInstructions");
        assertEquals(11 * MS, exec.task().cost(), "6 ms of execution and 5 ms of start dates");
        assertEquals(11 * MS, exec.responseTime().getAsLong(), "the executor responds in its 11 ms of cost (alone at its rank)");
        assertEquals(Verdict.MEETS, exec.verdict(), "the executor meets its deadline");
        assertEquals(1, timing.excluded().size(), "exactly one module is left out of the periodic analysis");
        assertEquals("interpretation/taskInterpreter", timing.excluded().get(0).label(), "the sporadic task interpreter is the module left out");
        assertTrue(timing.excluded().get(0).reason().contains("execType sporadic"), timing.excluded().get(0).reason());
    }

    /**
     * Experiment 1: m01's periodic function shares its module's lock with m01's aperiodic reaction, which holds it below
     * the real-time ranks: the function's wait for the lock has no bound, so it is not analysed (it was once given a
     * bound that counted no such wait, and on ROS 2 its jobs responded past it); the releases of modules without an
     * aperiodic reaction keep their verdicts.
     */
    @Test
    void aReleaseSharingItsLockWithAnAperiodicReactionIsNotAnalysed() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(example("exp1-hybrid.rsaml"));
        java.util.Set<String> aperiodic = new java.util.HashSet<>(timing.excluded().stream().map(x -> x.label()).toList());
        assertTrue(aperiodic.contains("functional/m01"), "m01 reacts aperiodically: " + aperiodic);
        TaskResult f0 = timing.processors().stream().flatMap(p -> p.result().tasks().stream())
                .filter(t -> t.task().name().equals("functional/m01.f0_m01")).findFirst().orElseThrow();
        assertEquals(Verdict.NOT_ANALYSED, f0.verdict(), "m01's function waits for the lock m01's aperiodic reaction holds");
        assertTrue(f0.explanation().startsWith("not analysed: it waits for its module's lock while the module's aperiodic reaction, which the analysis excludes, holds it"),
                f0.explanation());
        long kept = timing.processors().stream().flatMap(p -> p.result().tasks().stream())
                .filter(t -> !aperiodic.contains(t.task().group()) && t.task().priority() > 0 && t.verdict() == Verdict.MEETS).count();
        assertTrue(kept > 0, "the real-time releases of modules without an aperiodic reaction keep their verdicts");
    }

    @Test
    void aModuleOnTwoProcessorsIsRefused() throws Exception {
        Architecture a = example("mobile-base-latency.rsaml");
        Processor extra = RsamlFactory.eINSTANCE.createProcessor();
        extra.setName("core2");
        extra.getModules().add(a.getLayers().get(1).getModules().get(0));
        a.getProcessors().add(extra);
        TimingModelException e = assertThrows(TimingModelException.class, () -> TimingAnalysis.analyse(a), "a module allocated to two processors is refused, not analysed twice");
        assertEquals("module control/velocityController is allocated to two processors, 'core0' and 'core2': remove it from one of them",
                e.getMessage(), "the refusal names the module, both processors and the fix");
    }

    @Test
    void anEdfProcessorIsAnalysedByDemandAndSaysHowTheRuntimeSchedulesIt() throws Exception {
        Architecture a = example("mobile-base-latency.rsaml");
        a.getProcessors().get(1).setSchedPolicy(org.rsaml.model.SchedulingPolicy.EDF);
        ArchitectureTiming timing = TimingAnalysis.analyse(a);
        ProcessorTiming core1 = timing.processors().get(1);
        assertEquals(SchedulingPolicy.EDF, core1.result().policy(), "a processor set to EDF is analysed by processor demand");
        assertEquals(Verdict.MEETS, core1.result().verdict(), "core1's tasks meet their deadlines under EDF");
        assertTrue(core1.notes().get(0).contains("the generated C++ runtime runs each timed release under SCHED_DEADLINE")
                && core1.notes().get(0).contains("becomes a deadline thread at its first release")
                && core1.notes().get(0).contains("the kernel's periods are its releases, and there the verdict is claimed")
                && core1.notes().get(0).contains("The ROS 2 nodes do the same on each release's own executor thread")
                && core1.notes().get(0).contains("there the verdict is claimed as on the C++ runtime, deadlines shorter than periods included"),
                "how the runtimes schedule it, and what is claimed on each: "
                + core1.notes().get(0));
        assertTrue(core1.notes().get(1).startsWith("core 1 does not hold EDF:") && core1.notes().get(1).contains("on ROS 2, whose launch pins"
                + " the processor's container to core 1 (taskset), the kernel refuses SCHED_DEADLINE") && core1.notes().get(1).contains("on"
                + " neither runtime does this processor run as analysed"), "a processor with a core says plainly that neither runtime runs EDF on it: "
                + core1.notes());
        // without response times under EDF the latency through core 1 is not bounded, and says so
        assertEquals(Verdict.NOT_ANALYSED, timing.latencies().get(0).verdict(), "without EDF response times the latency through core1 is reported as not analysed");
    }

    /**
     * An EDF processor without a core beside a processor with one on its host: both runtimes keep it to the CPUs no
     * processor claims, where the kernel refuses SCHED_DEADLINE and its releases run first in first out at one rank, so
     * its tasks are not analysed (RSA-24), saying why and what to do (docs/timing.md, "EDF beside processors with cores");
     * the processor with a core keeps its verdict; on a host without a processor with a core, it keeps EDF's.
     */
    @Test
    void anEdfProcessorWithoutACoreBesideOneWithACoreIsNotAnalysed() throws Exception {
        Architecture a = example("mobile-base-latency.rsaml");
        a.getProcessors().get(1).setSchedPolicy(org.rsaml.model.SchedulingPolicy.EDF);
        a.getProcessors().get(1).setCore(-1);
        ArchitectureTiming timing = TimingAnalysis.analyse(a);
        ProcessorTiming nav = timing.processors().get(1);
        assertEquals(Verdict.NOT_ANALYSED, nav.result().verdict(), nav.result().toString());
        assertTrue(nav.result().tasks().stream().allMatch(t -> t.verdict() == Verdict.NOT_ANALYSED && t.explanation().equals("not analysed: EDF"
                + " processor 'core1' has no core of its own beside processor 'core0' with a core, so both runtimes keep its releases to the"
                + " CPUs no processor claims, where Linux (its deadline admission control on, as by default: sched_rt_runtime_us not -1)"
                + " refuses them SCHED_DEADLINE, and they run under SCHED_FIFO at one rank, first in first out, not by deadline (the trace"
                + " says 'instead of EDF'): give its functions fixed priorities (RM, DM), or put it on a host of its own")),
                "each task says why: " + nav.result().tasks());
        assertEquals(Verdict.MEETS, timing.processors().get(0).result().verdict(), "core0 keeps its core and its verdict");
        // on a host of its own, without a processor with a core beside it, it is scheduled by deadline and analysed so
        a.getProcessors().get(1).setHost("nav-board");
        assertEquals(Verdict.MEETS, TimingAnalysis.analyse(a).processors().get(1).result().verdict(), "on a host of its own");
    }

    /**
     * Deadlines shorter than periods on an EDF processor: the set meets them under EDF, and the verdict is claimed on
     * both runtimes, as for deadlines equal to periods (each release's thread never waits for its timer again): no note
     * sets them apart.
     */
    @Test
    void anEdfProcessorClaimsDeadlinesShorterThanPeriodsOnBothRuntimes() throws Exception {
        ProcessorTiming edf = TimingAnalysis.analyse(fixture("edf-constrained-deadlines.rsaml")).processors().get(0);
        assertEquals(Verdict.MEETS, edf.result().verdict(), "A (T 5, D 4, C 2) and B (T 8, D 6, C 3.5) meet their deadlines under EDF");
        assertTrue(edf.notes().get(0).contains("deadlines shorter than periods included"), "claimed on ROS 2 as on the C++ runtime: " + edf.notes());
        assertTrue(edf.notes().stream().noneMatch(n -> n.contains("not claimed")), "nothing left unclaimed: " + edf.notes());
    }

    /** Processors without a core share the cores no processor claims: a processor analysed alone proves nothing. */
    @Test
    void processorsWithoutACoreShareTheUnclaimedCpusAndAreNotAnalysed() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(fixture("deployment-two-without-core.rsaml"));
        assertEquals(List.of("p1", "p2", "default"), timing.processors().stream().map(ProcessorTiming::name).toList(), "every processor is reported, the default one (the unclaimed cores) last");
        for (ProcessorTiming p : timing.processors()) {
            assertEquals(Verdict.NOT_ANALYSED, p.result().verdict(), p.name());
            for (TaskResult t : p.result().tasks()) {
                assertEquals(Verdict.NOT_ANALYSED, t.verdict(), t.task().name());
                assertTrue(t.responseTime().isEmpty(), t.task().name());
                assertTrue(t.explanation().startsWith("not analysed: processors 'p1', 'p2' and 'default' have no core of their own"),
                        t.explanation());
                assertTrue(t.explanation().contains("give each processor a core of its own (and allocate the modules no processor names"),
                        t.explanation());
            }
        }
        assertEquals(Verdict.NOT_ANALYSED, timing.verdict(), "processors without a core of their own make the architecture's verdict not analysed");
        String text = TimingText.render("m.rsaml", timing);
        assertTrue(text.contains("l/a.fa   40 ms     12 ms  8 ms         2     -      -  not analysed"), text);
        assertTrue(text.contains("bound Liu & Layland (sufficient): U <= 1.0000 not applicable: task 'l/a.fa' has a deadline other than its period"), text);
        assertTrue(text.contains("bound hyperbolic (sufficient): prod(U_i + 1) <= 2 not applicable: the processor shares its CPUs"), text);
        assertTrue(text.contains("  verdict: not analysed: processors 'p1', 'p2' and 'default' have no core"), text);
    }

    @Test
    void processorsClaimingOneCoreAreNotAnalysedTheOthersAre() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(fixture("deployment-same-core.rsaml"));
        for (String name : List.of("p1", "p2")) {
            TaskResult t = processor(timing, name).result().tasks().get(0);
            assertEquals(Verdict.NOT_ANALYSED, t.verdict(), name);
            assertTrue(t.explanation().startsWith("not analysed: processors 'p1' and 'p2' claim the same core 1"), t.explanation());
        }
        TaskResult alone = processor(timing, "p3").result().tasks().get(0);
        assertEquals(Verdict.MEETS, alone.verdict(), "p3, on a core of its own, is analysed and meets its deadline");
        assertEquals(5 * MS, alone.responseTime().getAsLong(), "p3's task responds in its own 5 ms");
    }

    /** One processor without a core gets the cores no processor claims to itself: analysed as before. */
    @Test
    void oneProcessorWithoutACoreIsAnalysed() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(fixture("deployment-one-without-core.rsaml"));
        assertEquals(8 * MS, task(processor(timing, "core0"), "l/a.fa").responseTime().getAsLong(), "core0's task responds in 8 ms");
        assertEquals(10 * MS, task(processor(timing, "default"), "l/b2.fb2").responseTime().getAsLong(), "the processor without a core, given the unclaimed cores, is analysed: l/b2.fb2 responds in 10 ms");
        assertEquals(Verdict.MEETS, timing.verdict(), "one processor without a core leaves the architecture analysable, and it meets");
        // every example with a deployment gives each processor a core of its own
        for (String example : List.of("hierarchical-nasrem.rsaml", "mobile-base-latency.rsaml", "mobile-base-latency-missed.rsaml")) {
            for (ProcessorTiming p : TimingAnalysis.analyse(example(example)).processors()) {
                assertTrue(p.result().tasks().stream().noneMatch(t -> t.explanation().contains("core")), example + " " + p.name());
            }
        }
    }

    /** The utilisation bounds assume independent tasks: with a module's lock shared they prove nothing. */
    @Test
    void utilisationBoundsDoNotApplyWhenTasksShareTheirModulesLock() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(fixture("lock-group-bounds.rsaml"));
        ProcessorTiming p = timing.processors().get(0);
        TaskResult f1 = task(p, "l/m.f1");
        assertEquals(Verdict.MISSES, f1.verdict(), "f1 misses: it can wait for the lower-priority f2 holding the module's lock");
        assertEquals(12 * MS, f1.responseTime().getAsLong(), "f1's response includes the blocking by f2: 12 ms");
        String why = "not applicable: task 'l/m.f1' shares its module's lock with the lower-priority 'l/m.f2' and can wait for it,"
                + " and the bound assumes independent tasks";
        for (String bound : List.of("Liu & Layland", "hyperbolic")) {
            org.rsaml.analysis.BoundCheck b = p.result().bounds().stream().filter(c -> c.name().equals(bound)).findFirst().orElseThrow();
            assertEquals(false, b.applicable(), bound);
            assertEquals(why, b.note(), bound);
        }
        String text = TimingText.render("m.rsaml", timing);
        assertTrue(text.contains("bound Liu & Layland (sufficient): U <= 0.7798 " + why), text);
        assertTrue(!text.contains("U <= 0.7798 holds") && !text.contains("prod(U_i + 1) <= 2 holds"), "no utilisation bound is shown as holding when the tasks share a lock: " + text);
    }

    /**
     * A processor declared FIFO runs the runtime's ranks, which come from each function's schedPolicy. By
     * hand, fa: T 5, D 2, C 1; fb: T 100, C 10 (ms).
     * Rate monotonic: fa at rank 3 preempts fb at rank 2: R(fa) = 1, R(fb) = 10 + 3 fa jobs (at 0, 5, 10) = 13.
     * FIFO functions: one rank, SCHED_FIFO, first in, first out: fa released with fb can wait for all of
     * fb, R(fa) = 10 + 1 = 11 > 2; fb waits for the fa job released with it only, R(fb) = 1 + 10 = 11.
     * RR functions: one rank, SCHED_RR: time slices let the fa jobs at 5 and 10 in, R(fb) = 13; R(fa) = 11.
     */
    @Test
    void fifoAndRoundRobinAreAnalysedAsTheRuntimeRanksAndRunsThem() throws Exception {
        ProcessorTiming ranked = TimingAnalysis.analyse(fixture("fifo-ranked.rsaml")).processors().get(0);
        assertEquals(SchedulingPolicy.FIXED_PRIORITY, ranked.result().policy(), "rate-monotonic functions on a FIFO-declared processor are analysed as fixed priorities");
        assertEquals(3, task(ranked, "l/a.fa").task().priority(), "fa (shortest period) gets the top rank 3");
        assertEquals(1 * MS, task(ranked, "l/a.fa").responseTime().getAsLong(), "fa at the top rank responds in its own 1 ms");
        assertEquals(Verdict.MEETS, task(ranked, "l/a.fa").verdict(), "fa meets its 2 ms deadline at the top rank");
        assertEquals(13 * MS, task(ranked, "l/b.fb").responseTime().getAsLong(), "fb responds in 13 ms: its 10 ms plus three fa jobs");

        ArchitectureTiming fifo = TimingAnalysis.analyse(fixture("fifo-one-rank.rsaml"));
        ProcessorTiming oneRank = fifo.processors().get(0);
        TaskResult fa = task(oneRank, "l/a.fa");
        assertEquals(1, fa.task().priority(), "FIFO functions share one rank");
        assertEquals(11 * MS, fa.responseTime().getAsLong(), "fa released with fb can wait for all of fb: 10 + 1 = 11 ms");
        assertEquals(Verdict.MISSES, fa.verdict(), "fa misses its 2 ms deadline under first in, first out");
        assertEquals(List.of("l/b.fb 0 - 10000000", "l/a.fa 10000000 - 11000000"),
                fa.witness().schedule().stream().map(s -> s.task() + " " + s.start() + " - " + s.end()).toList(), "the witness shows fb running first, then fa");
        TaskResult fb = task(oneRank, "l/b.fb");
        assertEquals(11 * MS, fb.responseTime().getAsLong(), "fb waits only for the fa job released with it: 1 + 10 = 11 ms");
        assertTrue(fb.explanation().contains("first in, first out among the tasks of its priority"), fb.explanation());
        String text = TimingText.render("m.rsaml", fifo);
        assertTrue(text.contains("job 1 of l/a.fa released at 0 ns, completes at 11 ms; delayed by l/b.fb x1"), text);

        ProcessorTiming roundRobin = TimingAnalysis.analyse(fixture("rr-one-rank.rsaml")).processors().get(0);
        assertEquals(11 * MS, task(roundRobin, "l/a.fa").responseTime().getAsLong(), "under round robin fa still waits for fb's slice: 11 ms");
        assertEquals(13 * MS, task(roundRobin, "l/b.fb").responseTime().getAsLong(), "under round robin the fa jobs at 5 and 10 ms get in: fb responds in 13 ms");
    }
}
