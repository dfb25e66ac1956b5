/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Supplier;

import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Release;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.model.Architecture;
import org.rsaml.model.Processor;
import org.rsaml.model.SchedulingPolicy;

/**
 * What the observed-versus-bound checks of {@link JobTimingTest} (C++) and {@link Ros2LaunchTest}
 * (ROS 2) allow the platform, and when they cannot check at all (docs/timing.md, "The platform's
 * allowance"): one decision for both, {@link #boundCheck}.
 * <p>
 * <b>The allowance</b> is measured, not fixed, on the run's <i>probe</i> releases, those nothing in
 * the model can delay (alone at the top rank of a fixed-priority processor whose CPU is their own,
 * scheduled as analysed), in the same run, under the same load: their worst start latency (release to
 * the job's start: the timer's wake-up, the executor's dispatch on ROS 2) plus their worst stall
 * (the time a job, holding its module's lock, was ready and not running: its wall time minus its CPU
 * time). A run without such a release (EDF processors, one shared rank) takes both from a calibration
 * run of a C++ program of one probe per core, run just after. To it come {@link #BOOKKEEPING_NS},
 * stated, and the CPU time other programs' real-time threads used during the run, when it is small
 * enough to be tolerated ({@link OtherRealtime}). A job that runs longer than modeled is not covered:
 * its execution is CPU time, which no stall holds.
 * <p>
 * <b>Other programs' real-time threads</b> that used more than that take the CPUs at priorities the
 * analysis does not know: the run's bounds are not checked, said once in the output. CI runs alone:
 * with {@code RSAML_TIMING_BOUNDS=required} in the environment (set by {@code .ci/run}; the test JVM
 * inherits it), such a run fails instead, so the check cannot silently stop.
 */
final class PlatformCheck {
    private PlatformCheck() {
    }

    /**
     * Stated, not measured: the part of a response that is neither the platform's start latency nor the
     * modeled execution time: the job's bookkeeping after its busy work (taking the clock, the sends, the
     * trace, the statistics and, on ROS 2, the executor's return) and the context switches of its
     * preemptions.
     */
    static final long BOOKKEEPING_NS = 300_000;

    /**
     * The allowance of one run: the measured platform start latency and stall (the probes' worst of
     * each), where they came from, the stated bookkeeping and the tolerated CPU time of others' real-time threads.
     */
    record Allowance(long latencyNs, long stallNs, String source, OtherRealtime.Use others, Map<String, Long> reanalysed) {
        Allowance(long latencyNs, long stallNs, String source, OtherRealtime.Use others) {
            this(latencyNs, stallNs, source, others, Map.of());
        }

        Allowance(long latencyNs, long stallNs, String source) {
            this(latencyNs, stallNs, source, OtherRealtime.Use.NONE);
        }

        /**
         * This allowance with the bounds of the analysis run again on the platform as measured: the start latency as
         * every release's jitter, the stall, the bookkeeping and the others' real-time CPU time added to every execution
         * time, on each fixed-priority processor the analysis bounded. A delay at a job's start can push it into one
         * more release of a higher rank, which the plain sum (bound plus allowance) does not hold; the analysis with
         * release jitter does (Audsley et al.), and it is the analysis's own, not a second one. EDF processors keep the
         * plain sum.
         */
        Allowance reanalysed(ArchitectureTiming timing) {
            Map<String, Long> bounds = new HashMap<>();
            long extra = stallNs + BOOKKEEPING_NS + others.totalNs();
            for (ProcessorTiming p : timing.processors()) {
                ProcessorResult r = p.result();
                if (r.policy() != org.rsaml.analysis.SchedulingPolicy.FIXED_PRIORITY || r.tasks().stream().allMatch(t -> t.responseTime().isEmpty())) {
                    continue;
                }
                boolean roundRobin = p.element() != null && p.element().isSetSchedPolicy() && p.element().getSchedPolicy() == SchedulingPolicy.RR;
                List<Task> tasks = new ArrayList<>();
                Set<String> runToCompletion = new HashSet<>();
                for (TaskResult t : r.tasks()) {
                    Task x = t.task();
                    tasks.add(new Task(x.name(), x.period(), x.deadline(), Math.addExact(x.cost(), extra), x.priority(), Math.max(x.jitter(), latencyNs), x.group()));
                    if (!roundRobin) {
                        runToCompletion.add(x.name());
                    }
                }
                Set<String> bounded = new HashSet<>();
                r.tasks().stream().filter(t -> t.responseTime().isPresent()).forEach(t -> bounded.add(t.task().name()));
                for (TaskResult after : SchedulabilityAnalysis.analyse(r.processor(), r.policy(), tasks, runToCompletion).tasks()) {
                    if (bounded.contains(after.task().name()) && after.responseTime().isPresent()) {
                        bounds.put(after.task().name(), after.responseTime().getAsLong());
                    }
                }
            }
            return new Allowance(latencyNs, stallNs, source, others, Map.copyOf(bounds));
        }

