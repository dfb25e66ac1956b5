/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.LongPredicate;
import java.util.stream.Stream;

/**
 * Other programs' real-time threads during a timing test's run (docs/timing.md, "Other programs'
 * real-time threads"): a thread of another program under {@code SCHED_FIFO}, {@code SCHED_RR} or
 * {@code SCHED_DEADLINE} can take a CPU from the measured program at a priority the analysis does not
 * know, for as long as it runs, and no longer. So what counts is the CPU time such threads used
 * during the run, read from {@code /proc} before, during (four times a second) and after it: a system
 * service that owns a real-time thread and sleeps (multipathd, rtkit-daemon) uses none, or a few
 * microseconds when it wakes. Up to {@link #TOLERATED_NS} in all, the run's bounds are still checked
 * and that time is added to the allowance (a job cannot be delayed by more CPU time than the threads
 * used); beyond it they are not checked ({@link PlatformCheck#boundCheck}). The test's own programs are
 * never counted, the platform monitor ({@link PlatformCheck.Monitor}) among them: the test starts it.
 */
final class OtherRealtime {
    private OtherRealtime() {
    }

    /** The CPU time other programs' real-time threads may use during a run whose bounds are still checked. */
    static final long TOLERATED_NS = 1_000_000;

    /** Clock ticks per second of /proc's utime and stime (USER_HZ, 100 on Linux's usual architectures). */
    private static final long TICK_NS = 10_000_000;

    /** A real-time thread of another program, as /proc showed it: the CPU time it had used so far. */
    record RtThread(long pid, long tid, String command, String name, long cpuNs) {
        String key() {
            return pid + "/" + tid;
        }

        /** "pid command", and the thread when it is not the process's main one or is named otherwise. */
        String describe() {
            return pid + " " + command + (tid == pid && name.equals(command) ? "" : " thread " + tid + " " + name);
        }
    }

    /** What other programs' real-time threads used during a run: each thread that used CPU time, and how much. */
    record Use(Map<String, Long> ranNs) {
        static final Use NONE = new Use(Map.of());

        long totalNs() {
            return ranNs.values().stream().mapToLong(Long::longValue).sum();
        }

        /** Whether the run's bounds can still be checked, with this time in the allowance. */
        boolean tolerated() {
            return totalNs() <= TOLERATED_NS;
        }

        @Override
        public String toString() {
            if (ranNs.isEmpty()) {
                return "none ran";
            }
            List<String> each = new ArrayList<>();
            ranNs.forEach((thread, ns) -> each.add(thread + " ran " + JobTimingTest.ms(ns)));
            return JobTimingTest.ms(totalNs()) + " of CPU time in all: " + String.join(", ", each);
        }
    }

    /**
     * The real-time threads (policy 1, 2 or 6: field 41 of a thread's stat) of the user processes under
     * {@code proc} (kernel threads, by the flags of their stat, and the processes {@code ours} names left
     * out), with the CPU time each has used: the first field of its schedstat (nanoseconds), or where
     * there is none, its utime and stime (fields 14 and 15 of its stat, in clock ticks).
     */
    static List<RtThread> scan(Path proc, LongPredicate ours) {
        List<RtThread> found = new ArrayList<>();
        List<Path> processes;
        try (Stream<Path> s = Files.list(proc)) {
            processes = s.filter(p -> p.getFileName().toString().chars().allMatch(Character::isDigit)).toList();
        } catch (IOException e) {
            return found;
        }
        for (Path process : processes) {
            long pid = Long.parseLong(process.getFileName().toString());
            try {
                if (ours.test(pid)) {
                    continue;
                }
                String processStat = Files.readString(process.resolve("stat"));
                if (kernelThread(processStat)) {
                    continue;
                }
                String command = comm(processStat);
                List<Path> tasks;
                try (Stream<Path> s = Files.list(process.resolve("task"))) {
                    tasks = s.toList();
                }
                for (Path task : tasks) {
                    String stat = Files.readString(task.resolve("stat"));
                    String[] fields = fields(stat);
                    int policy = Integer.parseInt(fields[38]);
                    if (policy == 1 || policy == 2 || policy == 6) {
                        found.add(new RtThread(pid, Long.parseLong(task.getFileName().toString()), command, comm(stat), cpuNs(task, fields)));
                    }
                }
            } catch (IOException | RuntimeException e) {
                // the process or thread ended while being read
            }
        }
        return found;
    }

