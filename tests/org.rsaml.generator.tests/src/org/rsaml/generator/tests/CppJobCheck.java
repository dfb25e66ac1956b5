/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Reaction;
import org.rsaml.analysis.plan.Release;
import org.rsaml.generator.internal.cxx.OneMachineCpus;
import org.rsaml.model.Architecture;

/**
 * Runs a generated C++ program as {@link JobTimingTest} does (with {@code --busy-work 100}, for
 * {@link #RUN_MS}) and checks its summary lines against the model and the timing analysis
 * (docs/timing.md, "What the C++ program measures"): a line per timed release and per reacting
 * module, the analysis's bound written into the program, the modeled deadline and execution time,
 * about one job a period on the release's grid, the busy work consumed, a line per miss and per
 * overrun; and, for the releases scheduled as analysed with a CPU of their own, the worst observed
 * response within its bound computed again with the platform's loss, which the platform monitor,
 * run around the program, measured on every CPU, as {@link PlatformCheck#boundCheck} decides (said on
 * standard output where not); a CPU of their own as {@link PlatformCheck#notApart} decides.
 */
final class CppJobCheck {
    private CppJobCheck() {
    }

    static final long RUN_MS = 700;

    /** A bound to check once the run's allowance is known. */
    private record Bounded(String label, org.rsaml.model.Module module, JobSummary summary, long bound) {
    }

    /** Where the job was scheduled as analysed, its bound to check; else noted in unchecked. */
    private static void toCheck(Architecture arch, org.rsaml.model.Module module, String label, JobSummary s, Long bound,
            List<Bounded> checks, List<String> unchecked) {
        if (bound == null) {
            return;
        }
        String apart = PlatformCheck.notApart(arch, module, PlatformCheck.Placement.CPP);
        PlatformCheck.requireRealtime("JobTimingTest", label, s.sched());
        if (!s.asAnalysed() || apart != null) {
            unchecked.add(label + " (" + (apart != null ? apart : s.sched()) + ")");
            return;
        }
        checks.add(new Bounded(label, module, s, bound));
    }

    /**
     * Runs the program with busy work as modeled and checks every release's summary against the
     * model and the analysis; the bound itself where the release was scheduled as analysed.
     */
    static Map<String, JobSummary> runAndCheck(Architecture arch, Path project, String what) throws Exception {
        return run(arch, project, what).summaries();
    }

    /**
     * What one checked run saw: the summaries, the allowance its bounds were checked with (null when they were not), and
     * the program's output.
     */
    record Run(Map<String, JobSummary> summaries, PlatformCheck.Allowance allowance, OtherRealtime.Use others, String output) {
    }

    /**
     * As {@link #runAndCheck}, the platform monitor started with {@code monitorOptions} (e.g. a synthetic
     * hiccup) around the program; what the run saw and the allowance it was checked with.
     */
    static Run run(Architecture arch, Path project, String what, String... monitorOptions) throws Exception {
        return run(arch, project, what, RUN_MS, monitorOptions);
    }

