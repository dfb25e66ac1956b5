/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.SchedulabilityAnalysis;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.internal.AnalysisCounts;
import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Processor;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.SchedulingPolicy;

/**
 * Timing analysis figures: (1) one processor with n tasks, n = 1,000, 10,000 and 50,000, six
 * workloads: rate-monotonic tasks of harmonic periods at utilisation 0.99, of 12 periods dividing
 * 1.2 s at 0.8, of nearly distinct periods at 0.8 and at 0.99 (many of the latter miss), and tasks
 * that all share the top rank and run first in, first out; each with its ratio to its anchor in the
 * same run (the n tasks sorted by period, O(n log n)), and the same top rank with one round-robin task
 * among the first-in-first-out ones (all tied, analysed preemptively); each with its growth against the same workload at the
 * size before (1.0: linear); (2) an architecture of M periodic modules on 4
 * processors, each module connected to the next and every 50th also three ahead, with 100 latency
 * requirements each spanning 10 modules. Prints Markdown tables of medians, and beside each row of (1) what the analysis
 * did there, counted in a run of its own ({@link AnalysisCounts}): jobs, iteration steps, entries recounted, the longest busy
 * period, tied tasks read from a level's walk, the summary witnesses' nodes opened. {@code -Drsaml.bench.timing=key,...}
 * picks workloads of (1) (harmonic, periods12, distinct-0.8, distinct-0.99, fifo, round-robin; all by default).
 */
public final class TimingBench {

    static final int RUNS = 5;
    /** CPU time of this thread: on a shared machine wall time mostly measures the other processes. */
    static final java.lang.management.ThreadMXBean CPU = java.lang.management.ManagementFactory.getThreadMXBean();
    static final long MS = 1_000_000L;
    static final long[] PERIODS = { 5, 10, 20, 25, 40, 50, 100, 200, 300, 400, 600, 1200 };

    /** One task set's analysis, timed: the last run's result, median CPU and wall time (ns), runs. */
    private record Timed(ProcessorResult result, long cpuNs, long wallNs, int runs) {
    }

    /**
     * A workload of the one-processor table: the key that picks it ({@code -Drsaml.bench.timing=key,...}), its task set of n
     * tasks, and the tasks that run first in, first out.
     */
    private record Workload(String key, String name, java.util.function.IntFunction<List<Task>> tasks,
            java.util.function.Function<List<Task>, Set<String>> fifo) {
    }

    /**
     * The anchor of a row: the n tasks sorted by period (then priority), O(n log n) whatever the workload (sorting by
     * priority alone costs next to nothing where all tasks share one priority, which made the first-in-first-out rows'
     * ratios clock noise); CPU time of this thread per sort, median of 5 batches, each batch sorting a shuffled copy
     * again until it has taken at least 20 ms.
     */
    private static long sortCpuNs(List<Task> tasks) {
        java.util.Comparator<Task> order = java.util.Comparator.comparingLong(Task::period).thenComparing(java.util.Comparator.comparingInt(Task::priority).reversed());
        List<Task> shuffled = new ArrayList<>(tasks);
        java.util.Collections.shuffle(shuffled, new Random(tasks.size()));
        long[] cpu = new long[RUNS];
        for (int i = 0; i < RUNS; i++) {
            long c0 = CPU.getCurrentThreadCpuTime();
            int sorts = 0;
            long spent;
            do {
                List<Task> sorted = new ArrayList<>(shuffled);
                sorted.sort(order);
                sorts++;
                if (sorted.size() != tasks.size()) {
                    throw new IllegalStateException("sorting lost tasks");
                }
                spent = CPU.getCurrentThreadCpuTime() - c0;
            } while (spent < 20 * MS);
            cpu[i] = spent / sorts;
        }
        return GenerationBench.median(cpu);
    }

