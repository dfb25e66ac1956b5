/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.generator.internal.cxx.OneMachineCpus;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Processor;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.support.RsamlLabels;

/**
 * What the observed-versus-bound checks of {@link JobTimingTest} (C++) and {@link Ros2LaunchTest}
 * (ROS 2) allow the platform, and when they cannot check at all (docs/timing.md, "The platform's
 * allowance"): one decision for both, {@link #boundCheck}.
 * <p>
 * <b>The platform is measured during the run, on every CPU</b>, by the {@link Monitor}: a program
 * the test starts before the measured program (or launch) and stops after it, one thread per CPU
 * under {@code SCHED_FIFO} at the highest priority, above every thread of the model, waking every
 * millisecond and recording how late it ran. What it records is time its CPU did not run the model
 * (the kernel, the hypervisor, another program, the monitor itself), and nothing the model does can
 * make it late. Between those wake-ups a spinner per CPU under {@code SCHED_IDLE}, below every thread,
 * records the gaps in its own run that no thread ran in (the platform's, merged into its CPU's records);
 * it takes no CPU time the model wants, and sees nothing of what is taken from a running thread of the model. Each job the program reports over its analysed bound (on CLOCK_MONOTONIC) is then held to
 * its bound computed again with the loss in that job's own window ({@link TaskCheck}: from where its level's
 * busy period may have begun to its completion, {@link Platform#lossIn}): on a fixed-priority processor by the
 * analysis itself, that loss a job above every rank released with it, so that a delay that pulls one more
 * higher-rank job into the response is counted; elsewhere the plain sum. To it come
 * {@link #BOOKKEEPING_NS}, stated (on ROS 2 with the executor's measured work, {@link #ros2BookkeepingNs}), and the CPU time other programs' real-time threads used during the
 * run, when small enough to be tolerated ({@link OtherRealtime}). A job that runs longer than modeled is
 * not covered: its execution is CPU time, and a wrong schedule's delay is the model's, which the
 * monitor, above the model, never records.
 * <p>
 * <b>Other programs' real-time threads</b> that used more than that take the CPUs at priorities the
 * analysis does not know: the run's bounds are not checked, said once in the output. CI runs alone:
 * with {@code RSAML_TIMING_BOUNDS=required} in the environment (set by {@code .ci/run}; the test JVM
 * inherits it), such a run fails instead, so the check cannot silently stop; so does a run whose
 * monitor got no real-time priority.
 */
final class PlatformCheck {
    private PlatformCheck() {
    }

    /**
     * Stated, not measured: the part of a response that is neither the platform's loss nor the modeled
     * execution time: the job's bookkeeping after its busy work (taking the clock, the sends, the trace,
     * the statistics and, on ROS 2, the executor's dispatch and return) and the context switches of its
     * preemptions.
     */
    static final long BOOKKEEPING_NS = 300_000;

    /**
     * Stated, and measured in every run: on ROS 2, the executor's own CPU work for a job beyond {@link #BOOKKEEPING_NS},
     * which a node's release thread does at its rank between two of its jobs (waking, taking the timer, dispatching the
     * callback) and the C++ runtime does not. Each node prints what it measured
     * ({@code executor <release> jobs N worst X ms mean Y ms}); a run whose worst exceeds this is checked with its own
     * worst instead ({@link #ros2BookkeepingNs}), so the check never counts less than was measured. Stated from the
     * runs of 2026-11-27 (load average 5 to 8): the worst a node measured was 0.213 and 0.318 ms.
     */
    static final long ROS2_EXECUTOR_NS = 400_000;

    private static final Pattern EXECUTOR = Pattern.compile("\\] executor (\\S+) jobs (\\d+) worst ([0-9.]+) ms mean ([0-9.]+) ms");

    /**
     * The bookkeeping of every job on ROS 2: {@link #BOOKKEEPING_NS} and the executor's work, {@link #ROS2_EXECUTOR_NS}
     * or, where a node of the run measured more for a job, the most it measured.
     */
    static long ros2BookkeepingNs(String output) {
        return BOOKKEEPING_NS + Math.max(ROS2_EXECUTOR_NS, ros2ExecutorWorstNs(output));
    }

    /** The most CPU time a ROS 2 release thread of the run spent between two of its jobs, as its node measured it; 0 when none said. */
    static long ros2ExecutorWorstNs(String output) {
        long worst = 0;
        Matcher m = EXECUTOR.matcher(output);
        while (m.find()) {
            worst = Math.max(worst, Math.round(Double.parseDouble(m.group(3)) * 1e6));
        }
        return worst;
    }

    /** The CPU of a SCHED_DEADLINE thread, which the kernel runs on any: its loss is the time every CPU was taken at once. */
    static final int EVERY_CPU = -2;

    /** A SCHED_DEADLINE job's loss ({@link Platform#lossOfDeadlineJob}), the job never switched out; or switched out. */
    static final int DEADLINE_RUN = -3;
    static final int DEADLINE_SWITCHED = -4;

    /** The name of the task that stands for what the platform took, in the analysis run again. */
    private static final String PLATFORM_TASK = "the platform (as measured)";

    /** A re-analysed bound beyond this many times the deadline is no bound: the check fails, saying so. */
    static final long UNBOUNDED_DEADLINES = 100;

    /**
     * One CPU's records of the {@link Monitor}, within the run, sorted and disjoint: the intervals from each of its waker's
     * nominal wake-ups (a late one's: from the previous record's end, {@link Platform#LATE_NS}) to the end of its record,
     * merged with the gaps its spinner saw between the wake-ups; {@code sched} what its waker got. {@code spinner}: what
     * its spinner got, how much CPU time it ran ({@code spunNs}: the time it watched) and the gaps it recorded in the run
     * ({@code gaps}, {@code gapNs} in all); {@code spinner} null where the monitor ran none ({@code --no-spin}).
     */
    record CpuRecords(int cpu, String sched, boolean overflow, long[] starts, long[] ends, String spinner, boolean gapOverflow, long spunNs,
            int gaps, long gapNs) {
        CpuRecords(int cpu, String sched, boolean overflow, long[] starts, long[] ends) {
            this(cpu, sched, overflow, starts, ends, null, false, 0, 0, 0);
        }

        /** The most time these intervals cover in any window of {@code windowNs}: a window starting where one starts (two pointers). */
        long maxCovered(long windowNs) {
            long best = 0;
            if (windowNs <= 0) {
                return best;
            }
            long sum = 0; // of the lengths of intervals i..k-1
            int k = 0;
            for (int i = 0; i < starts.length; i++) {
                long until = starts[i] + windowNs;
                while (k < starts.length && starts[k] < until) {
                    sum += ends[k] - starts[k];
                    k++;
                }
                best = Math.max(best, sum - Math.max(0, ends[k - 1] - until));
                sum -= ends[i] - starts[i];
            }
            return best;
        }

        /** The time these intervals cover between {@code fromNs} and {@code toNs}. */
        long coveredIn(long fromNs, long toNs) {
            long sum = 0;
            for (int i = firstEndingAfter(fromNs); i < starts.length && starts[i] < toNs; i++) {
                sum += Math.min(ends[i], toNs) - Math.max(starts[i], fromNs);
            }
            return sum;
        }

        /** The index of the longest interval between {@code fromNs} and {@code toNs} (as cut by them), -1 when none. */
        int longestIn(long fromNs, long toNs) {
            int at = -1;
            long best = 0;
            for (int i = firstEndingAfter(fromNs); i < starts.length && starts[i] < toNs; i++) {
                long length = Math.min(ends[i], toNs) - Math.max(starts[i], fromNs);
                if (at < 0 || length > best) {
                    at = i;
                    best = length;
                }
            }
            return at;
        }

        private int firstEndingAfter(long ns) {
            int lo = 0;
            int hi = ends.length;
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (ends[mid] <= ns) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            return lo;
        }

        /** The index of the longest interval, -1 when none. */
        int longest() {
            int at = -1;
            for (int i = 0; i < starts.length; i++) {
                if (at < 0 || ends[i] - starts[i] > ends[at] - starts[at]) {
                    at = i;
                }
            }
            return at;
        }
    }

