/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Reaction;
import org.rsaml.analysis.plan.Release;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.cxx.OneMachineCpus;
import org.rsaml.model.Architecture;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.ModelLoader;

/**
 * Every job of a generated C++ program measured against the timing analysis's bound (docs/timing.md,
 * "What the C++ program measures"). The programs run with {@code --busy-work 100}: each job first
 * consumes its modeled execution time on the CPU, so the run is the worst case the analysis assumes.
 * <p>
 * The bound can only be asserted where the program got the scheduling the analysis assumes
 * (SCHED_FIFO/SCHED_RR at its ranks, SCHED_DEADLINE for EDF; each release's summary line says what
 * it got, as the kernel granted it) and every processor has a core of this machine to itself. Where
 * not (no CAP_SYS_NICE, a container without real-time budget, a model's core this machine lacks), the
 * test says so on standard output and checks what does not depend on it: the
 * summary of every release, the analysis's bound written into the program, the jobs counted, the
 * busy work consumed, and misses and overruns reported as they happen.
 * <p>
 * Each run is checked by {@link CppJobCheck}. The platform's part of a response, which the model does
 * not count, is measured during the run: the platform monitor ({@link PlatformCheck.Monitor}), started
 * before the program and stopped after it, records on every CPU, above every thread of the program, the
 * time the CPU did not run it; each bound is computed again with the most such time in a window as long
 * as the response (by the analysis itself on a fixed-priority processor), plus a stated constant for
 * the bookkeeping and the CPU time other programs' real-time threads used during the run
 * ({@link PlatformCheck#boundCheck}); every check prints the monitor's measurements, and a failure the
 * loss it took (CPU, window, the longest single delay and when) and the bound with it. While other
 * programs' real-time threads use more than {@link OtherRealtime#TOLERATED_NS} during a run, its bounds
 * are not checked, and the test says so, naming them and their CPU time; with
 * {@code RSAML_TIMING_BOUNDS=required} (CI) that fails instead, as does a monitor without real-time priority.
 * <p>
 * Slow on a shared machine (6.5 to 7 minutes on two cores under a load average of 20 to 30, mostly building the
 * programs): run it alone with {@code -Dtest=JobTimingTest -Dsurefire.failIfNoSpecifiedTests=false}
 * (or one method, {@code -Dtest=JobTimingTest#anEdfProcessorRunsUnderSchedDeadline}).
 */
class JobTimingTest {

    static String ms(long ns) {
        return String.format(Locale.ROOT, "%.3f ms", ns / 1e6);
    }

    /** The examples whose analysis bounds at least one timed release. */
    static List<String> timedExamples() throws Exception {
        List<String> timed = new ArrayList<>();
        for (String example : Tools.cleanExamples()) {
            Architecture arch = ModelLoader.load(Tools.example(example), example).architecture();
            if (!bounds(TimingAnalysis.analyse(arch)).isEmpty()) {
                timed.add(example);
            }
        }
        return timed;
    }

    /** Per task name (the release's label), the analysis's bound: its response time, or its deadline where EDF proves it. */
    static Map<String, Long> bounds(ArchitectureTiming timing) {
        Map<String, Long> bounds = new HashMap<>();
        for (ProcessorTiming p : timing.processors()) {
            for (TaskResult t : p.result().tasks()) {
                if (t.responseTime().isPresent()) {
                    bounds.put(t.task().name(), t.responseTime().getAsLong());
                } else if (t.verdict() == Verdict.MEETS) {
                    bounds.put(t.task().name(), t.task().deadline());
                }
            }
        }
        return bounds;
    }

    /** Per task name (the release's label), the analysis's verdict. */
    static Map<String, Verdict> verdicts(ArchitectureTiming timing) {
        Map<String, Verdict> verdicts = new HashMap<>();
        for (ProcessorTiming p : timing.processors()) {
            for (TaskResult t : p.result().tasks()) {
                verdicts.put(t.task().name(), t.verdict());
            }
        }
        return verdicts;
    }