        /** Whether {@code label}'s worst observed response is within its bound plus this allowance, or within its bound re-analysed with the platform ({@link #reanalysed}). */
        boolean admits(String label, long worstNs, long boundNs) {
            return admits(worstNs, boundNs) || worstNs <= reanalysed.getOrDefault(label, -1L);
        }

        /** What a failed {@link #admits(String, long, long)} compared with, beyond the plain sum. */
        String reanalysedText(String label) {
            Long b = reanalysed.get(label);
            return b == null ? "" : "; nor within " + JobTimingTest.ms(b) + ", its bound by the analysis run again with the platform's start latency as"
                    + " every release's jitter and its stall and bookkeeping added to every execution time";
        }

        long ns() {
            return latencyNs + stallNs + BOOKKEEPING_NS + others.totalNs();
        }

        /** Whether a worst observed response is within {@code boundNs} plus this allowance: the check of both timing tests. */
        boolean admits(long worstNs, long boundNs) {
            return worstNs <= boundNs + ns();
        }

        @Override
        public String toString() {
            return JobTimingTest.ms(ns()) + " = " + JobTimingTest.ms(latencyNs) + " platform start latency + " + JobTimingTest.ms(stallNs)
                    + " platform stall during a job (" + source + ") + " + JobTimingTest.ms(BOOKKEEPING_NS) + " stated for bookkeeping"
                    + (others.ranNs().isEmpty() ? "" : " + " + JobTimingTest.ms(others.totalNs()) + " other programs' real-time threads ran ("
                            + others + ")");
        }
    }

    /**
     * Whether a run's bounds are checked, and with what allowance: {@code allowance} when they are, else
     * {@code notChecked}, why not.
     */
    record BoundCheck(Allowance allowance, String notChecked) {
    }

    /**
     * The one decision of both timing tests, for a run that has bounds to check (scheduled as analysed):
     * while other programs' real-time threads used more CPU time during it than {@link OtherRealtime#TOLERATED_NS},
     * not checked (said once; a failure where {@link #required()}); else with the allowance of the run's own
     * probe releases, or else of a calibration run, plus the others' CPU time; not checked when the calibration
     * got no real-time scheduling either (a failure where required).
     */
    static BoundCheck boundCheck(String what, OtherRealtime.Use others, Supplier<List<Release>> probes, Map<String, JobSummary> summaries)
            throws Exception {
        if (!others.tolerated()) {
            otherRealtime(what, others);
            return new BoundCheck(null, "other programs' real-time threads ran " + JobTimingTest.ms(others.totalNs()));
        }
        Allowance allowance = fromRun(probes.get().stream().map(Release::label).toList(), summaries);
        if (allowance == null) {
            allowance = calibrate();
        }
        if (allowance == null) {
            if (required()) {
                fail("RSAML_TIMING_BOUNDS=required: the calibration run got no real-time scheduling, so no bound can be checked");
            }
            return new BoundCheck(null, "the calibration run got no real-time scheduling");
        }
        return new BoundCheck(new Allowance(allowance.latencyNs(), allowance.stallNs(), allowance.source(), others), null);
    }