    /**
     * The platform's loss used for one bound: at most {@code ns} of the window of {@code windowNs} on
     * {@code cpu} (-1: the worst of every CPU, for a thread that is not pinned) went to something other
     * than the model; the window starts {@code windowAtNs} after the run's start (-1: anywhere in the
     * run, the worst such window); the longest single interval the monitor recorded there, and when
     * (after the run's start).
     */
    record Loss(int cpu, long windowAtNs, long windowNs, long ns, long longestNs, long longestAtNs) {
        static final Loss NONE = new Loss(-1, -1, 0, 0, 0, 0);

        @Override
        public String toString() {
            return JobTimingTest.ms(ns) + " lost on " + (cpu == EVERY_CPU ? "every CPU at once (a SCHED_DEADLINE thread, which may run on any)"
                    : cpu == DEADLINE_RUN ? "every CPU at once until its start, then its CPU while it ran, never switched out (a SCHED_DEADLINE"
                            + " thread: its wall time less its CPU time)"
                    : cpu == DEADLINE_SWITCHED ? "every CPU at once until its start, then, switched out while it ran, at most every CPU at once"
                            + " (a SCHED_DEADLINE thread)"
                    : cpu < 0 ? "the worst CPU (the thread is not pinned)" : "CPU " + cpu)
                    + (windowAtNs < 0 ? " in a window of " + JobTimingTest.ms(windowNs)
                            : " from " + JobTimingTest.ms(windowAtNs).replace(" ms", "") + " to " + JobTimingTest.ms(windowAtNs + windowNs) + " into the run")
                    + " (its longest single delay " + JobTimingTest.ms(longestNs) + " at " + JobTimingTest.ms(longestAtNs) + " into the run)";
        }
    }