    @ParameterizedTest
    @MethodSource("timedExamples")
    void everyJobOfAnExampleStaysWithinItsBound(String example, @TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("project");
        new RsamlGenerator().generate(Tools.example(example), Target.CPP, out, false);
        Architecture arch = ModelLoader.load(Tools.example(example), example).architecture();
        CppJobCheck.runAndCheck(arch, out, example);
    }

    /**
     * Random task sets, from fixed seeds: two processors of three to five rate-monotonic tasks each
     * (one per core), at 40 to 75 % utilisation, every task bounded by the analysis.
     */
    @ParameterizedTest
    @ValueSource(longs = { 20261126L, 7L })
    void everyJobOfARandomTaskSetStaysWithinItsBound(long seed, @TempDir Path tmp) throws Exception {
        Path model = tmp.resolve("random" + seed + ".rsaml");
        Files.writeString(model, randomTaskSet(seed));
        Path out = tmp.resolve("project");
        new RsamlGenerator().generate(model, Target.CPP, out, false);
        Architecture arch = ModelLoader.load(model, model.getFileName().toString()).architecture();
        CppJobCheck.runAndCheck(arch, out, "random" + seed);
        ArchitectureTiming timing = TimingAnalysis.analyse(arch);
        assertEquals(Verdict.MEETS, timing.verdict(), "seed " + seed + ": the generated sets are meant to be schedulable");
    }

    /**
     * A random task set from a seed, as a model: two processors (cores 0 and 1) of three to five
     * rate-monotonic tasks each, at 40 to 75 % utilisation. Ros2LaunchTest runs such sets too.
     */
    static String randomTaskSet(long seed) {
        Random random = new Random(seed);
        StringBuilder layers = new StringBuilder();
        StringBuilder processors = new StringBuilder();
        long[] periods = { 5, 8, 10, 20, 25, 40, 50 };
        for (int core = 0; core < 2; core++) {
            int n = 3 + random.nextInt(3);
            double target = 0.4 + random.nextDouble() * 0.35;
            StringBuilder refs = new StringBuilder();
            for (int i = 0; i < n; i++) {
                long period = periods[random.nextInt(periods.length)];
                double cost = Math.max(0.3, Math.round(target / n * period * 10) / 10.0);
                String name = "t" + core + "_" + i;
                layers.append(module(name, period, cost, "RM"));
                refs.append(refs.length() == 0 ? "" : " ").append("//@layers[name='tasks']/@modules[name='").append(name).append("']");
            }
            processors.append("  <processors name=\"cpu").append(core).append("\" core=\"").append(core).append("\" modules=\"")
                    .append(refs).append("\"/>\n");
        }
        return modelText("random" + seed, layers.toString(), processors.toString());
    }

    /**
     * A sporadic module's reactions measured from the arrival that starts one to its completion: a
     * producer (T 10, C 2, rate monotonic) sends to a sporadic consumer (minimum interval 20 ms, C 3,
     * delay 20 ms) on the same core. The consumer reacts to every other message (arrivals at least
     * 20 ms apart), on its worker thread at priority 0 below the producer: its bound is 3 ms plus the
     * producer's preemptions, 5 ms.
     */
    @Test
    void aSporadicReactionIsMeasuredAgainstItsBound(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("project");
        Architecture arch = writeAndGenerate(tmp, "sporadic", producerAndConsumer(10, 2, "20.0", "20.0", "3.0"), PRODUCER_AND_CONSUMER, out, false);
        Map<String, Long> bounds = bounds(TimingAnalysis.analyse(arch));
        assertEquals(5_000_000L, bounds.get("tasks/consumer (reaction)"), "the analysis's bound of the reaction: " + bounds);
        Map<String, JobSummary> run = CppJobCheck.runAndCheck(arch, out, "sporadic");
        JobSummary s = run.get("tasks/consumer (reaction)");
        JobSummary producer = run.get("tasks/producer.f");
        assertNotNull(producer, "the producer's summary: " + run.keySet());
        // a message every 10 ms, a reaction to every other one (arrivals at least 20 ms apart): half as many reactions as
        // messages sent, counted from the producer's own jobs (the run's length is decided by a thread that is not real-time)
        long sent = producer.jobs();
        assertTrue(sent >= CppJobCheck.RUN_MS / 10 * 8 / 10, "about " + CppJobCheck.RUN_MS / 10 + " messages sent in " + CppJobCheck.RUN_MS + " ms: "
                + producer);
        assertTrue(s.jobs() >= sent / 4 && s.jobs() <= (sent + 1) / 2 + 1, "about half as many reactions as the " + sent
                + " messages sent (every other arrival, at least 20 ms apart): " + s);
        assertTrue(s.worstNs() >= s.executionNs(), "a response includes the reaction's execution: " + s);
    }

