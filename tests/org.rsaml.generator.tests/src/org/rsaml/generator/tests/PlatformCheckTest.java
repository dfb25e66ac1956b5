/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The timing tests skip (or, under RSAML_TIMING_BOUNDS=required, fail) their bound check only when
 * other programs' real-time threads used CPU time during the run ({@link OtherRealtime}): a system
 * service that owns an idle real-time thread must not count, one that ran must, named with the CPU
 * time it took, and the test's own programs never. Decided on /proc fixtures written here, and seen
 * once on this machine's /proc.
 */
class PlatformCheckTest {

    /** A thread's stat line: pid, comm, state, then fields 4 to 52, with utime/stime (14, 15) and the policy (41) set. */
    private static String stat(long tid, String comm, long flags, long utime, long stime, int policy) {
        StringBuilder sb = new StringBuilder(tid + " (" + comm + ") S");
        for (int field = 4; field <= 52; field++) {
            sb.append(' ').append(field == 9 ? flags : field == 14 ? utime : field == 15 ? stime : field == 41 ? policy : 0);
        }
        return sb.append('\n').toString();
    }

    /** Writes /proc/PID (its stat and one thread's stat, with a schedstat when cpuNs >= 0). */
    private static void thread(Path proc, long pid, String command, long tid, String name, int policy, long cpuNs, long ticks)
            throws Exception {
        Path p = Files.createDirectories(proc.resolve(Long.toString(pid)));
        // a kernel thread (command "") has PF_KTHREAD among its flags; a user process's flags here are PF_FORKNOEXEC | PF_RANDOMIZE
        long flags = command.isEmpty() ? 0x00208040L : 0x00400040L;
        Files.writeString(p.resolve("stat"), stat(pid, command.isEmpty() ? "kworker/0:1" : command, flags, 0, 0, 0));
        Path t = Files.createDirectories(p.resolve("task/" + tid));
        Files.writeString(t.resolve("stat"), stat(tid, name, flags, ticks, 0, policy));
        if (cpuNs >= 0) {
            Files.writeString(t.resolve("schedstat"), cpuNs + " 1200 7\n");
        } else {
            Files.deleteIfExists(t.resolve("schedstat"));
        }
    }

