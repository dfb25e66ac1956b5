/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentSkipListSet;
import java.util.concurrent.atomic.AtomicBoolean;

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
 * allowance").
 * <p>
 * <b>The allowance</b> is measured, not fixed: the worst start latency (release to the job's start:
 * the timer's wake-up, the executor's dispatch on ROS 2) of the run's <i>probe</i> releases, those
 * nothing in the model can delay at their start (alone at the top rank of a fixed-priority processor
 * whose CPU is its own, scheduled as analysed), measured in the same run, under the same load; a run
 * without such a release (EDF processors, one shared rank) takes it from a calibration run of a C++
 * program of one probe per core, run just after. To it comes {@link #BOOKKEEPING_NS}, stated.
 * <p>
 * <b>Other programs' real-time threads</b> ({@link RealtimeWatch}) take the CPUs at priorities the
 * analysis does not know: while any run, the bound is not checked, said once in the output. CI runs
 * alone: with {@code RSAML_TIMING_BOUNDS=required} in the environment (set by {@code .ci/run}; the
 * test JVM inherits it), such a run fails instead, so the check cannot silently stop.
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

    /** The allowance of one run: the measured platform start latency plus the stated bookkeeping, and where it came from. */
    record Allowance(long latencyNs, String source) {
        long ns() {
            return latencyNs + BOOKKEEPING_NS;
        }

        @Override
        public String toString() {
            return JobTimingTest.ms(ns()) + " = " + JobTimingTest.ms(latencyNs) + " platform start latency (" + source + ") + "
                    + JobTimingTest.ms(BOOKKEEPING_NS) + " stated for bookkeeping";
        }
    }

    /** Whether the environment demands the bound check (CI, which runs alone): then no other program's real-time thread is tolerated. */
    static boolean required() {
        String mode = System.getenv("RSAML_TIMING_BOUNDS");
        return "required".equals(mode);
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

    /** The allowance measured by the run's probes, or null when it has none. */
    /**
     * The allowance of a run: from its own releases that nothing delays, else from a calibration run; {@code null}
     * when neither got real-time scheduling, which fails where the check is {@link #required()}.
     */
    static Allowance forRun(List<Release> probes, Map<String, JobSummary> summaries) throws Exception {
        Allowance allowance = fromRun(probes, summaries);
        if (allowance == null) {
            allowance = calibrate();
        }
        if (allowance == null && required()) {
            fail("RSAML_TIMING_BOUNDS=required: the calibration run got no real-time scheduling, so no bound can be checked");
        }
        return allowance;
    }

    static Allowance fromRun(List<Release> probes, Map<String, JobSummary> summaries) {
        if (probes.isEmpty()) {
            return null;
        }
        long worst = 0;
        String by = "";
        for (Release r : probes) {
            long latency = summaries.get(r.label()).latencyNs();
            if (latency >= worst) {
                worst = latency;
                by = r.label();
            }
        }
        return new Allowance(worst, "measured in this run: the worst start latency of " + by + ", alone at its processor's top rank, of "
                + probes.size() + " such release" + (probes.size() == 1 ? "" : "s"));
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
        long worst = -1;
        for (JobSummary s : JobSummary.of(output).values()) {
            if (!s.asAnalysed() || s.jobs() == 0) {
                return null;
            }
            worst = Math.max(worst, s.latencyNs());
        }
        return worst < 0 ? null
                : new Allowance(worst, "measured by a calibration run just after: the worst start latency of a lone top-rank release on each of "
                        + Runtime.getRuntime().availableProcessors() + " cores, 500 ms");
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
     * Says once, for the whole test run, why bounds go unchecked while other programs have real-time
     * threads, and what this run saw; where the check is required (CI), fails instead.
     */
    static void otherRealtime(String what, Set<String> others) {
        if (required()) {
            fail(what + ": other programs had real-time threads during the run (" + others + "), and RSAML_TIMING_BOUNDS=required"
                    + " (CI runs alone): the observed responses cannot be checked against the bounds");
        }
        if (SAID.compareAndSet(false, true)) {
            System.out.println("SKIPPED (bound check): while another program on this machine has real-time threads (SCHED_FIFO, SCHED_RR,"
                    + " SCHED_DEADLINE), they take the CPUs at priorities the analysis does not know, so the runs they overlap are not"
                    + " checked against the analysis's bounds (only their measurement and report are); CI, which runs alone, sets"
                    + " RSAML_TIMING_BOUNDS=required and fails instead");
        }
        System.out.println("SKIPPED (bound check) " + what + ": other programs' real-time threads ran: " + others);
    }

    /**
     * Real-time threads (SCHED_FIFO, SCHED_RR, SCHED_DEADLINE) of user processes other than this JVM
     * and the programs it started, as "pid command". Read from /proc (policy: field 41 of a thread's stat).
     */
    static Set<String> otherRealtimeThreads() {
        Set<String> found = new TreeSet<>();
        File[] procs = new File("/proc").listFiles((d, n) -> n.chars().allMatch(Character::isDigit));
        for (File proc : procs == null ? new File[0] : procs) {
            long pid = Long.parseLong(proc.getName());
            try {
                if (Files.readAllBytes(proc.toPath().resolve("cmdline")).length == 0 || startedByThisTest(pid)) {
                    continue; // this test and what it started, or a kernel thread
                }
                File[] tasks = new File(proc, "task").listFiles();
                for (File task : tasks == null ? new File[0] : tasks) {
                    String stat = Files.readString(task.toPath().resolve("stat"));
                    String[] fields = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
                    int policy = Integer.parseInt(fields[38]); // field 41 of stat, counted from field 3
                    if (policy == 1 || policy == 2 || policy == 6) {
                        found.add(pid + " " + stat.substring(stat.indexOf('(') + 1, stat.lastIndexOf(')')));
                        break;
                    }
                }
            } catch (IOException | RuntimeException e) {
                // the process ended while being read
            }
        }
        return found;
    }

    /**
     * Whether {@code pid} is this test's JVM or a process it started, asked when the process is found (a program the
     * test starts while /proc is being read is its child by then; one left behind by an earlier run, handed to init, is not).
     */
    private static boolean startedByThisTest(long pid) {
        long self = ProcessHandle.current().pid();
        java.util.Optional<ProcessHandle> process = ProcessHandle.of(pid);
        for (int depth = 0; process.isPresent() && depth < 64; depth++) {
            if (process.get().pid() == self) {
                return true;
            }
            process = process.get().parent();
        }
        return false;
    }

    /** Looks for other programs' real-time threads four times a second while a run lasts. */
    static final class RealtimeWatch implements AutoCloseable {
        private final Set<String> seen = new ConcurrentSkipListSet<>();
        private final Thread thread;
        private volatile boolean closed;

        RealtimeWatch() {
            seen.addAll(otherRealtimeThreads());
            thread = new Thread(() -> {
                while (!closed) {
                    seen.addAll(otherRealtimeThreads());
                    try {
                        Thread.sleep(250);
                    } catch (InterruptedException e) {
                        return;
                    }
                }
            }, "rsaml-realtime-watch");
            thread.setDaemon(true);
            thread.start();
        }

        /** What was seen so far. */
        Set<String> seen() {
            return new TreeSet<>(seen);
        }

        @Override
        public void close() throws InterruptedException {
            closed = true;
            thread.join();
            seen.addAll(otherRealtimeThreads());
        }
    }
}