    /**
     * A module whose reactions are aperiodic, offered more data than it can react to, takes no real-time time from the
     * releases on its core: a producer (T 2, C 0.2) sends every 2 ms to a consumer that takes 5 ms a reaction (2.5 CPUs of
     * work offered, so its worker is always ready), beside A (T 10, C 2), all on core 1, for 2.5 s (past the kernel's
     * real-time period of 1 s, whose 95 % a real-time worker always ready would use up, after which the kernel would
     * hold every real-time thread of the core, the releases included, for the rest of the second). The consumer's
     * worker serves it at the default priority (its trace and summary say so) and its lock inherits priority; the
     * releases, whose analysis the consumer does not touch, keep their bounds with the platform's loss ({@link
     * CppJobCheck}: a send copies its data into a slot of the consumer's mailbox, allocating nothing the worker frees, so
     * that it never waits for the worker in the allocator, as two CI runs saw when each message's closure and queue node
     * were allocated by the producer and freed by the worker), the platform monitor on core 1 is never held back as the
     * kernel's throttling would hold it (a hold of 50 ms each second), and the consumer reacts in the time they leave;
     * the messages its full mailbox dropped are said and counted.
     */
    @Test
    void anAperiodicReactionOfferedTooMuchDataLeavesTheReleasesTheirBounds(@TempDir Path tmp) throws Exception {
        // the consumer aperiodic: no period, 5 ms a reaction
        String layers = producer(2, 0.2) + "    <modules name=\"consumer\" timeUnit=\"ms\" execDuration=\"5.0\">\n"
                + "      <ports xsi:type=\"rsaml:EntryPort\" name=\"in\" dataType=\"numeric\"/>\n    </modules>\n" + module("a", 10, 2, "RM");
        String processors = PRODUCER_AND_CONSUMER.replace("@modules[name='consumer']\"/>",
                "@modules[name='consumer'] //@layers[name='tasks']/@modules[name='a']\"/>");
        Path out = tmp.resolve("project");
        Architecture arch = writeAndGenerate(tmp, "flooded", layers, processors, out, false);
        ArchitectureTiming timing = TimingAnalysis.analyse(arch);
        assertEquals(List.of("tasks/consumer"), timing.excluded().stream().map(x -> x.label()).toList(), "the consumer's reactions are aperiodic");
        Map<String, Long> bounds = bounds(timing);
        assertTrue(bounds.containsKey("tasks/producer.f") && bounds.containsKey("tasks/a.f"), "the releases keep their bounds: " + bounds);

        // the program's own words: the consumer's worker at the default priority, every module's lock inheriting priority
        String traced = Tools.ok(out, 60, Tools.cmakeBuild(out, CppExamplesTest.executableName(out)).toString(), "--run-for-ms", "200");
        RunTrace trace = new RunTrace(traced);
        assertEquals(1, trace.matching("sched tasks/consumer worker default: it serves aperiodic reactions, whose load the model does not"
                + " bound, below every real-time thread").size(), "the consumer's worker at the default priority:\n" + Tools.last(traced, 3000));
        for (String module : List.of("tasks/producer", "tasks/consumer", "tasks/a")) {
            assertEquals(1, trace.matching("lock " + module + " PTHREAD_PRIO_INHERIT").size(),
                    module + "'s lock inherits priority:\n" + Tools.last(traced, 3000));
        }
        assertTrue(trace.matching("sched tasks/producer worker ").stream().noneMatch(l -> l.contains("aperiodic")),
                "a module that does not react keeps its worker at priority 0: " + trace.matching("sched tasks/producer worker "));

        CppJobCheck.Run flooded = CppJobCheck.run(arch, out, "flooded", 2500);
        Map<String, JobSummary> run = flooded.summaries();
        if (flooded.allowance() != null) {
            // The kernel's throttling, which an always-ready real-time worker would bring about, holds every real-time thread
            // of the core for the last 50 ms of each second, the platform monitor's too: CppJobCheck's allowance would count
            // that hold as the platform's loss and excuse the releases. So the monitor's delays of 25 ms or more on core 1
            // (its CPU here) are counted, those of that CPU alone (throttling is the CPU's; a stall of the whole machine,
            // which the other CPU's monitor shares, is not): two in the run of 2.5 s would be the throttle's, once a second.
            int cpu = OneMachineCpus.of(arch).values().iterator().next();
            PlatformCheck.Platform platform = flooded.allowance().platform();
            List<String> holds = new java.util.ArrayList<>();
            List<String> shared = new java.util.ArrayList<>();
            for (PlatformCheck.CpuRecords c : platform.cpus()) {
                for (int i = 0; c.cpu() == cpu && i < c.starts().length; i++) {
                    long from = c.starts()[i];
                    long length = c.ends()[i] - from;
                    if (length < 25_000_000L) {
                        continue;
                    }
                    boolean everyCpu = platform.cpus().stream().filter(o -> o.cpu() != cpu)
                            .allMatch(o -> platform.lossIn(o.cpu(), from, from + length).ns() >= length / 2);
                    (everyCpu ? shared : holds).add(ms(length) + " at " + ms(from - platform.fromNs()) + " into the run");
                }
            }
            assertTrue(holds.size() < 2, "real-time throttling on CPU " + cpu + " (a hold of 50 ms each second): the platform monitor's"
                    + " delays there, the other CPUs running: " + holds + (shared.isEmpty() ? "" : "; stalls of every CPU, not counted: " + shared));
            if (!shared.isEmpty()) {
                System.out.println("JobTimingTest flooded: stalls of every CPU at once, not throttling: " + shared);
            }
        }
        JobSummary consumer = run.get("tasks/consumer (reaction)");
        assertEquals("default (aperiodic reactions)", consumer.sched(), "the consumer's summary says where it ran: " + consumer);
        JobSummary producer = run.get("tasks/producer.f");
        // the consumer reacts in what the releases leave of the core (70 %), 5 ms a reaction: far fewer than the messages sent
        assertTrue(consumer.jobs() > 0 && consumer.jobs() * 5 < 2500, "the consumer reacted, but to no more than the core could take: " + consumer);
        // offered 2.5 CPUs of reactions, it takes at most the core: more than twice as many messages as reactions
        assertTrue(producer.jobs() > 2 * consumer.jobs(), "more messages were sent than the consumer could react to: " + producer + ", " + consumer);
        // the rest were dropped, the mailbox full, and said: every message sent (one a job, and one at the start) was reacted
        // to or dropped, but those left in the mailbox at the stop
        java.util.regex.Matcher dropped = java.util.regex.Pattern.compile("(?m)^\\[[ 0-9.]+ ms\\] mailbox tasks/consumer dropped (\\d+)"
                + " messages in all: its (\\d+) slots were taken").matcher(flooded.output());
        assertTrue(dropped.find(), "the consumer's full mailbox dropped messages, said with the summary:\n" + Tools.last(flooded.output(), 3000));
        long accounted = consumer.jobs() + Long.parseLong(dropped.group(1));
        long slots = Long.parseLong(dropped.group(2));
        assertTrue(accounted <= producer.jobs() + 1 && accounted >= producer.jobs() + 1 - slots, "each message sent reacted to or dropped, but"
                + " at most the " + slots + " left in the mailbox: " + dropped.group() + "; " + producer + ", " + consumer);
    }