    /** PF_KTHREAD, in a task's flags (field 9 of its stat). */
    private static final long KERNEL_THREAD = 0x00200000L;

    /**
     * Whether a process is one of the kernel's, by the flags of its stat. Not by its cmdline (empty for the kernel's):
     * reading a process's cmdline takes its memory map's lock, and this scan runs four times a second while the
     * programs under test run at real-time priority; a reader of normal priority holding that lock while the
     * real-time threads keep both cores busy would delay any of their threads that maps memory or faults a page in.
     */
    static boolean kernelThread(String stat) {
        return (Long.parseUnsignedLong(fields(stat)[6]) & KERNEL_THREAD) != 0;
    }

    /** The fields of a stat after the command's closing parenthesis: [0] is field 3 (the state). */
    private static String[] fields(String stat) {
        return stat.substring(stat.lastIndexOf(')') + 2).split(" ");
    }

    private static String comm(String stat) {
        return stat.substring(stat.indexOf('(') + 1, stat.lastIndexOf(')'));
    }

    private static long cpuNs(Path task, String[] stat) throws IOException {
        Path schedstat = task.resolve("schedstat");
        if (Files.isRegularFile(schedstat)) {
            return Long.parseLong(Files.readString(schedstat).strip().split("\\s+")[0]);
        }
        return (Long.parseLong(stat[11]) + Long.parseLong(stat[12])) * TICK_NS;
    }

    /**
     * The CPU time each thread used between the scans it was added in: from its first scan to its
     * last for a thread seen in the first one; all of it for a thread that appeared later (or turned
     * real-time later), which ran only during the run as far as is known.
     */
    static final class Ledger {
        private final Map<String, long[]> cpu = new LinkedHashMap<>();
        private final Map<String, String> names = new LinkedHashMap<>();
        private boolean first = true;

        synchronized void add(List<RtThread> scan) {
            for (RtThread t : scan) {
                long[] seen = cpu.get(t.key());
                if (seen == null) {
                    cpu.put(t.key(), new long[] {first ? t.cpuNs() : 0, t.cpuNs()});
                    names.put(t.key(), t.describe());
                } else {
                    seen[1] = Math.max(seen[1], t.cpuNs());
                }
            }
            first = false;
        }

        synchronized Use use() {
            Map<String, Long> ran = new LinkedHashMap<>();
            cpu.forEach((key, c) -> {
                if (c[1] > c[0]) {
                    ran.merge(names.get(key), c[1] - c[0], Long::sum);
                }
            });
            return new Use(ran);
        }
    }

    /**
     * Whether {@code pid} is this test's JVM or a process it started, asked when the process is found (a program the
     * test starts while /proc is being read is its child by then; one left behind by an earlier run, handed to init, is not).
     */
    static boolean startedByThisTest(long pid) {
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

    /** Reads this machine's /proc before a run, four times a second while it lasts, and when it is stopped. */
    static final class Watch implements AutoCloseable {
        private final Ledger ledger = new Ledger();
        private final Thread thread;
        private volatile boolean closed;

        Watch() {
            ledger.add(scan(Path.of("/proc"), OtherRealtime::startedByThisTest));
            thread = new Thread(() -> {
                while (!closed) {
                    try {
                        Thread.sleep(250);
                    } catch (InterruptedException e) {
                        return;
                    }
                    ledger.add(scan(Path.of("/proc"), OtherRealtime::startedByThisTest));
                }
            }, "rsaml-realtime-watch");
            thread.setDaemon(true);
            thread.start();
        }

        /** Stops the watch: what other programs' real-time threads used from its start to now. */
        Use stop() throws InterruptedException {
            if (!closed) {
                closed = true;
                thread.interrupt();
                thread.join();
                ledger.add(scan(Path.of("/proc"), OtherRealtime::startedByThisTest));
            }
            return ledger.use();
        }

        @Override
        public void close() throws InterruptedException {
            stop();
        }
    }
}