    /** As {@link #run(Architecture, Path, String, String...)}, the program run for {@code runMs} milliseconds. */
    static Run run(Architecture arch, Path project, String what, long runMs, String... monitorOptions) throws Exception {
        Path exe = Tools.cmakeBuild(project, CppExamplesTest.executableName(project));
        String output;
        OtherRealtime.Use others;
        PlatformCheck.Platform platform;
        try (OtherRealtime.Watch watch = new OtherRealtime.Watch(); PlatformCheck.Monitor monitor = PlatformCheck.Monitor.start(monitorOptions)) {
            output = Tools.ok(project, 60, exe.toString(), "--run-for-ms", Long.toString(runMs), "--quiet", "--busy-work", "100");
            platform = monitor.stop();
            others = watch.stop();
        }
        Map<String, JobSummary> summaries = JobSummary.of(output);
        ExecutionPlan plan = ExecutionPlan.of(arch);
        Map<String, Long> bounds = JobTimingTest.bounds(TimingAnalysis.analyse(arch));
        RunTrace trace = new RunTrace(output);
        RunTrace.assertNoneDropped(what, output);
        List<String> labels = new ArrayList<>(plan.releases().stream().map(Release::label).toList());
        plan.reactions().forEach(x -> labels.add(x.label()));
        assertEquals(labels.stream().sorted().toList(), summaries.keySet().stream().sorted().toList(),
                what + ": a summary line per timed release and per reacting module\n" + Tools.last(output, 3000));
        List<String> unchecked = new ArrayList<>();
        List<Bounded> checks = new ArrayList<>();
        for (Reaction x : plan.reactions()) {
            JobSummary s = summaries.get(x.label());
            Long bound = bounds.get(x.label());
            assertEquals(bound == null ? "none" : JobTimingTest.ms(bound), s.bound(), what + ": the analysis's bound, written into the program: " + s);
            assertEquals(x.deadlineNs(), s.deadlineNs(), what + ": the modeled deadline of the reactions: " + s);
            assertEquals(x.costNs(), s.modeledNs(), what + ": the modeled execution time of a reaction: " + s);
            if (s.jobs() > 0) {
                assertTrue(s.executionNs() >= x.costNs() * 9 / 10, what + ": the busy work consumed the modeled time: " + s);
            }
            assertEquals(s.misses(), trace.matching("miss " + x.label() + " job ").size(), what + ": a line per miss of " + x.label());
            assertEquals(s.overruns(), trace.matching("overrun " + x.label() + " job ").size(), what + ": a line per overrun of " + x.label());
            if (bound != null) {
                // a message its full mailbox dropped is a job of the bounded reactions never released nor measured
                java.util.regex.Matcher dropped = java.util.regex.Pattern.compile("mailbox " + java.util.regex.Pattern.quote(x.module().qualifiedName())
                        + " dropped (\\d+) messages in all").matcher(output);
                if (dropped.find()) {
                    org.junit.jupiter.api.Assertions.fail(what + ": " + x.label() + ": " + dropped.group(1)
                            + " messages dropped, the worker behind: jobs not measured\n" + Tools.last(output, 3000));
                }
            }
            toCheck(arch, x.module().module(), x.label(), s, bound, checks, unchecked);
        }
        for (Release r : plan.releases()) {
            JobSummary s = summaries.get(r.label());
            Long bound = bounds.get(r.label());
            assertEquals(bound == null ? "none" : JobTimingTest.ms(bound), s.bound(), what + ": the analysis's bound, written into the program: " + s);
            assertEquals(r.deadlineNs(), s.deadlineNs(), what + ": the modeled deadline: " + s);
            assertEquals(r.costNs(), s.modeledNs(), what + ": the modeled execution time: " + s);
            // about one a period; the releases go on until the threads see the stop (within 20 ms, later on a loaded machine)
            long expected = (runMs * 1_000_000 - r.offsetNs()) / r.periodNs() + 1;
            long most = ((runMs + 500) * 1_000_000 - r.offsetNs()) / r.periodNs() + 1;
            assertTrue(s.jobs() >= Math.max(1, expected / 2) && s.jobs() <= most,
                    what + ": " + s.jobs() + " jobs of " + r.label() + " in " + runMs + " ms, expected about " + expected);
            assertTrue(s.executionNs() >= r.costNs() * 9 / 10, what + ": the busy work consumed the modeled time: " + s);
            assertEquals((s.jobs() - 1) * r.periodNs(), s.lastNs() - s.firstNs(), 2_000,
                    what + ": the jobs of " + r.label() + " released on its grid, one every period, none skipped: " + s);
            assertEquals(s.misses(), trace.matching("miss " + r.label() + " job ").size(), what + ": a line per miss of " + r.label());
            assertEquals(s.overruns(), trace.matching("overrun " + r.label() + " job ").size(),
                    what + ": a line per overrun of " + r.label());
            if (s.misses() > 0) {
                assertTrue(s.worstNs() > s.deadlineNs(), what + ": a miss is a response past the deadline: " + s);
            }
            if (s.sched().startsWith("SCHED_DEADLINE")) {
                // the kernel's word that a deadline thread's runtime ran out (SCHED_FLAG_DL_OVERRUN), as the program reported it
                List<String> throttled = trace.matching("throttled " + r.label() + " job ");
                System.out.println("JobTimingTest " + what + ": " + r.label() + " under SCHED_DEADLINE, its runtime ran out " + throttled.size()
                        + " time(s) in " + s.jobs() + " jobs" + (throttled.isEmpty() ? "" : ": " + throttled));
            }
            toCheck(arch, r.module().module(), r.label(), s, bound, checks, unchecked);
        }
        PlatformCheck.Allowance allowance = null;
        if (!checks.isEmpty()) {
            // the CPU of each checked thread: its processor's on this machine (a checked thread has it to itself), else the worst CPU
            Map<org.rsaml.model.Processor, Integer> cpus = OneMachineCpus.of(arch);
            Map<String, Integer> cpuOf = new java.util.HashMap<>();
            for (Bounded c : checks) {
                org.rsaml.model.Processor p = PlatformCheck.processorOf(arch, c.module());
                if (p != null && p.getCore() >= 0 && cpus.get(p) < Runtime.getRuntime().availableProcessors()) {
                    cpuOf.put(c.label(), cpus.get(p));
                }
            }
            PlatformCheck.BoundCheck check = PlatformCheck.boundCheck("JobTimingTest " + what, others, platform, TimingAnalysis.analyse(arch),
                    summaries, label -> cpuOf.getOrDefault(label, -1), PlatformCheck.BOOKKEEPING_NS);
            allowance = check.allowance();
            if (allowance == null) {
                checks.forEach(c -> unchecked.add(c.label() + " (" + check.notChecked() + ")"));
                checks.clear();
            } else {
                System.out.println("JobTimingTest " + what + ": measured " + allowance);
            }
            List<String> contradictions = new ArrayList<>();
            for (Bounded c : checks) {
                JobSummary s = c.summary();
                if (PlatformCheck.uncheckedByMonitor("JobTimingTest " + what, c.label(), allowance, unchecked)) {
                    continue;
                }
                System.out.printf(Locale.ROOT, "JobTimingTest %s: %s %d jobs, worst response %s (start latency %s, stall %s), %s, %s%n",
                        what, c.label(), s.jobs(), JobTimingTest.ms(s.worstNs()), JobTimingTest.ms(s.latencyNs()), JobTimingTest.ms(s.stallNs()),
                        allowance.explain(c.label()), s.sched());
                if (!allowance.admits(c.label())) {
                    contradictions.add(c.label() + ": worst observed response " + JobTimingTest.ms(s.worstNs()) + " exceeds its bound: "
                            + allowance.explain(c.label()));
                }
            }
            assertTrue(contradictions.isEmpty(), what + " contradicts the timing analysis:\n  " + String.join("\n  ", contradictions)
                    + "\n  " + allowance + "\n" + Tools.last(output, 3000));
        }
        if (!unchecked.isEmpty()) {
            System.out.println("JobTimingTest " + what + ": not scheduled as analysed on this machine: " + unchecked
                    + ": the bound is not asserted for them, only the measurement and the report");
        }
        return new Run(summaries, allowance, others, output);
    }
}