    /**
     * A processor the analysis proves overloaded: A (T 10, C 5) and B (T 14, C 6) under rate
     * monotonic; B's worst response is 16 ms, past its 14 ms deadline. Run as modeled, the program
     * reports B's misses (under real-time scheduling; A, above it, meets); with --busy-work 150 every
     * job of both uses more than its modeled time and is reported as an overrun whatever the scheduling.
     */
    @Test
    void anOverloadedProcessorMissesAsPredicted(@TempDir Path tmp) throws Exception {
        String layers = module("a", 10, 5, "RM") + module("b", 14, 6, "RM");
        String processors = "  <processors name=\"cpu1\" core=\"1\" modules=\"//@layers[name='tasks']/@modules[name='a']"
                + " //@layers[name='tasks']/@modules[name='b']\"/>\n";
        Path out = tmp.resolve("project");
        // the analysis's miss is an error finding: generated anyway (--force), as an architect would to see it
        Architecture arch = writeAndGenerate(tmp, "overloaded", layers, processors, out, true);
        ArchitectureTiming timing = TimingAnalysis.analyse(arch);
        TaskResult b = timing.processors().get(0).result().tasks().stream().filter(t -> t.task().name().equals("tasks/b.f"))
                .findFirst().orElseThrow();
        assertEquals(Verdict.MISSES, b.verdict(), "the analysis predicts B's miss: " + b.explanation());

        CppJobCheck.Run run = CppJobCheck.run(arch, out, "overloaded");
        Map<String, JobSummary> asModeled = run.summaries();
        JobSummary sb = asModeled.get("tasks/b.f");
        if (sb.asAnalysed()) {
            assertTrue(sb.misses() > 0, "B's miss, predicted by the analysis, was not observed: " + sb);
            // A has the higher priority and meets: where the run held it to the analysis (the platform measured), each of its
            // jobs past its bound, a miss included, was held there to its bound with the platform's loss at that moment and
            // failed if past it (a stall of every CPU can make A miss); where it could not, A may miss nothing
            JobSummary sa = asModeled.get("tasks/a.f");
            boolean held = run.allowance() != null && sa.asAnalysed() && run.allowance().unchecked("tasks/a.f") == null;
            assertTrue(held || sa.misses() == 0, "A has the higher priority and meets: neither held to its bound with the platform"
                    + " as measured nor without a miss: " + sa + "; platform: " + run.allowance());
        }

        String doubled = Tools.ok(out, 60, Tools.cmakeBuild(out, CppExamplesTest.executableName(out)).toString(), "--run-for-ms",
                "400", "--quiet", "--busy-work", "150");
        Map<String, JobSummary> over = JobSummary.of(doubled);
        for (JobSummary s : over.values()) {
            assertTrue(s.jobs() > 0, "no job of " + s.label() + " completed:\n" + doubled);
            assertEquals(s.jobs(), s.overruns(), "every job used half as much again as its modeled time: " + s);
            RunTrace.assertNoneDropped("the doubled run", doubled);
            assertEquals(s.overruns(), new RunTrace(doubled).matching("overrun " + s.label() + " job ").size(),
                    "an overrun line per overrun of " + s.label());
        }
        assertTrue(over.get("tasks/b.f").misses() > 0, "B needs 8.7 ms of the 2.75 ms A leaves it every 10 ms, so it misses: "
                + over.get("tasks/b.f"));
    }