    private static Timed timed(List<Task> tasks, Set<String> fifo) {
        long[] times = new long[RUNS];
        long[] cpu = new long[RUNS];
        ProcessorResult r = null;
        int runs = 0;
        // up to RUNS runs, fewer when one takes seconds (the 50,000-task sets)
        for (long spent = 0; runs == 0 || runs < RUNS && spent < 3_000 * MS; runs++) {
            long c0 = CPU.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            r = SchedulabilityAnalysis.analyse("cpu", org.rsaml.analysis.SchedulingPolicy.FIXED_PRIORITY, tasks, fifo);
            times[runs] = System.nanoTime() - t0;
            cpu[runs] = CPU.getCurrentThreadCpuTime() - c0;
            spent += cpu[runs];
        }
        return new Timed(r, GenerationBench.median(java.util.Arrays.copyOf(cpu, runs)),
                GenerationBench.median(java.util.Arrays.copyOf(times, runs)), runs);
    }

    public static void main(String[] args) throws Exception {
        int modules = args.length > 0 ? Integer.parseInt(args[0].trim()) : 1000;
        // sized with the architecture, so that the short run of TimingBenchTest stays short
        int[] sizes = java.util.stream.IntStream.of(1_000, 10_000, 50_000).map(n -> Math.min(n, Math.max(10, 50 * modules))).distinct()
                .toArray();
        List<Workload> all = List.of(
                new Workload("harmonic", "harmonic periods (5 ms × 2^k), U = 0.99", n -> harmonic(n, 0.99, new Random(n)), t -> Set.of()),
                new Workload("periods12", "12 periods dividing 1.2 s, U = 0.8", n -> taskSet(n, new Random(n)), t -> Set.of()),
                new Workload("distinct-0.8", "distinct periods, U = 0.8", n -> distinctPeriods(n, 0.8, new Random(n)), t -> Set.of()),
                new Workload("distinct-0.99", "distinct periods, U = 0.99", n -> distinctPeriods(n, 0.99, new Random(n)), t -> Set.of()),
                new Workload("fifo", "first in, first out at the top rank (all tasks), distinct periods, U = 0.8",
                        n -> sameRank(distinctPeriods(n, 0.8, new Random(n))), t -> fifo(t, 0)),
                new Workload("round-robin", "one top rank, all tasks first in, first out but one round robin, distinct periods, U = 0.8",
                        n -> sameRank(distinctPeriods(n, 0.8, new Random(n))), t -> fifo(t, 1)));
        String picked = System.getProperty("rsaml.bench.timing", "all");
        List<Workload> workloads = all.stream().filter(w -> picked.equals("all") || List.of(picked.split(",")).contains(w.key())).toList();
        if (workloads.isEmpty()) {
            throw new IllegalArgumentException("rsaml.bench.timing: '" + picked + "' names none of "
                    + all.stream().map(Workload::key).toList() + " (or all)");
        }
        for (Workload w : workloads) { // JIT
            List<Task> tasks = w.tasks().apply(Math.min(1_000, sizes[0]));
            SchedulabilityAnalysis.analyse("cpu", org.rsaml.analysis.SchedulingPolicy.FIXED_PRIORITY, tasks, w.fifo().apply(tasks));
        }
        System.out.println("Load average (1 min) at the start: " + ValidationBench.loadAverage());
        System.out.println();
        System.out.println("| tasks on one processor | n | analysis, CPU time (median) | wall time | per task | anchor: the tasks sorted by"
                + " period, CPU time | ÷ anchor | growth ÷ growth of n (the same set at the size before) | verdict | misses"
                + " | critical-instant schedules (segments) | jobs of the busy periods | iteration steps | entries recounted (first jobs + later jobs)"
                + " | recounted ÷ n | calendar buckets passed | entries looked at | longest busy period | tied tasks read from the level's walk / iterated | summary nodes opened (per summary) |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        for (Workload w : workloads) {
            long previous = -1;
            int previousN = 0;
            for (int n : sizes) {
                List<Task> tasks = w.tasks().apply(n);
                long anchor = sortCpuNs(tasks);
                Timed timed = timed(tasks, w.fifo().apply(tasks));
                ProcessorResult r = timed.result();
                long misses = r.tasks().stream().filter(t -> t.verdict() == Verdict.MISSES).count();
                long schedules = r.tasks().stream().filter(t -> t.witness() != null && !t.witness().summary()).count();
                long segments = r.tasks().stream().filter(t -> t.witness() != null).mapToLong(t -> t.witness().schedule().size()).sum();
                String growth = previous <= 0 ? "" : String.format("%.2f", (double) timed.cpuNs() / previous / ((double) n / previousN));
                // what the analysis did, counted in a run of its own (not timed)
                AnalysisCounts c = new AnalysisCounts();
                c.during(() -> SchedulabilityAnalysis.analyse("cpu", org.rsaml.analysis.SchedulingPolicy.FIXED_PRIORITY, tasks, w.fifo().apply(tasks)));
                System.out.printf("| %s | %,d | %,d ms (%d runs) | %,d ms | %.1f µs | %.2f ms | %.0f× | %s | %s (U = %s) | %,d | %,d (%,d)"
                        + " | %,d | %,d | %,d + %,d | %.0f | %,d | %,d | %s | %,d / %,d | %,d (%s) |%n",
                        w.name(), n, timed.cpuNs() / MS, timed.runs(), timed.wallNs() / MS, timed.cpuNs() / 1e3 / n, anchor / 1e6,
                        (double) timed.cpuNs() / Math.max(1, anchor), growth, r.verdict(), r.utilisationText(), misses, schedules, segments,
                        c.jobs, c.iterations, c.firstJobSteps, c.laterJobSteps, (double) (c.firstJobSteps + c.laterJobSteps) / n, c.bucketsPassed, c.entriesLookedAt,
                        c.longestBusyPeriod <= 0 ? "" : org.rsaml.model.support.RsamlTimes.text(c.longestBusyPeriod), c.tiedDecided, c.tiedIterated,
                        c.nodesOpened, c.summaries == 0 ? "" : String.format("%.0f", (double) c.nodesOpened / c.summaries));
                previous = Math.max(1, timed.cpuNs());
                previousN = n;
            }
        }
        System.out.println();
        System.out.println("Load average (1 min) after the table: " + ValidationBench.loadAverage());
        Architecture a = architecture(modules, 100);
        TimingAnalysis.analyse(a); // JIT
        long[] times = new long[RUNS];
        long[] cpu = new long[RUNS];
        ArchitectureTiming timing = null;
        for (int i = 0; i < RUNS; i++) {
            long c0 = CPU.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            timing = TimingAnalysis.analyse(a);
            times[i] = System.nanoTime() - t0;
            cpu[i] = CPU.getCurrentThreadCpuTime() - c0;
        }
        int met = 0;
        for (LatencyResult l : timing.latencies()) {
            met += l.verdict() == Verdict.MEETS ? 1 : 0;
        }
        System.out.println();
        System.out.println("| modules | processors | latency requirements | analysis incl. execution plan, CPU time (median of " + RUNS
                + ") | wall time | verdict |");
        System.out.println("|---:|---:|---:|---:|---:|---|");
        System.out.printf("| %,d | %d | %d | %,d ms | %,d ms | %s (%d requirements met) |%n", modules, timing.processors().size(),
                timing.latencies().size(), GenerationBench.median(cpu) / MS, GenerationBench.median(times) / MS, timing.verdict(), met);
    }