    @Test
    void onlyOtherProgramsRealtimeThreadsThatRanCountWithTheirCpuTime(@TempDir Path proc) throws Exception {
        // before the run: an idle multipathd (SCHED_RR), rtkit's canary (SCHED_FIFO), a busy SCHED_FIFO
        // program, one under SCHED_DEADLINE, a kernel thread, the test's own program and a normal one
        thread(proc, 812, "multipathd", 815, "multipathd", 2, 4_100_000, 0);
        thread(proc, 990, "rtkit-daemon", 992, "rtkit-daemon", 1, 700_000, 0);
        thread(proc, 2001, "spinner", 2001, "spinner", 1, 10_000_000, 0);
        thread(proc, 2100, "controller", 2103, "worker", 6, 50_000, 0);
        thread(proc, 17, "", 17, "migration/0", 1, 9_000_000, 0);
        thread(proc, 3000, "ours", 3000, "ours", 1, 0, 0);
        thread(proc, 3500, "editor", 3500, "editor", 0, 0, 0);
        OtherRealtime.Ledger ledger = new OtherRealtime.Ledger();
        List<OtherRealtime.RtThread> before = OtherRealtime.scan(proc, pid -> pid == 3000);
        assertEquals(List.of("2001 spinner", "2100 controller thread 2103 worker", "812 multipathd thread 815 multipathd",
                "990 rtkit-daemon thread 992 rtkit-daemon"), before.stream().map(OtherRealtime.RtThread::describe).sorted().toList(),
                "the real-time threads of other user programs: not the kernel's, not the test's own, not a normal one");
        ledger.add(before);

        // during the run: multipathd and rtkit sleep, the spinner takes 250 ms, the test's own program runs
        thread(proc, 2001, "spinner", 2001, "spinner", 1, 260_000_000, 0);
        thread(proc, 3000, "ours", 3000, "ours", 1, 400_000_000, 0);
        ledger.add(OtherRealtime.scan(proc, pid -> pid == 3000));
        OtherRealtime.Use use = ledger.use();
        assertEquals(Map.of("2001 spinner", 250_000_000L), use.ranNs(), "only the spinner ran, 250 ms: " + use);
        assertFalse(use.tolerated(), "250 ms of another program's real-time CPU time is not tolerated: " + use);
        assertTrue(use.toString().contains("2001 spinner ran 250.000 ms"), "the thread that ran, named with its CPU time: " + use);

        // the service wakes briefly, a thread appears under SCHED_FIFO: all its time counts (it ran only during the run);
        // without the spinner, that is little enough to be tolerated
        OtherRealtime.Ledger quiet = new OtherRealtime.Ledger();
        quiet.add(OtherRealtime.scan(proc, pid -> pid == 3000 || pid == 2001));
        thread(proc, 812, "multipathd", 815, "multipathd", 2, 4_130_000, 0);
        thread(proc, 4000, "helper", 4000, "helper", 1, 200_000, 0);
        quiet.add(OtherRealtime.scan(proc, pid -> pid == 3000 || pid == 2001));
        OtherRealtime.Use little = quiet.use();
        assertEquals(Map.of("812 multipathd thread 815 multipathd", 30_000L, "4000 helper", 200_000L), little.ranNs(),
                "the service's wake-up and the new thread's time: " + little);
        assertTrue(little.tolerated(), "0.23 ms of other programs' real-time CPU time is tolerated (and allowed for): " + little);

        // without schedstat, utime + stime in clock ticks (10 ms each)
        OtherRealtime.Ledger ticks = new OtherRealtime.Ledger();
        thread(proc, 5000, "legacy", 5000, "legacy", 2, -1, 3);
        ticks.add(OtherRealtime.scan(proc, pid -> pid != 5000));
        thread(proc, 5000, "legacy", 5000, "legacy", 2, -1, 5);
        ticks.add(OtherRealtime.scan(proc, pid -> pid != 5000));
        assertEquals(Map.of("5000 legacy", 20_000_000L), ticks.use().ranNs(), "two ticks of utime: 20 ms");
    }

    @Test
    void theAllowanceCountsTheToleratedTimeAndSaysWhoseItIs() {
        OtherRealtime.Use use = new OtherRealtime.Use(Map.of("812 multipathd thread 815 multipathd", 30_000L));
        PlatformCheck.Allowance a = new PlatformCheck.Allowance(200_000, 150_000, "measured", use);
        assertEquals(200_000 + 150_000 + PlatformCheck.BOOKKEEPING_NS + 30_000, a.ns(), "start latency, stall, bookkeeping and the others' CPU time");
        assertTrue(a.toString().contains("0.030 ms other programs' real-time threads ran (0.030 ms of CPU time in all: 812 multipathd"),
                "the allowance says whose time it counts: " + a);
    }

    /** A summary line as both runtimes write it (times in ms), in a trace line. */
    private static String summary(String label, double response, double bound, double execution, double modeled, double latency, double stall,
            int rank) {
        return String.format(java.util.Locale.ROOT, "[  1200.000 ms] summary %s jobs 100 released 10.000..1190.000 ms misses 0 overruns %d"
                + " worst-response %.3f ms bound %.3f ms deadline %.3f ms worst-execution %.3f ms modeled %.3f ms worst-start-latency %.3f ms"
                + " worst-stall %.3f ms sched SCHED_FIFO rank %d%n", label, execution > modeled ? 1 : 0, response, bound, Math.max(bound, 10.0),
                execution, modeled, latency, stall, rank);
    }