    /** Whether the environment demands the bound check (CI, which runs alone): then other programs' real-time threads may not run beyond the tolerance. */
    static boolean required() {
        String mode = System.getenv("RSAML_TIMING_BOUNDS");
        return "required".equals(mode);
    }

    /**
     * Where the bound check is required (CI), a release (or reaction) the analysis bounds that ran
     * without real-time priority fails the test, naming it: its bound could not be checked, and a
     * required check may not pass by checking nothing. A release of an EDF processor that the kernel
     * refused SCHED_DEADLINE and that runs at its real-time rank instead ({@code ... instead of EDF})
     * is not held to EDF's bound, and is not a failure here.
     */
    static void requireRealtime(String what, String label, String sched) {
        if (required() && sched.startsWith("default")) {
            fail(what + ": " + label + " ran without real-time priority (sched " + sched + "), so its bound cannot be checked, and"
                    + " RSAML_TIMING_BOUNDS=required (CI) demands the check: run the tests as root or with CAP_SYS_NICE, or an rtprio limit");
        }
    }

    /**
     * Whether a bounded release or reaction ran as the analysis assumes, so that its bound is checked; where
     * it did not, it is noted in {@code unchecked} with its scheduling (and fails where {@link #required()}).
     */
    static boolean scheduledAsAnalysed(String what, String label, JobSummary observed, List<String> unchecked) {
        requireRealtime(what, label, observed.sched());
        if (!observed.asAnalysed()) {
            unchecked.add(label + " (" + observed.sched() + ")");
            return false;
        }
        return true;
    }

    /**
     * The releases of a run that measure the platform: alone at the highest rank of a processor that
     * schedules by fixed priorities, scheduled as analysed, with the CPU of their processor to
     * themselves ({@code apart}: null when so). Their start latency is the timer's wake-up and the
     * dispatch only: nothing the model counts can delay their start.
     */
    static List<Release> probes(Architecture arch, ExecutionPlan plan, Map<String, JobSummary> summaries,
            java.util.function.Function<Release, String> apart) {
        Map<Processor, List<Release>> byProcessor = new HashMap<>();
        Map<Processor, Boolean> edf = new HashMap<>();
        for (Release r : plan.releases()) {
            Processor p = r.module().processor();
            byProcessor.computeIfAbsent(p, x -> new java.util.ArrayList<>()).add(r);
            edf.merge(p, r.edf() || p != null && p.isSetSchedPolicy() && p.getSchedPolicy() == SchedulingPolicy.EDF, Boolean::logicalOr);
        }
        List<Release> probes = new java.util.ArrayList<>();
        for (Map.Entry<Processor, List<Release>> e : byProcessor.entrySet()) {
            if (edf.get(e.getKey())) {
                continue;
            }
            int top = e.getValue().stream().mapToInt(Release::rank).max().orElse(0);
            List<Release> atTop = e.getValue().stream().filter(r -> r.rank() == top).toList();
            if (atTop.size() == 1) {
                Release r = atTop.get(0);
                JobSummary s = summaries.get(r.label());
                if (s != null && s.jobs() > 0 && s.asAnalysed() && apart.apply(r) == null) {
                    probes.add(r);
                }
            }
        }
        probes.sort(java.util.Comparator.comparing(Release::label));
        return probes;
    }

    /**
     * The allowance measured by the run's probes (their labels), or null when it has none: the worst
     * start latency of any of them plus the worst stall of any of them (one job may be delayed both at
     * its start and while it runs; the two worsts may come from different probes), each named.
     * Only probes count: another release's stall holds the preemptions by higher ranks, which its
     * bound counts already.
     */
    static Allowance fromRun(List<String> probes, Map<String, JobSummary> summaries) {
        if (probes.isEmpty()) {
            return null;
        }
        JobSummary late = null;
        JobSummary stalled = null;
        for (String label : probes) {
            JobSummary s = summaries.get(label);
            if (late == null || s.latencyNs() > late.latencyNs()) {
                late = s;
            }
            if (stalled == null || s.stallNs() > stalled.stallNs()) {
                stalled = s;
            }
        }
        return new Allowance(late.latencyNs(), stalled.stallNs(), "measured in this run: the worst start latency, of " + late.label()
                + ", and the worst stall, of " + stalled.label() + ", of " + probes.size() + " release" + (probes.size() == 1 ? "" : "s")
                + " alone at their processor's top rank");
    }