    /**
     * The names of the tasks that run first in, first out: all but the first {@code others} (which the
     * runtime releases under another policy, round robin, at the same rank: then the rank is not
     * first in, first out, and every task of it is analysed preemptively with the others tied to it).
     */
    private static Set<String> fifo(List<Task> tasks, int others) {
        return tasks.stream().skip(others).map(Task::name).collect(java.util.stream.Collectors.toSet());
    }

    /** The same tasks, all at one priority (as the runtime ranks FIFO functions and module releases). */
    static List<Task> sameRank(List<Task> tasks) {
        return tasks.stream().map(t -> new Task(t.name(), t.period(), t.deadline(), t.cost(), 1, t.jitter(), t.group())).toList();
    }

    /** n tasks with harmonic periods 5 ms × 2^k (k from 0 to 7), rate-monotonic priorities, utilisation about u. */
    static List<Task> harmonic(int n, double u, Random random) {
        long[] periods = new long[n];
        double[] weights = new double[n];
        double sum = 0;
        for (int i = 0; i < n; i++) {
            periods[i] = (5L << random.nextInt(8)) * MS;
            weights[i] = random.nextDouble();
            sum += weights[i];
        }
        return rateMonotonic(periods, weights, sum, u);
    }

    /**
     * Tasks t0..t(n-1) with these periods, rate-monotonic priorities (the shortest period highest, distinct,
     * ties by index) and implicit deadlines; task i's share of the utilisation {@code u} is weights[i] / sum.
     */
    private static List<Task> rateMonotonic(long[] periods, double[] weights, double sum, double u) {
        int n = periods.length;
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        java.util.Arrays.sort(order, (x, y) -> Long.compare(periods[y], periods[x]));
        int[] priority = new int[n];
        for (int rank = 0; rank < n; rank++) {
            priority[order[rank]] = rank + 1;
        }
        List<Task> tasks = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            tasks.add(Task.implicit("t" + i, periods[i], Math.max(1, (long) (u * weights[i] / sum * periods[i])), priority[i]));
        }
        return tasks;
    }

    /** n tasks, rate-monotonic priorities (distinct, ties by index), total utilisation about 0.8. */
    static List<Task> taskSet(int n, Random random) {
        long[] periods = new long[n];
        double[] weights = new double[n];
        double sum = 0;
        for (int i = 0; i < n; i++) {
            periods[i] = PERIODS[random.nextInt(PERIODS.length)] * MS;
            weights[i] = random.nextDouble();
            sum += weights[i];
        }
        return rateMonotonic(periods, weights, sum, 0.8);
    }

    /**
     * n tasks with periods drawn from 1 to 1000 ms at microsecond resolution (nearly all distinct),
     * rate-monotonic priorities, total utilisation about {@code u}: near 1, many of the lowest
     * priorities miss their deadlines, each with a witness.
     */
    static List<Task> distinctPeriods(int n, double u, Random random) {
        long[] periods = new long[n];
        double[] weights = new double[n];
        double sum = 0;
        for (int i = 0; i < n; i++) {
            periods[i] = (1_000 + random.nextInt(999_000)) * 1_000L;
            weights[i] = random.nextDouble();
            sum += weights[i];
        }
        return rateMonotonic(periods, weights, sum, u);
    }

    /**
     * {@link SyntheticArchitecture} of {@code m} real-time periodic modules of one periodic function
     * each, on 4 processors; every 50th module also connected three modules ahead; {@code requirements}
     * latency requirements from a module's output to the entry port 10 modules on (fewer when the
     * architecture has fewer than 11 modules, none with 1 module).
     */
    static Architecture architecture(int m, int requirements) {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        List<Processor> processors = new ArrayList<>();
        for (int l = 0; l < SyntheticArchitecture.LAYERS; l++) {
            Processor p = f.createProcessor();
            p.setName("core" + l);
            p.setCore(l);
            processors.add(p);
        }
        SyntheticArchitecture.Built built = SyntheticArchitecture.build("timing", ArchitectureCategory.HYBRID, m, (module, i, n) -> {
            module.setType(ElementType.REAL_TIME);
            module.setExecType(ExecutionType.PERIODIC);
            long period = 100 + 100 * (i % 4);
            module.setPeriod(period);
            module.setExecDuration(0.2);
            processors.get(i % processors.size()).getModules().add(module);
            Function fn = f.createFunction();
            fn.setName("step");
            fn.setExecType(ExecutionType.PERIODIC);
            fn.setPeriod(period);
            fn.setExecDuration(0.2);
            fn.setSchedPolicy(SchedulingPolicy.RM);
            module.getFunctions().add(fn);
        });
        Architecture a = built.architecture();
        a.getProcessors().addAll(processors);
        List<EntryPort> ins = built.ins();
        List<OutputPort> outs = built.outs();
        for (int i = 0; i + 3 < m; i += 50) {
            SyntheticArchitecture.connect(a, outs.get(i), ins.get(i + 3));
        }
        int span = Math.min(10, m - 1);
        for (int r = 0; span > 0 && r < requirements; r++) {
            int from = (int) ((long) r * (m - span) / requirements);
            LatencyRequirement req = f.createLatencyRequirement();
            req.setName("req" + r);
            req.setSource(outs.get(from));
            req.setTarget(ins.get(from + span));
            req.setMaxLatency(5000);
            a.getLatencyRequirements().add(req);
        }
        return a;
    }
}