    @Test
    void theAllowanceHoldsTheProbesWorstStallSoAStallOfThePlatformDuringAJobPasses() {
        // The run that failed CI (mobile-base-latency): core 0's lone top-rank release started 5.3 ms late, and at the same
        // instant core 1's, obstacleDetector.detect, started on time but took 10.41 ms for 3.99 ms of CPU time: the platform
        // stalled both cores. The path planner, at a lower rank, stalled longer still, but its stall holds the preemptions
        // by the higher ranks (which its bound counts) and is no probe's.
        Map<String, JobSummary> run = JobSummary.of(summary("control/velocityController.control", 6.3, 3.0, 0.95, 1.0, 5.3, 0.05, 3)
                + summary("navigation/obstacleDetector.detect", 10.41, 4.0, 3.99, 4.0, 0.08, 6.33, 3)
                + summary("navigation/pathPlanner.plan", 44.0, 38.0, 20.0, 20.0, 6.0, 24.0, 1));
        assertEquals(6_330_000, run.get("navigation/obstacleDetector.detect").stallNs(), "the summary's worst-stall is read");
        PlatformCheck.Allowance a = PlatformCheck.fromRun(List.of("control/velocityController.control", "navigation/obstacleDetector.detect"), run);
        assertEquals(5_300_000, a.latencyNs(), "the probes' worst start latency: " + a);
        assertEquals(6_330_000, a.stallNs(), "the probes' worst stall, not the lower rank's 24 ms: " + a);
        assertTrue(a.toString().contains("start latency, of control/velocityController.control, and the worst stall, of"
                + " navigation/obstacleDetector.detect"), "the allowance names the probe each part came from: " + a);
        assertTrue(a.admits(run.get("navigation/obstacleDetector.detect").worstNs(), 4_000_000),
                "the stalled probe's 10.41 ms is within its 4 ms bound plus the platform's start latency and stall: " + a);
        assertFalse(new PlatformCheck.Allowance(a.latencyNs(), 0, "start latency only").admits(10_410_000, 4_000_000),
                "with the start latency alone (the allowance before) the platform's stall failed the check");
        assertTrue(a.admits(run.get("navigation/pathPlanner.plan").worstNs(), 38_000_000),
                "the planner, delayed by the same stall at its start and while it ran: " + a);
    }

    @Test
    void aDelayAtTheStartThatPullsInOneMoreHigherRankJobIsThePlatformsAndAWrongScheduleStillFails() throws Exception {
        // Another run that failed CI (mobile-base-latency, C++): velocityController and odometry are released together on
        // one core; the platform delayed both by 2.58 ms, odometry (rank 5) ran first, and velocityController (rank 4,
        // bound 3 ms = its 2 ms and one odometry job) started so late that odometry's next release fell inside its job:
        // 6.43 ms, more than 3 ms plus the 2.88 ms allowance, on a schedule exactly as analysed.
        org.rsaml.model.Architecture arch = org.rsaml.validation.ModelLoader.load(Tools.example("mobile-base-latency.rsaml"),
                "mobile-base-latency.rsaml").architecture();
        PlatformCheck.Allowance a = new PlatformCheck.Allowance(2_581_000, 1_000, "the failed run's probes")
                .reanalysed(org.rsaml.analysis.TimingAnalysis.analyse(arch));
        String label = "control/velocityController.control";
        assertFalse(a.admits(6_433_000, 3_000_000), "the plain sum, bound plus allowance, fails it: " + a);
        assertTrue(a.admits(label, 6_433_000, 3_000_000), "the analysis with the platform's start latency as release jitter counts"
                + " the second odometry job the delay pulled in: " + a.reanalysedText(label));
        long reanalysed = a.reanalysed().get(label);
        assertTrue(reanalysed < 10_000_000, "still a bound near the analysis's, not a blank cheque: " + a.reanalysedText(label));
        assertFalse(a.admits(label, reanalysed + 1_000_000, 3_000_000),
                "a response 1 ms past the re-analysed bound (a job the analysis does not count, a wrong priority) fails: " + a.reanalysedText(label));
        assertEquals(2_581_000L + 1_000_000 + 1_000 + PlatformCheck.BOOKKEEPING_NS, (long) a.reanalysed().get("control/odometry.integrate"),
                "the top rank's re-analysed bound is its cost plus the platform's latency, stall and bookkeeping, the plain sum");
    }