    /**
     * An EDF processor runs its releases under SCHED_DEADLINE (runtime = modeled cost, deadline,
     * period), as the kernel reports it back, each a deadline thread from its first release, so that
     * the kernel's periods are its releases; and every job is held to EDF's bound (its deadline) with
     * the platform's loss ({@link CppJobCheck}). Two sets, each feasible under EDF only: A (T 5, C 2) and
     * B (T 7, C 4), which rate monotonic would miss; and with deadlines shorter than periods, A (T 5, D 4,
     * C 2) and B (T 8, D 6, C 3.5), which deadline monotonic would miss. Where the kernel refuses, the
     * trace says so and what the release got instead.
     */
    @ParameterizedTest
    @ValueSource(booleans = { false, true })
    void anEdfProcessorRunsUnderSchedDeadline(boolean constrained, @TempDir Path tmp) throws Exception {
        double[][] set = constrained ? new double[][] { { 5, 4, 2 }, { 8, 6, 3.5 } } : new double[][] { { 5, 5, 2 }, { 7, 7, 4 } };
        String layers = module("a", (long) set[0][0], (long) set[0][1], set[0][2], "EDF") + module("b", (long) set[1][0], (long) set[1][1], set[1][2], "EDF");
        String processors = "  <processors name=\"edf\" schedPolicy=\"EDF\" core=\"1\" modules=\"//@layers[name='tasks']/@modules[name='a']"
                + " //@layers[name='tasks']/@modules[name='b']\"/>\n";
        Path out = tmp.resolve("project");
        String what = constrained ? "edf-constrained" : "edf";
        Architecture arch = writeAndGenerate(tmp, what, layers, processors, out, false);
        assertEquals(Verdict.MEETS, TimingAnalysis.analyse(arch).verdict(), "EDF schedules A and B");
        Map<String, JobSummary> run = CppJobCheck.runAndCheck(arch, out, what);
        for (JobSummary s : run.values()) {
            double[] t = s.label().equals("tasks/a.f") ? set[0] : set[1];
            String granted = "SCHED_DEADLINE runtime " + ms(Math.round(t[2] * 1e6)) + " deadline " + ms(Math.round(t[1] * 1e6)) + " period "
                    + ms(Math.round(t[0] * 1e6));
            if (s.sched().startsWith("SCHED_DEADLINE")) {
                assertTrue(s.sched().startsWith(granted) && s.sched().contains(", its periods from its first release (asked ")
                        && s.sched().contains("(kernel: " + granted), "the kernel's policy, runtime, deadline and period (sched_getattr) for "
                                + s.label() + ", a deadline thread from its first release: " + s.sched());
                System.out.println("JobTimingTest " + what + ": SCHED_DEADLINE in force for " + s.label() + " (" + s.sched() + ")");
            } else {
                assertTrue(s.sched().matches("(SCHED_FIFO rank \\d+|default) instead of EDF: .+"), "the fallback, said: " + s.sched());
                System.out.println("JobTimingTest: SCHED_DEADLINE not granted here (" + s.sched() + "): checked the fallback and its report");
            }
        }
    }

