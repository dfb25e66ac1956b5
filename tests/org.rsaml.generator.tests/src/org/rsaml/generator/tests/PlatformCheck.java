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
import org.rsaml.model.SchedulingPolicy;

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
 * make it late. Each bound is then computed again with that loss ({@link Allowance#of}): on a
 * fixed-priority processor by the analysis itself, the job's cost raised by the most time the monitor
 * lost on its CPU in any window as long as the response ({@link Platform#loss}), so that a delay that
 * pulls one more higher-rank job into the response is counted; elsewhere the plain sum. To it come
 * {@link #BOOKKEEPING_NS}, stated, and the CPU time other programs' real-time threads used during the
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

    /** The CPU of a SCHED_DEADLINE thread, which the kernel runs on any: its loss is the time every CPU was taken at once. */
    static final int EVERY_CPU = -2;

    /** A re-analysed bound beyond this many times the deadline is no bound: the check fails, saying so. */
    static final long UNBOUNDED_DEADLINES = 100;

    /**
     * One CPU's records of the {@link Monitor}: the intervals from each activation's nominal wake-up
     * (a late one's: from the previous record's end, {@link Platform#LATE_NS}) to the end of its record,
     * within the run, sorted and disjoint (the monitor's next wake-up is always past its last record's
     * end); {@code sched} what its thread got.
     */
    record CpuRecords(int cpu, String sched, boolean overflow, long[] starts, long[] ends) {
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
     * than the model; the longest single interval the monitor recorded there, and when (after the run's start).
     */
    record Loss(int cpu, long windowNs, long ns, long longestNs, long longestAtNs) {
        static final Loss NONE = new Loss(-1, 0, 0, 0, 0);

        @Override
        public String toString() {
            return JobTimingTest.ms(ns) + " lost on " + (cpu == EVERY_CPU ? "every CPU at once (a SCHED_DEADLINE thread, which may run on any)"
                    : cpu < 0 ? "the worst CPU (the thread is not pinned)" : "CPU " + cpu)
                    + " in a window of " + JobTimingTest.ms(windowNs) + " (its longest single delay " + JobTimingTest.ms(longestNs) + " at "
                    + JobTimingTest.ms(longestAtNs) + " into the run)";
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
    record Platform(int priority, int minPriority, List<CpuRecords> cpus, long fromNs, long toNs, List<long[]> aboveMonitor) {
        private static final Pattern HEADER = Pattern.compile("rsaml-platform-monitor period (\\d+) ns priority (\\d+) min (\\d+) memory (.*)");
        private static final Pattern CPU = Pattern.compile("cpu (\\d+) records (\\d+)( overflow)? sched (.*)");

        /**
         * A record longer than this was a late wake-up: something held the CPU at the moment the monitor was due, and it
         * may have taken the CPU at any time after the monitor's previous record ended (the monitor sleeps in between and
         * sees nothing), so the record counts from there. The usual record takes 10 to 50 us.
         */
        static final long LATE_NS = 100_000;

        /**
         * Reads the monitor's file, keeping what falls between {@code fromNs} and {@code toNs}; a late record
         * ({@link #LATE_NS}) counts from the end of the CPU's previous record.
         */
        static Platform parse(String text, long fromNs, long toNs) {
            String[] lines = text.split("\n");
            Matcher h = HEADER.matcher(lines.length > 0 ? lines[0] : "");
            assertTrue(h.matches(), "the platform monitor's records begin with its header: " + Tools.last(text, 500));
            Map<Integer, String> sched = new TreeMap<>();
            Map<Integer, Boolean> overflow = new TreeMap<>();
            Map<Integer, List<long[]>> intervals = new TreeMap<>();
            for (int i = 1; i < lines.length; i++) {
                Matcher c = CPU.matcher(lines[i]);
                if (c.matches()) {
                    int cpu = Integer.parseInt(c.group(1));
                    sched.put(cpu, c.group(4));
                    overflow.put(cpu, c.group(3) != null);
                    intervals.put(cpu, new ArrayList<>());
                    continue;
                }
                String[] f = lines[i].split(" ");
                intervals.get(Integer.parseInt(f[0])).add(new long[] {Long.parseLong(f[1]), Long.parseLong(f[2])});
            }
            List<CpuRecords> cpus = new ArrayList<>();
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
                cpus.add(new CpuRecords(cpu, sched.get(cpu), overflow.get(cpu), list.stream().mapToLong(x -> x[0]).toArray(),
                        list.stream().mapToLong(x -> x[1]).toArray()));
            });
            return new Platform(Integer.parseInt(h.group(2)), Integer.parseInt(h.group(3)), List.copyOf(cpus), fromNs, toNs, List.of());
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
            return new Platform(priority, minPriority, cpus, fromNs, toNs, List.copyOf(above));
        }

        private static final Pattern DEADLINE = Pattern.compile("^SCHED_DEADLINE runtime ([0-9.]+) ms deadline [0-9.]+ ms period ([0-9.]+) ms");

        /** Null when every CPU was measured as the check needs (SCHED_FIFO at the top, every record kept), else why not. */
        String notMeasured() {
            for (CpuRecords c : cpus) {
                if (!c.sched().startsWith("SCHED_FIFO")) {
                    return "the platform monitor got no real-time scheduling on CPU " + c.cpu() + " (" + c.sched() + ")";
                }
                if (c.overflow()) {
                    return "the platform monitor ran out of room for its records on CPU " + c.cpu();
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
                Loss l = new Loss(cpu, windowNs, ns, longest < 0 ? 0 : c.ends()[longest] - c.starts()[longest],
                        longest < 0 ? 0 : c.starts()[longest] - fromNs);
                if (worst == null || l.ns() > worst.ns()) {
                    worst = l;
                }
            }
            return worst != null ? worst : new Loss(cpu, windowNs, 0, 0, 0);
        }

        /**
         * For a SCHED_DEADLINE release: the most time in a window during which every CPU's monitor was delayed at once.
         * Such a job, which the kernel may run on any CPU, waits only while every CPU runs something else, and as the
         * model's deadline threads are no more than the CPUs, one of those is then the platform's (or the job's own
         * work, beside another deadline job: the check is that much looser). Its longest single delay: on any CPU.
         */
        private Loss everyCpuAtOnce(long windowNs) {
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
            Loss any = loss(-1, windowNs);
            return new Loss(EVERY_CPU, windowNs, new CpuRecords(EVERY_CPU, "", false, starts, ends).maxCovered(windowNs), any.longestNs(),
                    any.longestAtNs());
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
            for (CpuRecords c : cpus) {
                int l = c.longest();
                each.add(String.format(Locale.ROOT, "CPU %d: %d wake-ups, longest delay %s at %s, %s in its worst 10 ms", c.cpu(), c.starts().length,
                        JobTimingTest.ms(l < 0 ? 0 : c.ends()[l] - c.starts()[l]), JobTimingTest.ms(l < 0 ? 0 : c.starts()[l] - fromNs),
                        JobTimingTest.ms(c.maxCovered(10_000_000))));
            }
            return "the platform monitor (SCHED_FIFO " + priority + ", every 1 ms on every CPU, during the run of "
                    + JobTimingTest.ms(toNs - fromNs) + "): " + String.join("; ", each);
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
     * One task's bound with the platform as measured: {@code boundNs} (-1: none, {@code why} says why),
     * from its analysed bound, the loss it took ({@code loss}) and how ({@code how}); or not checked at
     * all ({@code unchecked} says why).
     */
    record Bound(long analysedNs, long boundNs, Loss loss, String how, String why, String unchecked, boolean overloaded) {
    }

    /**
     * The platform's part of one run's bounds: the monitor's records, the tolerated CPU time of others'
     * real-time threads, and each task's bound computed again with them ({@link #of}).
     */
    record Allowance(Platform platform, OtherRealtime.Use others, Map<String, Bound> bounds) {

        /**
         * Each bounded task's bound with the platform's loss, by task name (the release's or reaction's label).
         * On a fixed-priority processor, for each task i, R is iterated from its analysed bound: R becomes task i's
         * response by {@link SchedulabilityAnalysis#analyse} with every task's cost raised by the bookkeeping and, above
         * every rank, a task released once with i's job that stands for the loss on i's CPU in a window of R and the
         * others' real-time CPU time, until R stops growing (response-time analysis over the supply the platform left:
         * R = C + I(R) + loss(R)). Elsewhere (EDF, a processor the analysis does not bound by response times, a set the
         * bookkeeping on every job overloads) the plain sum, iterated the same way: R becomes the bound plus the
         * bookkeeping, the others' time and the loss in a window of R. {@code cpuOf}: the CPU a task's thread ran on,
         * -1 when not pinned (the worst CPU); a SCHED_DEADLINE thread's loss is the time every CPU was taken at once.
         * A processor with a thread at the monitor's priority is not checked.
         */
        static Allowance of(Platform platform, OtherRealtime.Use others, ArchitectureTiming timing, Map<String, JobSummary> summaries,
                java.util.function.ToIntFunction<String> cpuOf) {
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
                boolean reanalysable = r.policy() == org.rsaml.analysis.SchedulingPolicy.FIXED_PRIORITY;
                for (TaskResult t : r.tasks()) {
                    Long bound = analysed.get(t.task().name());
                    if (bound == null) {
                        continue;
                    }
                    if (collision != null) {
                        bounds.put(t.task().name(), new Bound(bound, -1, Loss.NONE, "", "", collision, false));
                        continue;
                    }
                    JobSummary s = summaries.get(t.task().name());
                    // a SCHED_DEADLINE thread runs on any CPU (the kernel admits it only so)
                    int cpu = s != null && s.sched().startsWith("SCHED_DEADLINE") ? EVERY_CPU : cpuOf.applyAsInt(t.task().name());
                    Bound b = reanalysable && t.responseTime().isPresent() ? reanalysed(platform, others, p, r, t.task(), bound, cpu) : null;
                    if (b == null || b.boundNs() < 0 && b.overloaded()) {
                        // where the bookkeeping on every job overloads the processor (a set the analysis bounds only at its
                        // modeled costs), the plain sum, said
                        Bound sum = summed(platform, others, t.task(), bound, cpu);
                        b = b == null ? sum : new Bound(sum.analysedNs(), sum.boundNs(), sum.loss(), sum.how() + " (the analysis run again with "
                                + JobTimingTest.ms(BOOKKEEPING_NS) + " of bookkeeping on every job finds no bound: the processor is overloaded with it)",
                                sum.why(), null, false);
                    }
                    bounds.put(t.task().name(), b);
                }
            }
            return new Allowance(platform, others, Map.copyOf(bounds));
        }

        private static final Pattern RANK = Pattern.compile("^SCHED_(?:FIFO|RR) rank (\\d+)");

        private static Bound reanalysed(Platform platform, OtherRealtime.Use others, ProcessorTiming p, ProcessorResult r, Task task, long bound,
                int cpu) {
            boolean roundRobin = p.element() != null && p.element().isSetSchedPolicy() && p.element().getSchedPolicy() == SchedulingPolicy.RR;
            long limit = limit(task);
            long response = bound;
            Loss loss = Loss.NONE;
            int top = r.tasks().stream().mapToInt(t -> t.task().priority()).max().orElse(0);
            long once = limit > Long.MAX_VALUE / 4 ? Long.MAX_VALUE / 4 : limit * 2;
            // the processor's tasks with the bookkeeping on every job: the same in every step, only the platform's task changes
            List<Task> withBookkeeping = new ArrayList<>();
            Set<String> runToCompletion = new HashSet<>();
            for (TaskResult t : r.tasks()) {
                Task x = t.task();
                withBookkeeping.add(new Task(x.name(), x.period(), x.deadline(), Math.addExact(x.cost(), BOOKKEEPING_NS), x.priority(), x.jitter(),
                        x.group()));
                if (!roundRobin) {
                    runToCompletion.add(x.name());
                }
            }
            runToCompletion.add(PLATFORM_TASK);
            for (int step = 0; step < 10_000; step++) {
                loss = platform.loss(cpu, response);
                List<Task> tasks = new ArrayList<>(withBookkeeping);
                // what the platform took in the window, once: a task above all, released with the job, whose period outlasts any response
                tasks.add(new Task(PLATFORM_TASK, once, once, Math.max(1, loss.ns() + others.totalNs()), top + 1, 0, null));
                java.util.OptionalLong next = SchedulabilityAnalysis.analyse(r.processor(), r.policy(), tasks, runToCompletion).tasks().stream()
                        .filter(t -> t.task().name().equals(task.name())).findFirst().orElseThrow().responseTime();
                String how = "the analysis run again with " + loss + " taken from the processor above every rank, "
                        + JobTimingTest.ms(BOOKKEEPING_NS) + " of bookkeeping added to every job" + (others.ranNs().isEmpty() ? ""
                                : ", and " + JobTimingTest.ms(others.totalNs()) + " of other programs' real-time threads (" + others + ") taken too");
                if (next.isEmpty() || next.getAsLong() > limit) {
                    return new Bound(bound, -1, loss, how, "the analysis finds no response within " + UNBOUNDED_DEADLINES
                            + " times the deadline: the platform left too little of the CPU", null, step == 0 && bookkeepingOverloads(r));
                }
                if (next.getAsLong() <= response && step > 0) {
                    return new Bound(bound, response, loss, how, null, null, false);
                }
                response = Math.max(response, next.getAsLong());
            }
            return new Bound(bound, -1, loss, "", "the re-analysis did not settle", null, false);
        }

        /** Whether the processor's tasks, each with the bookkeeping added to its cost, need more than the whole processor. */
        private static boolean bookkeepingOverloads(ProcessorResult r) {
            double u = 0;
            for (TaskResult t : r.tasks()) {
                u += (double) (t.task().cost() + BOOKKEEPING_NS) / t.task().period();
            }
            return u >= 1;
        }

        /** The name of the task that stands for what the platform took, in the analysis run again. */
        private static final String PLATFORM_TASK = "the platform (as measured)";

        private static long limit(Task task) {
            return task.deadline() > Long.MAX_VALUE / UNBOUNDED_DEADLINES ? Long.MAX_VALUE : task.deadline() * UNBOUNDED_DEADLINES;
        }

        private static Bound summed(Platform platform, OtherRealtime.Use others, Task task, long bound, int cpu) {
            long limit = limit(task);
            long response = bound;
            Loss loss = Loss.NONE;
            for (int step = 0; step < 10_000; step++) {
                loss = platform.loss(cpu, response);
                long next = bound + BOOKKEEPING_NS + others.totalNs() + loss.ns();
                String how = "the bound plus " + loss + ", " + JobTimingTest.ms(BOOKKEEPING_NS) + " of bookkeeping"
                        + (others.ranNs().isEmpty() ? "" : " and " + JobTimingTest.ms(others.totalNs()) + " of other programs' real-time threads (" + others + ")");
                if (next > limit) {
                    return new Bound(bound, -1, loss, how, "the platform left too little of the CPU: no bound within " + UNBOUNDED_DEADLINES
                            + " times the deadline", null, false);
                }
                if (next <= response && step > 0) {
                    return new Bound(bound, response, loss, how, null, null, false);
                }
                response = Math.max(response, next);
            }
            return new Bound(bound, -1, loss, "", "the sum did not settle", null, false);
        }

        /** Why {@code label}'s bound is not checked in this run, null when it is. */
        String unchecked(String label) {
            Bound b = bounds.get(label);
            return b == null ? "no bound by the analysis" : b.unchecked();
        }

        /** Whether {@code label}'s worst observed response is within its bound with the platform as measured. */
        boolean admits(String label, long worstNs) {
            Bound b = bounds.get(label);
            return b != null && b.unchecked() == null && b.boundNs() >= 0 && worstNs <= b.boundNs();
        }

        /** The check of {@code label}, for a message: its analysed bound, the loss taken and the bound with it. */
        String explain(String label) {
            Bound b = bounds.get(label);
            if (b == null) {
                return "no bound by the analysis";
            }
            if (b.unchecked() != null) {
                return b.unchecked();
            }
            return "analysed bound " + JobTimingTest.ms(b.analysedNs()) + "; with the platform as measured: "
                    + (b.boundNs() < 0 ? "no bound (" + b.why() + ")" : JobTimingTest.ms(b.boundNs())) + ", by " + b.how();
        }

        @Override
        public String toString() {
            return platform + (others.ranNs().isEmpty() ? "" : "; other programs' real-time threads ran (" + others + ")") + "; "
                    + JobTimingTest.ms(BOOKKEEPING_NS) + " stated for bookkeeping";
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
            Map<String, JobSummary> summaries, java.util.function.ToIntFunction<String> cpuOf) {
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
        return new BoundCheck(Allowance.of(platform.withDeadlineThreads(summaries), others, timing, summaries, cpuOf), null);
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
