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
        PlatformCheck.Allowance a = new PlatformCheck.Allowance(200_000, "measured", use);
        assertEquals(200_000 + PlatformCheck.BOOKKEEPING_NS + 30_000, a.ns(), "start latency, bookkeeping and the others' CPU time");
        assertTrue(a.toString().contains("0.030 ms other programs' real-time threads ran (0.030 ms of CPU time in all: 812 multipathd"),
                "the allowance says whose time it counts: " + a);
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