    /**
     * Two hosts' "core 0" in one program: mobile-base-latency with its navigation processor moved to
     * core 0 of the board "nav-board". The analysis counts the two processors apart (different
     * hosts), so the one program gives the board's core 0 a CPU of its own on this machine (CPU 1,
     * said in the trace), and every release is held to its bound there.
     */
    @Test
    void twoHostsCoresGetCpusOfTheirOwnInOneProgram(@TempDir Path tmp) throws Exception {
        String text = Files.readString(Tools.example("mobile-base-latency.rsaml"));
        String nav = "<processors name=\"core1\" description=\"CPU core 1: navigation.\" core=\"1\"";
        assertTrue(text.contains(nav), "mobile-base-latency's navigation processor");
        Path model = tmp.resolve("two-hosts.rsaml");
        Files.writeString(model, text.replace(nav, "<processors name=\"core1\" description=\"Core 0 of the navigation board.\" core=\"0\""
                + " host=\"nav-board\""));
        Path out = tmp.resolve("project");
        new RsamlGenerator().generate(model, Target.CPP, out, false);
        Architecture arch = ModelLoader.load(model, "two-hosts.rsaml").architecture();
        ArchitectureTiming timing = TimingAnalysis.analyse(arch);
        assertEquals(2, timing.processors().size(), "two processors, analysed apart");
        assertTrue(bounds(timing).containsKey("navigation/obstacleDetector.detect") && bounds(timing).containsKey("control/velocityController.control"),
                "both processors' releases are bounded by the analysis: " + bounds(timing));
        Path exe = Tools.cmakeBuild(out, CppExamplesTest.executableName(out));
        RunTrace trace = new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", "200"));
        assertEquals(List.of("cpu control/velocityController core 0"), trace.matching("cpu control/velocityController core"),
                "the main host's core 0 is CPU 0");
        List<String> board = trace.matching("cpu navigation/obstacleDetector");
        assertTrue(!board.isEmpty(), "the board's module is placed:\n" + Tools.last(trace.output, 3000));
        if (Runtime.getRuntime().availableProcessors() >= 2) {
            for (String line : board) {
                assertTrue(line.startsWith("cpu navigation/obstacleDetector") && line.contains(" core 0 of host nav-board on CPU 1 (one program runs every host"),
                        "the board's core 0 on a CPU of its own, said: " + line);
            }
            CppJobCheck.runAndCheck(arch, out, "two-hosts");
        } else {
            assertTrue(board.stream().allMatch(l -> l.endsWith(" not available: default")),
                    "on one CPU, the board's CPU 1 is not there, said plainly: " + board);
        }
    }