    @Test
    void theAllowanceStillFailsAWrongScheduleAndAnOverrun() {
        // A quiet run: the probe started at most 0.1 ms late and stalled at most 0.15 ms.
        Map<String, JobSummary> run = JobSummary.of(summary("tasks/a.run", 1.2, 1.0, 0.99, 1.0, 0.1, 0.15, 3)
                + summary("tasks/b.run", 5.4, 3.0, 1.99, 2.0, 1.2, 2.1, 2)
                + summary("tasks/c.run", 6.2, 4.0, 5.98, 4.0, 0.02, 0.1, 3));
        PlatformCheck.Allowance a = PlatformCheck.fromRun(List.of("tasks/a.run"), run);
        assertEquals(100_000 + 150_000 + PlatformCheck.BOOKKEEPING_NS, a.ns(), "the probe's start latency and stall, and the bookkeeping: " + a);
        // b waited 2 ms for a job the analysis does not count (a wrong priority): its stall is not the platform's, and it fails
        assertFalse(a.admits(run.get("tasks/b.run").worstNs(), 3_000_000),
                "a response 2.4 ms past the bound, more than the platform's 0.55 ms, fails the check: " + a);
        // c ran 5.98 ms of CPU time of a modeled 4: an overrun is CPU time, which no stall covers
        JobSummary c = run.get("tasks/c.run");
        assertEquals(1, c.overruns(), "the overrun is reported");
        assertFalse(a.admits(c.worstNs(), 4_000_000), "a job that really runs 2 ms longer than modeled fails the check: " + a);
        assertFalse(PlatformCheck.fromRun(List.of("tasks/a.run", "tasks/c.run"), run).admits(c.worstNs(), 4_000_000),
                "even as a probe, its own overrun gives no allowance: its stall is 0.1 ms");
    }

    @Test
    void anIdleRealtimeThreadOfAnotherProgramIsSeenButDoesNotCountAndTheTestsOwnAreNotSeen(@TempDir Path tmp) throws Exception {
        // Started by a shell that exits at once: the sleeper is no longer this JVM's descendant, as another program's thread.
        Tools.Result started = Tools.run(tmp, 10, "sh", "-c", "chrt -f 1 sleep 3 >/dev/null 2>&1 & echo $!; wait_for=$!; sleep 0.2; kill -0 $wait_for");
        Assumptions.assumeTrue(started.exit() == 0, "SCHED_FIFO not permitted here (chrt -f 1): " + started.output());
        long pid = Long.parseLong(started.output().lines().findFirst().orElseThrow().strip());
        try (OtherRealtime.Watch watch = new OtherRealtime.Watch()) {
            List<OtherRealtime.RtThread> seen = OtherRealtime.scan(Path.of("/proc"), OtherRealtime::startedByThisTest);
            assertTrue(seen.stream().anyMatch(t -> t.describe().equals(pid + " sleep")),
                    "another program's SCHED_FIFO thread (pid " + pid + ") is seen: " + seen);
            Thread.sleep(600);
            OtherRealtime.Use use = watch.stop();
            assertFalse(use.ranNs().containsKey(pid + " sleep"), "the sleeping thread used no CPU time during the watch: " + use);
        } finally {
            ProcessHandle.of(pid).ifPresent(ProcessHandle::destroy);
        }
        Process own = new ProcessBuilder("chrt", "-f", "1", "sleep", "1").start();
        try {
            Thread.sleep(200);
            assertFalse(OtherRealtime.scan(Path.of("/proc"), OtherRealtime::startedByThisTest).stream().anyMatch(t -> t.pid() == own.pid()),
                    "a real-time program the test started itself is not another program's");
        } finally {
            own.destroy();
        }
    }
}