    /**
     * What the {@link Monitor} recorded during one run ({@code fromNs} to {@code toNs}, on
     * CLOCK_MONOTONIC, which is Java's {@link System#nanoTime()} on Linux), and at what priority
     * ({@code minPriority} the lowest of SCHED_FIFO: the runtimes give rank r {@code min + r}).
     * {@code aboveMonitor}: the model's own threads that run above it (SCHED_DEADLINE, above every
     * SCHED_FIFO priority), as (runtime, period) pairs: their work, which the kernel holds to its runtime
     * a period, is taken out of the loss, so that a late EDF job never counts as the platform's.
     */
    record Platform(int priority, int minPriority, List<CpuRecords> cpus, long fromNs, long toNs, List<long[]> aboveMonitor,
            List<CpuRecords> wakeUps) {
        private static final Pattern HEADER = Pattern.compile("rsaml-platform-monitor period (\\d+) ns priority (\\d+) min (\\d+) memory (.*)");
        private static final Pattern CPU = Pattern.compile("cpu (\\d+) records (\\d+)( overflow)? sched (.*)");
        private static final Pattern SPIN = Pattern.compile("spin (\\d+) gaps (\\d+)( overflow)? over (\\d+) ns ran (\\d+) ns waits (read|unread) sched (.*)");

        /**
         * A record longer than this was a late wake-up: something held the CPU at the moment the monitor was due, and it
         * may have taken the CPU at any time after the monitor's previous record ended (the waker sleeps in between, and
         * its spinner sees nothing while a thread of the model runs), so the record counts from there. The usual record takes 10 to 50 us.
         */
        static final long LATE_NS = 100_000;

        /**
         * Reads the monitor's file, keeping what falls between {@code fromNs} and {@code toNs}; a late record
         * ({@link #LATE_NS}) counts from the end of the CPU's previous record; the spinner's gaps ({@code gap CPU FROM TO})
         * are merged into their CPU's records.
         */
        static Platform parse(String text, long fromNs, long toNs) {
            String[] lines = text.split("\n");
            Matcher h = HEADER.matcher(lines.length > 0 ? lines[0] : "");
            assertTrue(h.matches(), "the platform monitor's records begin with its header: " + Tools.last(text, 500));
            Map<Integer, String> sched = new TreeMap<>();
            Map<Integer, Boolean> overflow = new TreeMap<>();
            Map<Integer, List<long[]>> intervals = new TreeMap<>();
            Map<Integer, Matcher> spinners = new TreeMap<>();
            Map<Integer, List<long[]>> gaps = new TreeMap<>();
            for (int i = 1; i < lines.length; i++) {
                Matcher c = CPU.matcher(lines[i]);
                if (c.matches()) {
                    int cpu = Integer.parseInt(c.group(1));
                    sched.put(cpu, c.group(4));
                    overflow.put(cpu, c.group(3) != null);
                    intervals.put(cpu, new ArrayList<>());
                    continue;
                }
                Matcher spin = SPIN.matcher(lines[i]);
                if (spin.matches()) {
                    spinners.put(Integer.parseInt(spin.group(1)), spin);
                    gaps.put(Integer.parseInt(spin.group(1)), new ArrayList<>());
                    continue;
                }
                String[] f = lines[i].split(" ");
                if (f[0].equals("gap")) {
                    long from = Math.max(fromNs, Long.parseLong(f[2]));
                    long to = Math.min(toNs, Long.parseLong(f[3]));
                    if (to > from) {
                        gaps.get(Integer.parseInt(f[1])).add(new long[] {from, to});
                    }
                    continue;
                }
                intervals.get(Integer.parseInt(f[0])).add(new long[] {Long.parseLong(f[1]), Long.parseLong(f[2])});
            }
            List<CpuRecords> cpus = new ArrayList<>();
            List<CpuRecords> wakeUps = new ArrayList<>();
            intervals.forEach((cpu, records) -> {
                records.sort(java.util.Comparator.comparingLong(x -> x[0]));
                List<long[]> list = new ArrayList<>();
                long previousEnd = Long.MIN_VALUE;
                for (long[] r : records) {
                    // a late wake-up: the delay may have begun any time after the monitor's previous record ended
                    long start = r[1] - r[0] > LATE_NS && previousEnd != Long.MIN_VALUE ? Math.min(r[0], previousEnd) : r[0];
                    previousEnd = r[1];
                    start = Math.max(fromNs, start);
                    long end = Math.min(toNs, r[1]);
                    if (end > start) {
                        list.add(new long[] {start, end});
                    }
                }
                wakeUps.add(new CpuRecords(cpu, sched.get(cpu), overflow.get(cpu), list.stream().mapToLong(x -> x[0]).toArray(),
                        list.stream().mapToLong(x -> x[1]).toArray()));
                Matcher spin = spinners.get(cpu);
                if (spin == null) {
                    cpus.add(wakeUps.get(wakeUps.size() - 1));
                    return;
                }
                List<long[]> seen = gaps.get(cpu);
                List<long[]> merged = new ArrayList<>();
                List<long[]> all = new ArrayList<>(list);
                all.addAll(seen);
                all.sort(java.util.Comparator.comparingLong(x -> x[0]));
                for (long[] r : all) { // the waker's records and the spinner's gaps, overlapping ones joined
                    long[] last = merged.isEmpty() ? null : merged.get(merged.size() - 1);
                    if (last != null && r[0] <= last[1]) {
                        last[1] = Math.max(last[1], r[1]);
                    } else {
                        merged.add(new long[] {r[0], r[1]});
                    }
                }
                cpus.add(new CpuRecords(cpu, sched.get(cpu), overflow.get(cpu), merged.stream().mapToLong(x -> x[0]).toArray(),
                        merged.stream().mapToLong(x -> x[1]).toArray(), spin.group(7), spin.group(3) != null, Long.parseLong(spin.group(5)),
                        seen.size(), seen.stream().mapToLong(x -> x[1] - x[0]).sum()));
            });
            return new Platform(Integer.parseInt(h.group(2)), Integer.parseInt(h.group(3)), List.copyOf(cpus), fromNs, toNs, List.of(),
                    List.copyOf(wakeUps));
        }

        /** This platform as its waker threads alone recorded it, without its spinners' gaps: what the check counted before them. */
        Platform wakeUpsOnly() {
            return new Platform(priority, minPriority, wakeUps, fromNs, toNs, aboveMonitor, wakeUps);
        }

        /** Whether the monitor's spinners watched between the wake-ups. */
        boolean spun() {
            return cpus.stream().anyMatch(c -> c.spinner() != null);
        }

        /** This platform, with the model's threads that run above the monitor (SCHED_DEADLINE, from the run's summaries) taken out of its loss. */
        Platform withDeadlineThreads(Map<String, JobSummary> summaries) {
            List<long[]> above = new ArrayList<>();
            for (JobSummary s : summaries.values()) {
                Matcher m = DEADLINE.matcher(s.sched());
                if (m.find()) {
                    above.add(new long[] {Math.round(Double.parseDouble(m.group(1)) * 1e6), Math.round(Double.parseDouble(m.group(2)) * 1e6)});
                }
            }
            return new Platform(priority, minPriority, cpus, fromNs, toNs, List.copyOf(above), wakeUps);
        }

        private static final Pattern DEADLINE = Pattern.compile("^SCHED_DEADLINE runtime ([0-9.]+) ms deadline [0-9.]+ ms period ([0-9.]+) ms");

        /** Null when every CPU was measured as the check needs (SCHED_FIFO at the top, every record kept), else why not. */
        String notMeasured() {
            for (CpuRecords c : cpus) {
                if (!c.sched().startsWith("SCHED_FIFO")) {
                    return "the platform monitor got no real-time scheduling on CPU " + c.cpu() + " (" + c.sched() + ")";
                }
                if (c.overflow() || c.gapOverflow()) {
                    return "the platform monitor ran out of room for its records on CPU " + c.cpu();
                }
                if (c.spinner() != null && !c.spinner().equals("SCHED_IDLE")) {
                    return "the platform monitor's spinner got no SCHED_IDLE on CPU " + c.cpu() + " (" + c.spinner() + ")";
                }
            }
            return cpus.isEmpty() ? "the platform monitor measured no CPU" : null;
        }

        /** The most time lost in any window of {@code windowNs} on {@code cpu} (-1: the worst CPU), less what the model's threads above the monitor may have run there. */
        Loss loss(int cpu, long windowNs) {
            if (cpu == EVERY_CPU && !aboveMonitor.isEmpty() && aboveMonitor.size() <= cpus.size()) {
                return everyCpuAtOnce(windowNs);
            }
            Loss worst = null;
            for (CpuRecords c : cpus) {
                if (cpu >= 0 && c.cpu() != cpu) {
                    continue;
                }
                long ns = Math.max(0, c.maxCovered(windowNs) - aboveMonitorNs(windowNs));
                int longest = c.longest();
                Loss l = new Loss(cpu, -1, windowNs, ns, longest < 0 ? 0 : c.ends()[longest] - c.starts()[longest],
                        longest < 0 ? 0 : c.starts()[longest] - fromNs);
                if (worst == null || l.ns() > worst.ns()) {
                    worst = l;
                }
            }
            return worst != null ? worst : new Loss(cpu, -1, windowNs, 0, 0, 0);
        }

        /**
         * The time lost on {@code cpu} (-1: the worst CPU) between {@code fromNs} and {@code toNs} (CLOCK_MONOTONIC), less what
         * the model's threads above the monitor may have run there: the loss in one job's own window.
         */
        Loss lossIn(int cpu, long fromNs, long toNs) {
            long from = Math.max(fromNs, this.fromNs);
            long to = Math.max(from, Math.min(toNs, this.toNs));
            long window = to - from;
            List<CpuRecords> which = new ArrayList<>();
            if (cpu == EVERY_CPU && !aboveMonitor.isEmpty() && aboveMonitor.size() <= cpus.size()) {
                which.add(everyCpu());
            } else {
                for (CpuRecords c : cpus) {
                    if (cpu < 0 || c.cpu() == cpu) {
                        which.add(c);
                    }
                }
            }
            Loss worst = null;
            for (CpuRecords c : which) {
                long ns = c.cpu() == EVERY_CPU ? c.coveredIn(from, to) : Math.max(0, c.coveredIn(from, to) - aboveMonitorNs(window));
                int longest = c.longestIn(from, to);
                Loss l = new Loss(cpu, from - this.fromNs, window, ns,
                        longest < 0 ? 0 : Math.min(c.ends()[longest], to) - Math.max(c.starts()[longest], from),
                        longest < 0 ? 0 : Math.max(c.starts()[longest], from) - this.fromNs);
                if (worst == null || l.ns() > worst.ns()) {
                    worst = l;
                }
            }
            return worst != null ? worst : new Loss(cpu, from - this.fromNs, window, 0, 0, 0);
        }

        /**
         * The loss of one job of a SCHED_DEADLINE release whose program listed where it started, its CPU time and its
         * context switches, in its window from {@code fromNs} to its completion {@code doneNs}: until its start, the time
         * every CPU was taken at once (a ready deadline job waits only while every CPU runs something else, and where the
         * model's deadline threads are no more than the CPUs one of those is the platform's); from its start, the time it
         * did not run (its wall time less its CPU time), which, where it was never switched out, is what its CPU took from
         * it (an interrupt, the hypervisor), and else at most the time every CPU was taken at once (a throttled job leaves
         * its CPU to others, which the monitor sees). Where the deadline threads outnumber the CPUs, {@link #lossIn}.
         */
        Loss lossOfDeadlineJob(long fromNs, long startNs, long doneNs, long cpuNs, long switches) {
            if (aboveMonitor.isEmpty() || aboveMonitor.size() > cpus.size()) {
                return lossIn(EVERY_CPU, fromNs, doneNs);
            }
            long from = Math.max(fromNs, this.fromNs);
            long to = Math.max(from, Math.min(doneNs, this.toNs));
            long start = Math.max(from, Math.min(startNs, to));
            CpuRecords every = everyCpu();
            long off = Math.max(0, doneNs - startNs - cpuNs);
            long ns = every.coveredIn(from, start) + (switches == 0 ? off : Math.min(off, every.coveredIn(start, to)));
            Loss any = lossIn(-1, fromNs, doneNs);
            return new Loss(switches == 0 ? DEADLINE_RUN : DEADLINE_SWITCHED, from - this.fromNs, to - from, ns, any.longestNs(), any.longestAtNs());
        }

        /**
         * For a SCHED_DEADLINE release: the most time in a window during which every CPU's monitor was delayed at once.
         * Such a job, which the kernel may run on any CPU, waits only while every CPU runs something else, and as the
         * model's deadline threads are no more than the CPUs, one of those is then the platform's (or the job's own
         * work, beside another deadline job: the check is that much looser). Its longest single delay: on any CPU.
         */
        private Loss everyCpuAtOnce(long windowNs) {
            Loss any = loss(-1, windowNs);
            return new Loss(EVERY_CPU, -1, windowNs, everyCpu().maxCovered(windowNs), any.longestNs(), any.longestAtNs());
        }

        /** The intervals during which every CPU's monitor was delayed at once. */
        private CpuRecords everyCpu() {
            long[] starts = cpus.get(0).starts();
            long[] ends = cpus.get(0).ends();
            for (CpuRecords c : cpus.subList(1, cpus.size())) {
                List<long[]> both = new ArrayList<>();
                for (int i = 0, j = 0; i < starts.length && j < c.starts().length;) {
                    long from = Math.max(starts[i], c.starts()[j]);
                    long to = Math.min(ends[i], c.ends()[j]);
                    if (from < to) {
                        both.add(new long[] {from, to});
                    }
                    if (ends[i] < c.ends()[j]) {
                        i++;
                    } else {
                        j++;
                    }
                }
                starts = both.stream().mapToLong(x -> x[0]).toArray();
                ends = both.stream().mapToLong(x -> x[1]).toArray();
            }
            return new CpuRecords(EVERY_CPU, "", false, starts, ends);
        }

        /** The most CPU time the model's SCHED_DEADLINE threads may take in a window: each its runtime in every period the window touches. */
        private long aboveMonitorNs(long windowNs) {
            long ns = 0;
            for (long[] t : aboveMonitor) {
                ns += ((windowNs + t[1] - 1) / t[1] + 1) * t[0];
            }
            return ns;
        }

        @Override
        public String toString() {
            List<String> each = new ArrayList<>();
            for (int i = 0; i < cpus.size(); i++) {
                CpuRecords c = cpus.get(i);
                CpuRecords w = wakeUps.get(i);
                int l = c.longest();
                each.add(String.format(Locale.ROOT, "CPU %d: %d wake-ups%s, longest delay %s at %s, %s in its worst 10 ms", c.cpu(), w.starts().length,
                        c.spinner() == null ? "" : String.format(Locale.ROOT, " and %d gaps between them (%s in all; the spinner ran %s)", c.gaps(),
                                JobTimingTest.ms(c.gapNs()), JobTimingTest.ms(c.spunNs())),
                        JobTimingTest.ms(l < 0 ? 0 : c.ends()[l] - c.starts()[l]), JobTimingTest.ms(l < 0 ? 0 : c.starts()[l] - fromNs),
                        JobTimingTest.ms(c.maxCovered(10_000_000))));
            }
            return "the platform monitor (SCHED_FIFO " + priority + ", every 1 ms on every CPU" + (spun() ? ", and SCHED_IDLE between" : "")
                    + ", during the run of " + JobTimingTest.ms(toNs - fromNs) + "): " + String.join("; ", each);
        }
    }