    private static Path calibration;

    /**
     * The allowance of a calibration run, run now: a C++ program of one probe release per core of this
     * machine (period 2 ms, 0.1 ms of busy work, each alone on its core at the top rank), for 500 ms, just after the run.
     * Null where it did not get real-time scheduling (then no bound is checked anyway).
     */
    static Allowance calibrate() throws Exception {
        Path exe = calibrationProgram();
        String output = Tools.ok(exe.getParent(), 60, exe.toString(), "--run-for-ms", "500", "--quiet", "--busy-work", "100");
        long latency = -1;
        long stall = -1;
        for (JobSummary s : JobSummary.of(output).values()) {
            if (!s.asAnalysed() || s.jobs() == 0) {
                return null;
            }
            latency = Math.max(latency, s.latencyNs());
            stall = Math.max(stall, s.stallNs());
        }
        return latency < 0 ? null
                : new Allowance(latency, stall, "measured by a calibration run just after: the worst start latency and the worst stall of a"
                        + " lone top-rank release on each of " + Runtime.getRuntime().availableProcessors() + " cores, 500 ms");
    }

    private static synchronized Path calibrationProgram() throws Exception {
        if (calibration == null) {
            int cores = Math.min(8, Runtime.getRuntime().availableProcessors());
            StringBuilder modules = new StringBuilder();
            StringBuilder processors = new StringBuilder();
            for (int core = 0; core < cores; core++) {
                modules.append(JobTimingTest.module("probe" + core, 2, 0.1, "RM"));
                processors.append("  <processors name=\"cpu").append(core).append("\" core=\"").append(core)
                        .append("\" modules=\"//@layers[name='tasks']/@modules[name='probe").append(core).append("']\"/>\n");
            }
            Path dir = Files.createTempDirectory("rsaml-calibration");
            Path model = dir.resolve("calibration.rsaml");
            Files.writeString(model, JobTimingTest.modelText("calibration", modules.toString(), processors.toString()));
            Path out = dir.resolve("project");
            new RsamlGenerator().generate(model, Target.CPP, out, false);
            calibration = Tools.cmakeBuild(out, CppExamplesTest.executableName(out));
        }
        return calibration;
    }

    private static final AtomicBoolean SAID = new AtomicBoolean();

    /**
     * Says once, for the whole test run, why bounds go unchecked while other programs' real-time
     * threads run, and which ran during this run and for how long; where the check is required (CI), fails instead.
     */
    static void otherRealtime(String what, OtherRealtime.Use others) {
        if (required()) {
            fail(what + ": other programs' real-time threads ran during the run (" + others + "; tolerated: "
                    + JobTimingTest.ms(OtherRealtime.TOLERATED_NS) + "), and RSAML_TIMING_BOUNDS=required (CI runs alone): the observed"
                    + " responses cannot be checked against the bounds");
        }
        if (SAID.compareAndSet(false, true)) {
            System.out.println("SKIPPED (bound check): while another program's real-time threads (SCHED_FIFO, SCHED_RR, SCHED_DEADLINE)"
                    + " run on this machine, they take the CPUs at priorities the analysis does not know, so the runs in which they used more"
                    + " than " + JobTimingTest.ms(OtherRealtime.TOLERATED_NS) + " of CPU time are not checked against the analysis's bounds"
                    + " (only their measurement and report are); CI, which runs alone, sets RSAML_TIMING_BOUNDS=required and fails instead");
        }
        System.out.println("SKIPPED (bound check) " + what + ": other programs' real-time threads ran: " + others);
    }
}