    /**
     * A producer (a module of one function, rate monotonic, period and cost given, with an output port "out") and a
     * sporadic consumer of it (an entry port "in"; its minimum interval, delay and execution time in ms given).
     */
    static String producerAndConsumer(long period, double cost, String consumerPeriod, String consumerDelay, String consumerCost) {
        return producer(period, cost) + "    <modules name=\"consumer\" timeUnit=\"ms\" type=\"realTime\" period=\"" + consumerPeriod
                + "\" delay=\"" + consumerDelay + "\" execDuration=\"" + consumerCost + "\" execType=\"sporadic\">\n"
                + "      <ports xsi:type=\"rsaml:EntryPort\" name=\"in\" dataType=\"numeric\"/>\n    </modules>\n";
    }

    /** A periodic producer (rate monotonic) with an output port "out", sent after each of its jobs. */
    static String producer(long period, double cost) {
        return module("producer", period, cost, "RM").replace("    </modules>",
                "      <ports xsi:type=\"rsaml:OutputPort\" name=\"out\" dataType=\"numeric\"/>\n    </modules>");
    }

    /** The producer and the consumer of {@link #producerAndConsumer} on core 1, the producer's "out" connected to the consumer's "in". */
    static final String PRODUCER_AND_CONSUMER = "  <processors name=\"cpu1\" core=\"1\" modules=\"//@layers[name='tasks']/@modules[name='producer']"
            + " //@layers[name='tasks']/@modules[name='consumer']\"/>\n  <connections source=\"//@layers[name='tasks']/@modules[name='producer']/@ports[name='out']\""
            + " target=\"//@layers[name='tasks']/@modules[name='consumer']/@ports[name='in']\"/>\n";

    static String module(String name, long period, double cost, String policy) {
        return module(name, period, period, cost, policy);
    }

    /** A periodic module of one function, its deadline (delay) given. */
    static String module(String name, long period, long delay, double cost, String policy) {
        String timing = String.format(Locale.ROOT, "timeUnit=\"ms\" type=\"realTime\" period=\"%d.0\" delay=\"%d.0\" execDuration=\"%s\""
                + " execType=\"periodic\"", period, delay, cost);
        return "    <modules name=\"" + name + "\" " + timing + ">\n      <functions name=\"f\" " + timing + " schedPolicy=\"" + policy
                + "\"/>\n    </modules>\n";
    }

    private static Architecture writeAndGenerate(Path tmp, String name, String modules, String processors, Path out, boolean force)
            throws Exception {
        Path model = tmp.resolve(name + ".rsaml");
        Files.writeString(model, modelText(name, modules, processors));
        new RsamlGenerator().generate(model, Target.CPP, out, force);
        return ModelLoader.load(model, name + ".rsaml").architecture();
    }

    /** A model of one layer, "tasks", holding the modules, and the processors. */
    static String modelText(String name, String modules, String processors) {
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<rsaml:Architecture xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\""
                + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"" + name
                + "\" category=\"other\" declaredLayers=\"1\">\n"
                + "  <layers name=\"tasks\" timeUnit=\"ms\" level=\"0\" maxExecTime=\"1000.0\">\n" + modules + "  </layers>\n" + processors
                + "</rsaml:Architecture>\n";
    }
}