    /**
     * The platform monitor of one run: started (and running, its threads at their priority) before the
     * measured program, stopped after it. A process this test started, so {@link OtherRealtime} never
     * counts its real-time threads as another program's.
     */
    static final class Monitor implements AutoCloseable {
        private static Path program;
        private final Process process;
        private final java.io.BufferedReader output;
        private final Path records;
        private final long fromNs;

        private Monitor(Process process, java.io.BufferedReader output, Path records, long fromNs) {
            this.process = process;
            this.output = output;
            this.records = records;
            this.fromNs = fromNs;
        }

        private static synchronized Path program() throws Exception {
            if (program == null) {
                program = Tools.cmakeBuild(Tools.resource("platform-monitor"), "rsaml-platform-monitor");
            }
            return program;
        }

        /**
         * Starts the monitor ({@code options}: more of its command line, e.g. a synthetic hiccup) and waits (at most 30 s)
         * until every CPU's thread runs. It stops by itself when the thread that started it ends (its parent-death signal),
         * and after {@code --max-ms} at the latest: a monitor at the top priority never outlives its test.
         */
        static Monitor start(String... options) throws Exception {
            Path records = Files.createTempFile("rsaml-platform", ".txt");
            List<String> command = new ArrayList<>(List.of(program().toString(), "--out", records.toString()));
            command.addAll(List.of(options));
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            java.io.BufferedReader out = new java.io.BufferedReader(new java.io.InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            String ready;
            try {
                ready = java.util.concurrent.CompletableFuture.supplyAsync(() -> {
                    try {
                        return out.readLine();
                    } catch (java.io.IOException e) {
                        return "(its output unreadable: " + e.getMessage() + ")";
                    }
                }).get(30, TimeUnit.SECONDS);
            } catch (java.util.concurrent.TimeoutException e) {
                ready = "(nothing within 30 s)";
            }
            if (ready == null || !ready.startsWith("ready ")) {
                p.destroyForcibly();
                Files.deleteIfExists(records);
                fail("the platform monitor did not start: " + ready);
            }
            return new Monitor(p, out, records, System.nanoTime());
        }

        /** Stops the monitor (SIGTERM) and reads what it recorded from its start to now. */
        Platform stop() throws Exception {
            long toNs = System.nanoTime();
            process.destroy();
            if (!process.waitFor(60, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                fail("the platform monitor did not stop within 60 s of SIGTERM");
            }
            if (process.exitValue() != 0) {
                fail("the platform monitor failed (exit " + process.exitValue() + "): " + String.join("\n", output.lines().toList()));
            }
            try {
                return Platform.parse(Files.readString(records), fromNs, toNs);
            } finally {
                Files.deleteIfExists(records);
            }
        }

        @Override
        public void close() throws Exception {
            if (process.isAlive()) {
                process.destroyForcibly();
            }
            Files.deleteIfExists(records);
        }
    }

    /**
     * One job's check: released at {@code releaseNs} (CLOCK_MONOTONIC; -1 for the check that stands for the jobs the
     * program did not list, {@code unlisted}), its response {@code responseNs}, and its bound with the platform as
     * measured ({@code boundNs}, -1: none, {@code why} says why), from the loss it took ({@code loss}: in the job's own
     * window, or for the unlisted jobs the most in any window as long) and how ({@code how}). {@code lossUnbounds}: there
     * is no bound only because of what the platform took (the same check with no loss finds one): no response can
     * contradict the analysis then, and the job cannot be judged, which is said ({@link #describe}), not a failure.
     */
    record JobCheck(long releaseNs, long responseNs, long boundNs, Loss loss, String how, String why, boolean unlisted, boolean lossUnbounds) {
        /** Within its bound with the platform as measured. */
        boolean passes() {
            return boundNs >= 0 && responseNs <= boundNs;
        }

        /** Whether the job shows the analysis wrong: past its bound with the platform as measured, or with no bound the platform's loss explains. */
        boolean contradicts() {
            return !passes() && !(boundNs < 0 && lossUnbounds);
        }

        /** For a message: the job, its response, its bound with the loss it took and how. */
        String describe(long runStartNs) {
            return (unlisted ? "the jobs over it that the program did not list, by the worst response "
                    : "the job released " + JobTimingTest.ms(releaseNs - runStartNs) + " into the run, response ")
                    + JobTimingTest.ms(responseNs) + (passes() ? " within" : contradicts() ? " exceeds" : " not judged by")
                    + " its bound with the platform as measured: " + (boundNs < 0 ? "no bound (" + why + (lossUnbounds
                            ? "; with no loss there is one: what the platform took leaves nothing to contradict" : "") + ")"
                            : JobTimingTest.ms(boundNs)) + ", by " + how;
        }
    }

    /**
     * One task's bound check: its analysed bound, how far before a job's completion the job's window starts
     * ({@code windowNs}: the longest its level's busy period can last with the platform's worst loss of the run, or the
     * whole run before the job where that has no bound), and each job over the analysed bound checked ({@code jobs});
     * or not checked at all ({@code unchecked} says why).
     */
    record Bound(long analysedNs, long windowNs, List<JobCheck> jobs, String unchecked, TaskCheck task) {
        /**
         * The job that decides: the first that contradicts the analysis, else the one closest to its bound, else one
         * that cannot be judged; null when no job exceeded the analysed bound.
         */
        JobCheck decisive() {
            JobCheck closest = null;
            JobCheck unjudged = null;
            for (JobCheck j : jobs) {
                if (j.contradicts()) {
                    return j;
                }
                if (!j.passes()) {
                    unjudged = unjudged == null ? j : unjudged;
                } else if (closest == null || j.boundNs() - j.responseNs() < closest.boundNs() - closest.responseNs()) {
                    closest = j;
                }
            }
            return closest != null ? closest : unjudged;
        }
    }

    /**
     * The check of one task's jobs against its bound with the platform as measured. A job that responded in
     * {@code r} and completed at {@code f} ran in its level's busy period, which began at some {@code t0 <= f - r}
     * with no work of its rank or above pending; what delayed it is that work released from {@code t0} on, one job
     * of a lower rank holding the CPU or the lock at {@code t0} (blocking), and what the platform took between
     * {@code t0} and {@code f}: a delay before {@code t0} cannot reach it, one between {@code t0} and its release can
     * (it pushes the work of higher ranks into the job). That busy period lasts at most {@code L}, the least
     * {@code L >= } the bound with {@code blocking + sum over the ranks at or above of ceil((L + J) / T) (C +
     * bookkeeping) + loss(L) + others <= L}, where {@code loss(L)} is the most the platform took in any window of
     * {@code L} of the run, so {@code t0 >= f - L}: the job's loss is what the monitor recorded in
     * {@code [f - L, f]} ({@link Platform#lossIn}), and the job's bound the analysis run again with that loss as a
     * top-rank job released with it ({@link #at}). On a processor not analysed by response times (EDF) the busy
     * period is the processor's (every task), and the bound the plain sum. Jobs the program did not list are held,
     * by the worst response, to the bound with the most the platform lost in any window of {@code L}
     * ({@link #anywhere}).
     */
    static final class TaskCheck {
        private final Platform platform;
        private final OtherRealtime.Use others;
        private final ProcessorResult processor;
        private final Task task;
        private final long bound;
        private final int cpu;
        private final boolean reanalysable;
        private final long bookkeepingNs;
        private final List<Task> withBookkeeping = new ArrayList<>();
        private final Set<String> runToCompletion = new HashSet<>();
        private final long windowNs;
        private final int top;

        TaskCheck(Platform platform, OtherRealtime.Use others, ProcessorTiming p, Task task, long bound, int cpu, boolean reanalysable,
                long bookkeepingNs) {
            this.platform = platform;
            this.others = others;
            this.processor = p.result();
            this.task = task;
            this.bound = bound;
            this.cpu = cpu;
            this.reanalysable = reanalysable;
            this.bookkeepingNs = bookkeepingNs;
            boolean roundRobin = p.element() != null && p.element().isSetSchedPolicy() && p.element().getSchedPolicy() == SchedulingPolicy.RR;
            for (TaskResult t : processor.tasks()) {
                Task x = t.task();
                withBookkeeping.add(new Task(x.name(), x.period(), x.deadline(), Math.addExact(x.cost(), bookkeepingNs), x.priority(), x.jitter(),
                        x.group()));
                if (!roundRobin) {
                    runToCompletion.add(x.name());
                }
            }
            runToCompletion.add(PLATFORM_TASK);
            this.top = processor.tasks().stream().mapToInt(t -> t.task().priority()).max().orElse(0);
            this.windowNs = busyPeriod();
        }

        /** The longest the level's busy period can last with the platform's worst loss (see above); the run's length where it has no bound within it. */
        private long busyPeriod() {
            long run = Math.max(1, platform.toNs() - platform.fromNs());
            boolean byRank = reanalysable;
            List<Task> level = new ArrayList<>();
            Set<String> groups = new HashSet<>();
            for (Task x : withBookkeeping) {
                if (!byRank || x.priority() >= task.priority()) {
                    level.add(x);
                    if (x.group() != null) {
                        groups.add(x.group());
                    }
                }
            }
            // a job of a lower rank holding a lock of the level's when the busy period began (one, as the analysis counts it)
            long blocking = 0;
            for (Task x : withBookkeeping) {
                if (!level.contains(x) && x.group() != null && groups.contains(x.group())) {
                    blocking = Math.max(blocking, x.cost());
                }
            }
            long length = Math.max(1, bound);
            for (int step = 0; step < 10_000; step++) {
                long next = blocking + others.totalNs() + platform.loss(cpu, length).ns();
                for (Task x : level) {
                    next += ((length + x.jitter() + x.period() - 1) / x.period()) * x.cost();
                    if (next > run) {
                        return run;
                    }
                }
                if (next <= length) {
                    return length;
                }
                length = next;
            }
            return run;
        }

        /** The job released at {@code releaseNs} and done at {@code doneNs} (CLOCK_MONOTONIC), with the loss in its own window. */
        JobCheck at(long releaseNs, long doneNs) {
            // from where the level's busy period may have begun, and at least from the job's release
            return with(platform.lossIn(cpu, Math.min(doneNs - windowNs, releaseNs), doneNs), releaseNs, doneNs - releaseNs, false);
        }

        /**
         * A SCHED_DEADLINE job released at {@code releaseNs}, started at {@code startNs} and done at {@code doneNs}
         * (CLOCK_MONOTONIC), of {@code cpuNs} CPU time and {@code switches} context switches, with its loss
         * ({@link Platform#lossOfDeadlineJob}).
         */
        JobCheck atDeadlineJob(long releaseNs, long doneNs, long startNs, long cpuNs, long switches) {
            return with(platform.lossOfDeadlineJob(Math.min(doneNs - windowNs, releaseNs), startNs, doneNs, cpuNs, switches), releaseNs,
                    doneNs - releaseNs, false);
        }

        /** A job of {@code responseNs} somewhere in the run, with the most the platform lost in any window as long as its window. */
        JobCheck anywhere(long responseNs) {
            return with(platform.loss(cpu, windowNs), -1, responseNs, true);
        }

        /** The analysis run again, by the platform's time it takes (jobs of a run may take the same). */
        private final Map<Long, java.util.OptionalLong> analysed = new HashMap<>();

        private JobCheck with(Loss loss, long releaseNs, long responseNs, boolean unlisted) {
            long limit = task.deadline() > Long.MAX_VALUE / UNBOUNDED_DEADLINES ? Long.MAX_VALUE : task.deadline() * UNBOUNDED_DEADLINES;
            String othersSaid = others.ranNs().isEmpty() ? ""
                    : ", and " + JobTimingTest.ms(others.totalNs()) + " of other programs' real-time threads (" + others + ") taken too";
            String window = " (the job's window: " + JobTimingTest.ms(windowNs) + " up to its completion, the longest its level's busy period"
                    + " can last)";
            if (reanalysable) {
                long once = limit > Long.MAX_VALUE / 4 ? Long.MAX_VALUE / 4 : limit * 2;
                java.util.OptionalLong r = analysed.computeIfAbsent(loss.ns(), ns -> {
                    List<Task> tasks = new ArrayList<>(withBookkeeping);
                    // what the platform took in the window, once: a task above all, released with the job, whose period outlasts any response
                    tasks.add(new Task(PLATFORM_TASK, once, once, Math.max(1, ns + others.totalNs()), top + 1, 0, null));
                    return SchedulabilityAnalysis.analyse(processor.processor(), processor.policy(), tasks, runToCompletion).tasks().stream()
                            .filter(t -> t.task().name().equals(task.name())).findFirst().orElseThrow().responseTime();
                });
                String how = "the analysis run again with " + loss + window + " taken from the processor above every rank, "
                        + JobTimingTest.ms(bookkeepingNs) + " of bookkeeping added to every job" + othersSaid;
                if (r.isPresent() && r.getAsLong() <= limit) {
                    return new JobCheck(releaseNs, responseNs, r.getAsLong(), loss, how, null, unlisted, false);
                }
                if (!bookkeepingOverloads()) {
                    return new JobCheck(releaseNs, responseNs, -1, loss, how, "the analysis finds no response within " + UNBOUNDED_DEADLINES
                            + " times the deadline: the platform left too little of the CPU", unlisted, loss.ns() > 0 && boundedWithoutLoss());
                }
            }
            long sum = bound + bookkeepingNs + others.totalNs() + loss.ns();
            String how = "the bound plus " + loss + window + ", " + JobTimingTest.ms(bookkeepingNs) + " of bookkeeping"
                    + (others.ranNs().isEmpty() ? "" : " and " + JobTimingTest.ms(others.totalNs()) + " of other programs' real-time threads ("
                            + others + ")")
                    + (reanalysable ? " (the analysis run again with " + JobTimingTest.ms(bookkeepingNs)
                            + " of bookkeeping on every job finds no bound: the processor is overloaded with it)" : "");
            return sum > limit ? new JobCheck(releaseNs, responseNs, -1, loss, how, "the platform left too little of the CPU: no bound within "
                    + UNBOUNDED_DEADLINES + " times the deadline", unlisted, loss.ns() > 0 && boundedWithoutLoss())
                    : new JobCheck(releaseNs, responseNs, sum, loss, how, null, unlisted, false);
        }

        private Boolean boundedWithoutLoss;

        /** Whether this task has a bound when the platform takes nothing (its bookkeeping and the others' time still counted). */
        private boolean boundedWithoutLoss() {
            if (boundedWithoutLoss == null) {
                boundedWithoutLoss = with(Loss.NONE, -1, 0, true).boundNs() >= 0;
            }
            return boundedWithoutLoss;
        }

        /** Whether the processor's tasks, each with the bookkeeping added to its cost, need more than the whole processor. */
        private boolean bookkeepingOverloads() {
            double u = 0;
            for (Task t : withBookkeeping) {
                u += (double) t.cost() / t.period();
            }
            return u >= 1;
        }
    }

    /**
     * The platform's part of one run's bounds: the monitor's records, the tolerated CPU time of others'
     * real-time threads, the bookkeeping stated for each job, and each task's jobs checked against the
     * bound computed again with them ({@link #of}).
     */
    record Allowance(Platform platform, OtherRealtime.Use others, long bookkeepingNs, Map<String, Bound> bounds, List<String> heldByGaps) {

        /**
         * Each bounded task's check, by task name (the release's or reaction's label): each of its jobs that the
         * program reports over the analysed bound ({@link JobSummary#overBoundJobs}) against the bound computed again
         * with the platform's loss in that job's own window ({@link TaskCheck}); a job within the analysed bound needs
         * none. {@code cpuOf}: the CPU a task's thread ran on, -1 when not pinned (the worst CPU); a SCHED_DEADLINE
         * thread's loss is the time every CPU was taken at once. A processor with a thread at the monitor's priority is
         * not checked. {@code bookkeepingNs}: added to every job's cost ({@link #BOOKKEEPING_NS}, on ROS 2 more).
         */
        static Allowance of(Platform platform, OtherRealtime.Use others, ArchitectureTiming timing, Map<String, JobSummary> summaries,
                java.util.function.ToIntFunction<String> cpuOf, long bookkeepingNs) {
            Map<String, Bound> bounds = new HashMap<>();
            Map<String, Long> analysed = JobTimingTest.bounds(timing);
            for (ProcessorTiming p : timing.processors()) {
                ProcessorResult r = p.result();
                String collision = null;
                for (TaskResult t : r.tasks()) {
                    JobSummary s = summaries.get(t.task().name());
                    Matcher rank = s == null ? null : RANK.matcher(s.sched());
                    if (rank != null && rank.find() && platform.minPriority() + Integer.parseInt(rank.group(1)) >= platform.priority()) {
                        collision = t.task().name() + " runs at " + s.sched() + ", priority " + Math.min(platform.priority(),
                                platform.minPriority() + Integer.parseInt(rank.group(1))) + ", not below the platform monitor's "
                                + platform.priority() + ": its work would count as the platform's, so processor " + r.processor()
                                + "'s bounds are not checked";
                    }
                }
                for (TaskResult t : r.tasks()) {
                    Long bound = analysed.get(t.task().name());
                    if (bound == null) {
                        continue;
                    }
                    if (collision != null) {
                        bounds.put(t.task().name(), new Bound(bound, 0, List.of(), collision, null));
                        continue;
                    }
                    JobSummary s = summaries.get(t.task().name());
                    // a SCHED_DEADLINE thread runs on any CPU (the kernel admits it only so)
                    int cpu = s != null && s.sched().startsWith("SCHED_DEADLINE") ? EVERY_CPU : cpuOf.applyAsInt(t.task().name());
                    boolean reanalysable = r.policy() == org.rsaml.analysis.SchedulingPolicy.FIXED_PRIORITY && t.responseTime().isPresent();
                    TaskCheck check = new TaskCheck(platform, others, p, t.task(), bound, cpu, reanalysable, bookkeepingNs);
                    List<JobCheck> jobs = new ArrayList<>();
                    if (s != null) {
                        for (long[] job : s.overBoundJobs()) {
                            jobs.add(cpu == EVERY_CPU && job.length == 5 ? check.atDeadlineJob(job[0], job[1], job[2], job[3], job[4])
                                    : check.at(job[0], job[1]));
                        }
                        // the jobs over the bound the program did not list: the worst response speaks for them
                        if (s.unlisted() > 0 || s.overBound() == 0 && s.worstNs() > bound) {
                            jobs.add(check.anywhere(s.worstNs()));
                        }
                    }
                    bounds.put(t.task().name(), new Bound(bound, check.windowNs, List.copyOf(jobs), null, check));
                }
            }
            // the releases that hold only with the gaps the spinners saw between the wake-ups: said, to show what they count
            List<String> heldByGaps = new ArrayList<>();
            if (platform.spun()) {
                Allowance wakeUps = of(platform.wakeUpsOnly(), others, timing, summaries, cpuOf, bookkeepingNs);
                bounds.forEach((label, b) -> {
                    if (b.unchecked() == null && b.jobs().stream().noneMatch(JobCheck::contradicts) && !wakeUps.admits(label)) {
                        heldByGaps.add(label);
                    }
                });
                heldByGaps.sort(null);
            }
            return new Allowance(platform, others, bookkeepingNs, Map.copyOf(bounds), List.copyOf(heldByGaps));
        }

        private static final Pattern RANK = Pattern.compile("^SCHED_(?:FIFO|RR) rank (\\d+)");

        /** Why {@code label}'s bound is not checked in this run, null when it is. */
        String unchecked(String label) {
            Bound b = bounds.get(label);
            return b == null ? "no bound by the analysis" : b.unchecked();
        }

        /**
         * Whether no job of {@code label} the run reported over its analysed bound contradicts the analysis: each within its
         * bound with the platform as measured, or without one only because of what the platform took ({@link JobCheck#contradicts}).
         */
        boolean admits(String label) {
            Bound b = bounds.get(label);
            return b != null && b.unchecked() == null && b.jobs().stream().noneMatch(JobCheck::contradicts);
        }

        /** The check of a job of {@code label} released at {@code releaseNs} and done at {@code doneNs} (CLOCK_MONOTONIC), whether the run had it or not. */
        JobCheck at(String label, long releaseNs, long doneNs) {
            return bounds.get(label).task().at(releaseNs, doneNs);
        }

        /** The check of {@code label}, for a message: its analysed bound, and the deciding job's response, loss, window and bound with it. */
        String explain(String label) {
            Bound b = bounds.get(label);
            if (b == null) {
                return "no bound by the analysis";
            }
            if (b.unchecked() != null) {
                return b.unchecked();
            }
            JobCheck d = b.decisive();
            if (d == null) {
                return "analysed bound " + JobTimingTest.ms(b.analysedNs()) + ", which no job exceeded";
            }
            long failing = b.jobs().stream().filter(JobCheck::contradicts).count();
            long unjudged = b.jobs().stream().filter(j -> !j.passes() && !j.contradicts()).count();
            return "analysed bound " + JobTimingTest.ms(b.analysedNs()) + "; " + b.jobs().stream().filter(j -> !j.unlisted()).count()
                    + " jobs over it listed" + (b.jobs().stream().anyMatch(JobCheck::unlisted) ? " and more not listed" : "")
                    + ", each held to its bound with the platform's loss in its own window"
                    + (unjudged > 0 ? " (" + unjudged + (unjudged == b.jobs().size() ? ", all of them," : "") + " not judged: no bound with"
                            + " the platform's loss in their window, one without it)" : "")
                    + "; " + (failing > 0 ? failing + " fail, the first: " : "the closest: ") + d.describe(platform.fromNs());
        }

        /** The releases whose jobs over the bound were more than their program lists, checked in part by the worst window of the run. */
        List<String> unlisted() {
            return bounds.entrySet().stream().filter(e -> e.getValue().jobs().stream().anyMatch(JobCheck::unlisted)).map(Map.Entry::getKey)
                    .sorted().toList();
        }

        @Override
        public String toString() {
            List<String> unlisted = unlisted();
            return platform + (others.ranNs().isEmpty() ? "" : "; other programs' real-time threads ran (" + others + ")") + "; "
                    + JobTimingTest.ms(bookkeepingNs) + " stated for bookkeeping; " + (unlisted.isEmpty()
                            ? "every job over its bound checked in its own window"
                            : unlisted.size() + " releases with more jobs over the bound than listed, those checked by the run's worst window: "
                                    + unlisted)
                    + (heldByGaps.isEmpty() ? "" : "; held only with the gaps between the monitor's wake-ups: " + heldByGaps);
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
     * not checked (said once; a failure where {@link #required()}); not checked either when the platform
     * monitor was not measuring as it must (no real-time priority; a failure where required); else each bound
     * with the platform's loss as the monitor recorded it ({@link Allowance#of}), on the CPU {@code cpuOf} gives
     * each label's thread (-1: not pinned, the worst CPU).
     */
    static BoundCheck boundCheck(String what, OtherRealtime.Use others, Platform platform, ArchitectureTiming timing,
            Map<String, JobSummary> summaries, java.util.function.ToIntFunction<String> cpuOf, long bookkeepingNs) {
        if (!others.tolerated()) {
            otherRealtime(what, others);
            return new BoundCheck(null, "other programs' real-time threads ran " + JobTimingTest.ms(others.totalNs()));
        }
        String notMeasured = platform.notMeasured();
        if (notMeasured != null) {
            if (required()) {
                fail("RSAML_TIMING_BOUNDS=required: " + what + ": " + notMeasured + ", so no bound can be checked");
            }
            return new BoundCheck(null, notMeasured);
        }
        return new BoundCheck(Allowance.of(platform.withDeadlineThreads(summaries), others, timing, summaries, cpuOf, bookkeepingNs), null);
    }

    /** The CPU of each thread of a run by its label, as its trace says where it was pinned ({@link #cpus}); -1 where not pinned. */
    static java.util.function.ToIntFunction<String> tracedCpus(String output) {
        Map<String, Integer> cpus = cpus(output);
        return label -> cpus.getOrDefault(label.replace(" (reaction)", ""), -1);
    }

    private static final Pattern PLACED = Pattern.compile("\\] cpu (\\S+) (core (\\d+).*)$");
    private static final Pattern ON_CPU = Pattern.compile(" on CPU (\\d+)");

    /**
     * The CPU each thread of a run was pinned to, by its label, from the trace lines where the runtimes say it
     * ("cpu navigation/obstacleDetector.detect core 1", "... core 0 of host nav-board on CPU 1 ..."); a thread
     * that was not pinned ("not available", the unclaimed cores, a module without a core) is not in it.
     */
    static Map<String, Integer> cpus(String output) {
        Map<String, Integer> cpus = new HashMap<>();
        for (String line : output.split("\n")) {
            Matcher m = PLACED.matcher(line);
            if (m.find() && !m.group(2).contains("not available") && !m.group(2).contains("not supported")) {
                Matcher on = ON_CPU.matcher(m.group(2));
                cpus.put(m.group(1), on.find() ? Integer.parseInt(on.group(1)) : Integer.parseInt(m.group(3)));
            }
        }
        return cpus;
    }

    /**
     * Whether the monitor's run leaves {@code label}'s bound unchecked (a model thread at the monitor's priority):
     * then noted in {@code unchecked}, and a failure where {@link #required()}.
     */
    static boolean uncheckedByMonitor(String what, String label, Allowance allowance, List<String> unchecked) {
        String why = allowance.unchecked(label);
        if (why == null) {
            return false;
        }
        if (required()) {
            fail("RSAML_TIMING_BOUNDS=required: " + what + ": " + label + ": " + why);
        }
        unchecked.add(label + " (" + why + ")");
        return true;
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
     * Where a target runs the threads of a processor that the model gives no CPU of its own (docs/timing.md, "Other
     * machines"). Both keep the threads (C++) or processes (ROS 2) of the processors without a core, an EDF processor's
     * included, to the CPUs no processor claims where some processor claims a core, by one rule
     * ({@link OneMachineCpus#claimed}): an EDF processor without a core beside processors with cores is refused
     * SCHED_DEADLINE there and runs at its ranks, saying 'instead of EDF', so that the processors' cores stay theirs
     * (docs/timing.md, "EDF beside processors with cores"). They differ for an EDF processor with a core.
     */
    enum Placement {
        /**
         * The C++ program: a processor's core pins its threads ({@link OneMachineCpus}), but for an EDF processor's
         * releases, left on every core (the kernel admits a deadline thread only there).
         */
        CPP,
        /**
         * A ROS 2 launch without host:=: a processor's core pins its processes with taskset ({@link OneMachineCpus}), its
         * EDF releases included (the kernel then refuses them SCHED_DEADLINE: they run at their ranks, 'instead of EDF').
         */
        ROS2
    }

    /** As {@link #notApart(Architecture, Module, Placement, int)} on this machine's CPUs. */
    static String notApart(Architecture arch, Module module, Placement target) {
        return notApart(arch, module, target, Runtime.getRuntime().availableProcessors());
    }

    /**
     * Null when the threads of {@code module}'s releases and reactions have CPUs that no other processor's threads use on
     * a machine of {@code cpus} CPUs under {@code target}, as the analysis of their processor assumes (a processor with a
     * core: that CPU alone; the one processor without a core: the CPUs no processor claims, one or more); else why not,
     * for the report of the releases whose bounds a test leaves unchecked. Not apart: the threads of a processor whose core
     * the machine lacks run anywhere, so no processor's do; the modules without a core of several hosts, or of two
     * processors (the 'default' one counted), share the CPUs left; the deadline threads of another EDF processor run on
     * every CPU (C++: one with a core; both targets: one without a core where no processor claims a core, while beside
     * processors with cores it is kept to the CPUs they leave, refused SCHED_DEADLINE there); where every CPU is claimed,
     * the modules without a core run on every one, the claimed ones included.
     */
    static String notApart(Architecture arch, Module module, Placement target, int cpus) {
        Map<Processor, Integer> cpuOf = OneMachineCpus.of(arch);
        Set<String> corelessHosts = new java.util.TreeSet<>();
        Set<String> corelessProcessors = new java.util.TreeSet<>(); // with modules, 'default' for the modules no processor names
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                Processor p = processorOf(arch, m);
                if (p == null || p.getCore() < 0) {
                    corelessHosts.add(RsamlLabels.hostName(p));
                    corelessProcessors.add(p == null ? "default" : p.getName());
                } else {
                    int cpu = cpuOf.get(p);
                    if (cpu >= cpus) {
                        return "processor " + p.getName() + "'s core " + p.getCore() + (cpu == p.getCore() ? "" : " (CPU " + cpu + " here)")
                                + " is not among this machine's " + cpus + ", so its threads run anywhere";
                    }
                }
            }
        }
        if (corelessHosts.size() > 1) {
            return "the modules without a core of hosts " + corelessHosts + " share CPUs the analysis counts apart";
        }
        Processor p = processorOf(arch, module);
        int claimed = new HashSet<>(cpuOf.values()).size();
        for (Processor q : arch.getProcessors()) {
            if (q != p && q.isSetSchedPolicy() && q.getSchedPolicy() == SchedulingPolicy.EDF && !q.getModules().isEmpty()
                    && (q.getCore() >= 0 ? target == Placement.CPP : claimed == 0)) {
                return "the deadline threads of EDF processor " + q.getName() + " run on every core";
            }
        }
        int unclaimed = cpus - claimed;
        boolean coreless = !corelessProcessors.isEmpty();
        if (p != null && p.getCore() >= 0) {
            return coreless && unclaimed == 0 ? "no core is left for the modules without one, so they run on every core" : null;
        }
        if (corelessProcessors.size() > 1) {
            return "it has no core of its own and shares the CPUs no processor claims with the modules of processors "
                    + corelessProcessors + ", which have none either";
        }
        if (claimed > 0 && unclaimed == 0) {
            return "it has no core of its own and no core is left for it, so it runs on every core, the processors' included";
        }
        return null;
    }

    /** The processor that runs {@code m}, or null (the modules no processor names). */
    static Processor processorOf(Architecture arch, Module m) {
        return arch.getProcessors().stream().filter(q -> q.getModules().contains(m)).findFirst().orElse(null);
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
