/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.Reaction;
import org.rsaml.analysis.plan.Release;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.Names;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.support.RsamlTopics;
import org.rsaml.validation.ModelLoader;

/**
 * The generated ROS 2 packages on a real ROS 2 (see {@link Ros2Jazzy}): built with colcon, started
 * with {@code ros2 launch} on the loopback in a domain of their own, every job busy-working
 * {@link #LOAD} of its modeled execution time. Every node starts; every timed release runs at its
 * modeled period, or at the period its package's parameters file gives it (in {@link #TUNED}, one period
 * doubled in config/&lt;pkg&gt;.params.yaml before the build), with no job skipped (judged by the nodes' own release times); messages arrive
 * at every connected entry port at the rate their publisher is released; every node reports the
 * timing analysis's bound of each release (written into it by the generator); where the system
 * grants real-time priorities, to the releases whose threads have a CPU to themselves as the launch places them
 * ({@link PlatformCheck#notApart}; the others are reported with the reason), the run does not contradict the analysis
 * ({@link #contradictions}): no
 * release of a task the analysis says meets its deadline is dropped by ROS 2's timer unless the late call
 * that made the timer drop it is within the task's bound with the platform's loss, and each release's
 * worst observed response (release to completion,
 * measured by the node on its clock), and each reaction's (from the arrival its node's data thread takes
 * to completion), is within its bound with the platform as measured during the launch ({@link PlatformCheck}: the
 * platform monitor, started before the launch and stopped after it, records on every CPU, above every thread of the
 * model, the time the CPU did not run the model; each job over the analysed bound, as its node lists it on
 * CLOCK_MONOTONIC, is held to the bound computed again with the loss in that job's own window, and a stated constant
 * for the bookkeeping with the executor's measured work; a failure says the job, the loss it took, where and when), unless
 * other programs' real-time threads ran
 * beyond a tolerance ({@link OtherRealtime}: said, naming them; a failure under {@code RSAML_TIMING_BOUNDS=required}, as in CI); the topics the model
 * names exist under those names with their publisher and subscribers (one of them renamed through
 * its launch argument, its QoS set by the model's name in the parameters file and in effect under
 * the new name); and everything exits cleanly on SIGINT. What else runs on ROS 2: {@link Ros2LaunchFilesTest} (host:=, the
 * CPUs, an invalid parameters file, the package's own launch test), {@link Ros2LifecycleLaunchTest} (managed nodes) and
 * {@link Ros2SharedMessagesTest} (messages shared in a container). By default a representative set: an example with two processors, a message
 * type of its own and connections, a model where a long low-priority job must not delay a short
 * high-priority one on the same core, an inhibitor, two EDF processors (one pinned to a core, one not: each
 * release under SCHED_DEADLINE with the kernel's runtime, deadline and period, or the kernel's refusal and the
 * fallback, and the test says which it saw), and one seeded random task set (two processors of rate-monotonic
 * tasks, as {@link JobTimingTest} runs on the C++ runtime), a chain of two reactions sharing a core with a timed
 * release (ros2-reaction.rsaml), a processor pinned to a core beside an EDF processor without one (ros2-mixed-placement.rsaml:
 * the EDF one kept to the CPUs left, where the kernel refuses it SCHED_DEADLINE, docs/timing.md "EDF beside processors with
 * cores"), and, always, a processor the analysis says misses, whose
 * predicted misses must show ({@link #anOverloadedProcessorMissesAsPredicted}); {@code -Drsaml.ros2.examples=all} runs every example
 * without errors as well,
 * {@code -Drsaml.ros2.examples=mobile-base-latency.rsaml,resources/inhibitor-window.rsaml} only
 * those ({@code resources/ros2-two-hosts.rsaml}: two hosts' core 0 on one machine, each node's threads on the CPU the launch
 * gave its process), and {@code -Drsaml.ros2.seeds=1,2,3} other random sets. Every run checks that each release's thread is
 * pinned where the launch placed its process (OneMachineCpus), as its cpu line says.
 */
class Ros2LaunchTest {

    /**
     * The share of its modeled execution time each job busy-works: all of it, as the analysis assumes. ROS 2's own
     * work for a job (the executor's wake-up, taking the timer, the dispatch) is not hidden in a margin of the job's
     * time: each node measures it, and the check adds it to every job as stated bookkeeping
     * ({@link PlatformCheck#ros2BookkeepingNs}; docs/timing.md, "The platform's allowance").
     */
    static final double LOAD = 1.0;
    /** How long the system runs once every node is up. */
    static final long RUN_MS = 5000;

    /** The seeds of the random task sets run on ROS 2 (one by default; -Drsaml.ros2.seeds=1,2,3 for others). */
    static List<Long> seeds() {
        String seeds = Tools.option("rsaml.ros2.seeds");
        return java.util.Arrays.stream((seeds.isBlank() ? "20261127" : seeds).split(",")).map(String::trim)
                .filter(x -> !x.isEmpty()).map(Long::valueOf).toList();
    }

    static List<String> models() throws Exception {
        String chosen = Tools.option("rsaml.ros2.examples");
        if (!chosen.isBlank() && !"all".equals(chosen)) {
            return java.util.Arrays.stream(chosen.split(",")).map(String::trim).filter(x -> !x.isEmpty()).toList();
        }
        List<String> models = new ArrayList<>(List.of("mobile-base-latency.rsaml", "resources/ros2-preemption.rsaml", "resources/inhibitor-window.rsaml",
                "resources/ros2-edf.rsaml", "resources/ros2-edf-constrained.rsaml", "resources/ros2-reaction.rsaml",
                "resources/ros2-mixed-placement.rsaml"));
        if ("all".equals(chosen)) {
            for (String e : Tools.cleanExamples()) {
                if (!models.contains(e)) {
                    models.add(e);
                }
            }
        }
        return models;
    }

    static final Pattern PORT = Pattern.compile("summary (\\S+) messages (\\d+) received ([\\d.]+)\\.\\.([\\d.]+) ms");

    /** The model whose parameters file the test edits, as a user tunes the system without generating again. */
    static final String TUNED = "mobile-base-latency.rsaml";

    @ParameterizedTest
    @MethodSource("models")
    void buildsStartsAndRunsAsAnalysed(String name, @TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        run(Ros2Test.model(name), name, tmp, src -> {
        });
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void aRandomTaskSetRunsAsAnalysed(long seed, @TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Path model = tmp.resolve("random" + seed + ".rsaml");
        Files.writeString(model, JobTimingTest.randomTaskSet(seed));
        run(model, model.getFileName().toString(), tmp, src -> {
        });
    }

    /**
     * A processor the analysis says misses, on ROS 2, shows the misses it predicts, seen as the check of
     * every other run sees them ({@link Missed}, {@link #contradictions}). On core 1, under rate monotonic:
     * A (T 10, C 5) above B (T 13, deadline 4, C 2.5), whose worst response is 7.5 ms, past its deadline;
     * C (T 3, C 0.625, FIFO) at rank 1 below both, whose job waits for A's, longer than its period, so
     * ROS 2's timer drops C's releases that fall due meanwhile. The periods' phases drift through each
     * other (13 against 10), so B's misses do not depend on when the nodes started. A meets, and is
     * held to that: its bound, each miss (a stall of the platform's) within it with the platform's loss. B's and C's misses are reported, not contradictions, and must be
     * seen where the releases got their real-time priorities: B past its deadline, C dropped.
     */
    @Test
    void anOverloadedProcessorMissesAsPredicted(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String modules = JobTimingTest.module("a", 10, 5, "RM")
                + JobTimingTest.module("b", 13, 2.5, "RM").replace("delay=\"13.0\"", "delay=\"4.0\"")
                + JobTimingTest.module("c", 3, 0.625, "FIFO");
        String processors = "  <processors name=\"cpu1\" core=\"1\" modules=\"//@layers[name='tasks']/@modules[name='a']"
                + " //@layers[name='tasks']/@modules[name='b'] //@layers[name='tasks']/@modules[name='c']\"/>\n";
        Path model = tmp.resolve("overloaded.rsaml");
        Files.writeString(model, JobTimingTest.modelText("overloaded", modules, processors));
        Architecture arch = ModelLoader.load(model, "overloaded.rsaml").architecture();
        Map<String, Verdict> verdicts = JobTimingTest.verdicts(TimingAnalysis.analyse(arch));
        assertEquals(Map.of("tasks/a.f", Verdict.MEETS, "tasks/b.f", Verdict.MISSES, "tasks/c.f", Verdict.MISSES), verdicts,
                "the analysis: A meets, B and C miss");

        // the analysis's misses are error findings: generated anyway, as an architect would to see them
        long before = System.nanoTime(); // CLOCK_MONOTONIC, as the nodes' instants
        java.util.Set<String> held = new java.util.TreeSet<>();
        String out = run(model, "overloaded.rsaml", tmp, src -> {
        }, true, held);
        long after = System.nanoTime();
        Map<String, JobSummary> observed = JobSummary.of(out);
        Map<String, Missed> missed = Missed.of(out);
        JobSummary b = observed.get("tasks/b.f");
        JobSummary c = observed.get("tasks/c.f");
        if (!b.asAnalysed() || !c.asAnalysed()) {
            System.out.println("Ros2LaunchTest overloaded: B and C did not get their real-time priorities (" + b.sched() + "; " + c.sched()
                    + "): the predicted misses are not asserted");
            return;
        }
        assertTrue(missed.getOrDefault("tasks/b.f", Missed.NONE).late() > 0, "B's miss, predicted by the analysis (worst response 7.5 ms,"
                + " deadline 4 ms), was not observed on ROS 2: " + b + "\n" + Tools.last(out, 4000));
        assertTrue(missed.getOrDefault("tasks/c.f", Missed.NONE).dropped() > 0, "C's releases, due while A's 4 ms jobs run above it"
                + " (period 3 ms), were not dropped by ROS 2's timer and counted as misses: " + c + "\n" + Tools.last(out, 4000));
        // each drop said with the late call that made the timer drop it, on the monitor's clock: a period or more after its release
        List<long[]> calls = missed.get("tasks/c.f").lateCalls();
        assertTrue(!calls.isEmpty() && calls.stream().allMatch(x -> x[1] - x[0] >= 3_000_000 && x[0] > before && x[1] < after),
                "C's drops, each with the release before them and its call a period or more later, during the launch: "
                        + calls.stream().map(x -> x[0] + ".." + x[1]).limit(5).toList());
        // A, at the top rank, meets: where run() held it to the analysis, each of its misses (a job past its deadline, a
        // release dropped after a late call) was held to its bound with the platform's loss at that moment and failed if
        // past it; where it could not (no measured platform), A may miss nothing
        assertTrue(held.contains("tasks/a.f") || observed.get("tasks/a.f").misses() == 0, "A, at the top rank, meets: neither held to"
                + " its bound with the platform as measured nor without a miss: " + observed.get("tasks/a.f") + "; held: " + held);
    }

    /** The architect's code written into the generated packages (under src/) before they are built. */
    interface UserCode {
        void write(Path src) throws Exception;
    }

    /** Generates, builds, launches and checks one model; the launch's output. */
    static String run(Path model, String name, Path tmp, UserCode code) throws Exception {
        return run(model, name, tmp, code, false);
    }

    /**
     * As {@link #run(Path, String, Path, UserCode)}; with {@code force}, a model with errors (a deadline
     * the analysis says is missed) is generated anyway, as {@code rsaml generate --force} does.
     */
    static String run(Path model, String name, Path tmp, UserCode code, boolean force) throws Exception {
        return run(model, name, tmp, code, force, new java.util.TreeSet<>());
    }

    /** As {@link #run(Path, String, Path, UserCode, boolean)}, adding to {@code held} the releases it held to the analysis. */
    static String run(Path model, String name, Path tmp, UserCode code, boolean force, java.util.Set<String> held) throws Exception {
        Architecture arch = ModelLoader.load(model, name).architecture();
        String pkg = Names.snake(arch.getName());
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, force);
        code.write(src);
        ExecutionPlan plan = ExecutionPlan.of(arch);
        Map<Release, Long> periodsNs = new IdentityHashMap<>();
        plan.releases().forEach(r -> periodsNs.put(r, r.periodNs()));
        // The topics the model names, each under its name, but one renamed through its launch argument.
        Map<String, String> named = new TreeMap<>();
        StringBuilder remaps = new StringBuilder();
        String renamed = null;
        for (Connection c : arch.getConnections()) {
            String topic = RsamlTopics.sharedTopic(c.getSource());
            if (topic != null && !named.containsKey(topic)) {
                String as = named.isEmpty() ? "renamed/" + topic.replaceFirst("^/", "") : topic;
                named.put(topic, as.startsWith("/") ? as : "/" + as);
                if (!as.equals(topic)) {
                    renamed = topic;
                    remaps.append(' ').append(topic.replaceFirst("^/", "").replace('/', '_')).append("_topic:=").append(as);
                }
            }
        }
        String[] qos = null;
        if (name.equals(TUNED)) {
            Ros2ParamsTuning.tune(src.resolve(pkg), plan, periodsNs);
            assertNotNull(renamed, TUNED + " names no topic");
            qos = Ros2ParamsTuning.tuneQos(src.resolve(pkg), renamed);
        }
        Path install = Ros2Jazzy.colconBuild(src, tmp);

        // Launch, wait for every node, let it run, interrupt it.
        Map<String, String> nodes = Ros2Test.nodes(src);
        Path log = tmp.resolve("launch.log");
        int domain = 1 + (int) (ProcessHandle.current().pid() % 100);
        ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash(Ros2Jazzy.launch(pkg + " " + pkg + ".launch.py simulated_load:=" + LOAD + remaps), install))
                .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
        Ros2Jazzy.isolate(pb.environment(), domain);
        OtherRealtime.Watch watch = new OtherRealtime.Watch();
        PlatformCheck.Monitor monitor = PlatformCheck.Monitor.start();
        Process launch;
        try {
            launch = pb.start();
        } catch (java.io.IOException | RuntimeException e) {
            monitor.close();
            watch.stop();
            throw e;
        }
        OtherRealtime.Use others;
        PlatformCheck.Platform platform;
        String out = "";
        try {
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (true) {
                out = Files.readString(log, StandardCharsets.UTF_8);
                String o = out;
                if (nodes.values().stream().allMatch(n -> o.contains("Loaded node '/" + n + "'"))) {
                    break;
                }
                if (!launch.isAlive() || System.nanoTime() > until) {
                    fail("not every node of " + nodes.values() + " started within 120 s:\n" + Tools.last(out, 6000));
                }
                Thread.sleep(200);
            }
            for (Map.Entry<String, String> t : named.entrySet()) {
                String script = "export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST ROS_DOMAIN_ID=" + domain + "; ros2 topic info --no-daemon --spin-time 3 -v "
                        + t.getValue();
                // discovery on a loaded machine can take longer than one query's spin: asked up to three times
                String info = "";
                for (int attempt = 0; attempt < 3 && !info.matches("(?s).*Publisher count: [1-9].*Subscription count: [1-9].*"); attempt++) {
                    info = Tools.ok(tmp, 60, Ros2Jazzy.bash(script, install).toArray(String[]::new));
                }
                assertTrue(info.matches("(?s).*Publisher count: [1-9].*Subscription count: [1-9].*"), "the model's topic '" + t.getKey()
                        + "' is not " + t.getValue() + " with its publisher and subscribers (asked three times):\n" + info);
                if (qos != null && t.getKey().equals(renamed)) {
                    // the override written under the model's name reaches the topic under its new name
                    List<String> endpoints = new ArrayList<>();
                    for (String endpoint : info.split("Node name: ")) {
                        Matcher e = Pattern.compile("(?s).*Endpoint type: (\\w+).*Reliability: (\\w+).*").matcher(endpoint);
                        if (e.matches() && e.group(1).equals(qos[0])) {
                            endpoints.add(e.group(2));
                        }
                    }
                    assertTrue(!endpoints.isEmpty() && endpoints.stream().allMatch(qos[1]::equals), "the parameters file sets the " + qos[0]
                            + " reliability of topic '" + renamed + "' to " + qos[1] + ", but under its new name " + t.getValue()
                            + " it is " + endpoints + ":\n" + info);
                }
            }
            Thread.sleep(RUN_MS);
            Tools.ok(tmp, 10, "kill", "-INT", Long.toString(launch.pid()));
            if (!launch.waitFor(60, TimeUnit.SECONDS)) {
                fail("ros2 launch did not stop within 60 s of SIGINT:\n" + Tools.last(Files.readString(log, StandardCharsets.UTF_8), 6000));
            }
        } finally {
            // on a failure, the containers go too (they do not die with ros2 launch)
            launch.descendants().forEach(ProcessHandle::destroyForcibly);
            launch.destroyForcibly();
            try {
                platform = monitor.stop();
            } finally {
                monitor.close();
                others = watch.stop();
            }
        }
        out = Files.readString(log, StandardCharsets.UTF_8);
        String trace = out;
        assertEquals(0, launch.exitValue(), () -> "ros2 launch exited with " + launch.exitValue() + ":\n" + Tools.last(trace, 6000));
        int containers = (int) Pattern.compile("ComposableNodeContainer\\(").matcher(
                Files.readString(src.resolve(pkg + "/launch/" + pkg + ".launch.py"))).results().count();
        assertEquals(containers, Pattern.compile("process has finished cleanly").matcher(out).results().count(),
                () -> "not every container exited cleanly on SIGINT:\n" + Tools.last(trace, 6000));

        Map<String, JobSummary> observed = JobSummary.of(out);
        // Each release's thread where the launch placed its process (OneMachineCpus: without host:=, another host's core on a
        // CPU of its own), not on the model's core, as its cpu line says; a machine without that CPU says 'not available'.
        Map<String, Integer> placed = PlatformCheck.cpus(out);
        for (Release r : plan.releases()) {
            org.rsaml.model.Processor p = PlatformCheck.processorOf(arch, r.module().module());
            int cpu = org.rsaml.generator.internal.cxx.OneMachineCpus.cpu(p);
            if (cpu >= 0 && cpu < Runtime.getRuntime().availableProcessors()) {
                assertEquals(Integer.valueOf(cpu), placed.get(r.label()), r.label() + ": pinned where the launch placed its process (CPU " + cpu
                        + "), its cpu line: " + out.lines().filter(l -> l.contains("] cpu " + r.label() + " ")).toList());
            }
        }
        Map<String, double[]> ports = new TreeMap<>();
        Matcher m = PORT.matcher(out);
        while (m.find()) {
            ports.put(m.group(1), new double[] {Long.parseLong(m.group(2)), Double.parseDouble(m.group(3)), Double.parseDouble(m.group(4))});
        }

        // Every release at its modeled period: its jobs (the releases ROS 2's timer dropped counted among
        // them) on the grid for the whole run, each miss said on a line of its own.
        Map<String, Missed> missed = Missed.of(out);
        RunTrace.assertNoneDropped(name + " on ROS 2", out);
        StringBuilder report = new StringBuilder(name + ": observed on ROS 2 (simulated load " + LOAD + ")\n");
        for (PlannedModule pm : plan.modules()) {
            for (Release r : pm.releases()) {
                JobSummary o = observed.get(r.label());
                assertNotNull(o, "no summary of release " + r.label() + ":\n" + Tools.last(trace, 6000));
                double period = periodsNs.get(r) / 1e6;
                assertTrue(o.jobs() >= Math.max(2, (long) (RUN_MS * 0.8 / period)), r.label() + " ran " + o.jobs() + " jobs in a run of "
                        + RUN_MS + " ms, period " + period + " ms");
                assertEquals((o.jobs() - 1) * periodsNs.get(r), o.lastNs() - o.firstNs(), 10_000,
                        r.label() + ": " + o.jobs() + " jobs released from " + o.firstNs() + " to " + o.lastNs() + " ns, not every " + period + " ms");
                Missed x = missed.getOrDefault(r.label(), Missed.NONE);
                assertEquals(o.misses(), x.late() + x.dropped(), r.label() + ": a miss line per job past its deadline (" + x.late()
                        + ") and per release ROS 2's timer dropped (" + x.dropped() + "), as many as the summary's misses: " + o + "\n"
                        + trace.lines().filter(l -> l.contains(" " + r.label() + " ") && !l.contains("] miss ") && !l.contains("] over-bound "))
                                .collect(java.util.stream.Collectors.joining("\n")) + "\n" + Tools.last(trace, 3000));
                assertTrue(x.dropped() < o.jobs(), r.label() + ": every release dropped, none run: " + o);
            }
        }

        // Messages arrive at every connected entry port, at the rate its publisher is released, unless the
        // model sends the port's node, or the data threads of its processor, more than they can react to
        // (Ros2DataLoad): then a message waits behind reactions and the middleware keeps only the last few.
        Ros2DataLoad load = Ros2DataLoad.of(plan);
        for (Connection c : arch.getConnections()) {
            String port = c.getTarget().getModule().getLayer().getName() + "/" + c.getTarget().getModule().getName() + ":" + c.getTarget().getName();
            double[] p = ports.get(port);
            assertNotNull(p, "no message reached " + port + ":\n" + Tools.last(trace, 6000));
            PlannedModule source = plan.modules().stream().filter(x -> x.module() == c.getSource().getModule()).findFirst().orElseThrow();
            PlannedModule target = plan.modules().stream().filter(x -> x.module() == c.getTarget().getModule()).findFirst().orElseThrow();
            double rate = p[0] >= 3 ? (p[0] - 1) / (p[2] - p[1]) : 0;
            if (!source.reactive() && !source.releases().isEmpty() && p[0] >= 3 && load.takesEveryMessage(target)) {
                // a release ROS 2's timer dropped sent nothing: the publisher's rate is that of its releases that ran (the
                // dropped ones are judged above and in the contradictions below)
                double expected = source.releases().stream().mapToDouble(r -> {
                    JobSummary o = observed.get(r.label());
                    long dropped = missed.getOrDefault(r.label(), Missed.NONE).dropped();
                    return 1e6 / periodsNs.get(r) * (o.jobs() - dropped) / o.jobs();
                }).sum();
                assertEquals(expected, rate, expected * 0.15, port + " received " + (long) p[0] + " messages from " + p[1] + " to " + p[2]
                        + " ms: " + rate * 1000 + " a second, its publisher's releases that ran (those ROS 2's timer dropped sent nothing) "
                        + expected * 1000 + " a second (" + load.level(target) + ")");
            }
            report.append("  ").append(port).append(": ").append((long) p[0]).append(String.format(java.util.Locale.ROOT, " messages (%.1f a second)",
                    rate * 1000)).append(load.takesEveryMessage(target) ? "" : ", its rate not asserted: " + load.whyNot(target)).append('\n');
        }

        // Each node reports the analysis's bound of its releases. Where a release got the scheduling the
        // analysis assumes and other programs' real-time threads used at most OtherRealtime.TOLERATED_NS,
        // the run may not contradict the analysis (contradictions: a dropped release of a task that
        // meets its deadline, a response past the bound plus the platform's measured allowance).
        ArchitectureTiming timing = TimingAnalysis.analyse(arch);
        Map<String, Long> bounds = JobTimingTest.bounds(timing);
        Map<String, Verdict> verdicts = JobTimingTest.verdicts(timing);
        List<String> unchecked = new ArrayList<>();
        List<Release> checked = new ArrayList<>();
        for (Release r : plan.releases()) {
            JobSummary o = observed.get(r.label());
            long bound = bounds.getOrDefault(r.label(), -1L);
            assertEquals(bound < 0 ? "none" : JobTimingTest.ms(bound), o.bound(), r.label() + ": the analysis's bound, written into the node: " + o);
            assertEquals(r.deadlineNs(), o.deadlineNs(), 500, r.label() + ": the modeled deadline: " + o);
            assertEquals(r.costNs(), o.modeledNs(), 500, r.label() + ": the modeled execution time: " + o);
            Missed x = missed.getOrDefault(r.label(), Missed.NONE);
            report.append(String.format(java.util.Locale.ROOT,
                    "  %s: %d jobs (%d missed: %d past the deadline, %d releases dropped), worst response %s (execution %s, start latency %s,"
                            + " stall %s), bound %s, deadline %s, analysis: %s, %s%n",
                    r.label(), o.jobs(), o.misses(), x.late(), x.dropped(), JobTimingTest.ms(o.worstNs()), JobTimingTest.ms(o.executionNs()),
                    JobTimingTest.ms(o.latencyNs()), JobTimingTest.ms(o.stallNs()), o.bound(), JobTimingTest.ms(o.deadlineNs()), verdicts.get(r.label()), o.sched()));
            if (r.edf()) {
                report.append("  ").append(edfCase(r, o)).append('\n');
            }
            if (bound < 0) {
                continue;
            }
            if (PlatformCheck.scheduledAsAnalysed("Ros2LaunchTest " + name, r.label(), o, unchecked) && apart(arch, r.module().module(), r.label(), unchecked)) {
                checked.add(r);
            }
        }
        // The reactions are held to their bounds as the releases are, under the same rules: where their
        // node's data thread got the scheduling the analysis assumes (priority 0, SCHED_FIFO's lowest).
        List<Reaction> reacting = new ArrayList<>();
        for (Reaction x : plan.reactions()) {
            JobSummary o = observed.get(x.label());
            if (o == null || bounds.getOrDefault(x.label(), -1L) < 0) {
                continue;
            }
            if (PlatformCheck.scheduledAsAnalysed("Ros2LaunchTest " + name, x.label(), o, unchecked) && apart(arch, x.module().module(), x.label(), unchecked)) {
                reacting.add(x);
            }
        }
        if (!checked.isEmpty() || !reacting.isEmpty()) {
            PlatformCheck.BoundCheck check = PlatformCheck.boundCheck("Ros2LaunchTest " + name, others, platform, timing, observed,
                    PlatformCheck.tracedCpus(out), PlatformCheck.ros2BookkeepingNs(out));
            PlatformCheck.Allowance allowance = check.allowance();
            if (allowance == null) {
                checked.forEach(r -> unchecked.add(r.label() + " (" + check.notChecked() + ")"));
                checked.clear();
                reacting.forEach(x -> unchecked.add(x.label() + " (" + check.notChecked() + ")"));
                reacting.clear();
            } else {
                report.append("  measured: ").append(allowance).append(" (on ROS 2: ").append(JobTimingTest.ms(PlatformCheck.BOOKKEEPING_NS))
                        .append(" and the executor's own work for a job, stated ").append(JobTimingTest.ms(PlatformCheck.ROS2_EXECUTOR_NS))
                        .append(", the most a node measured in this run ").append(JobTimingTest.ms(PlatformCheck.ros2ExecutorWorstNs(out))).append(")\n");
                checked.removeIf(r -> PlatformCheck.uncheckedByMonitor("Ros2LaunchTest " + name, r.label(), allowance, unchecked));
                reacting.removeIf(x -> PlatformCheck.uncheckedByMonitor("Ros2LaunchTest " + name, x.label(), allowance, unchecked));
            }
            List<String> contradictions = contradictions(checked, verdicts, bounds, observed, missed, allowance, report);
            for (Reaction x : reacting) {
                JobSummary o = observed.get(x.label());
                if (!allowance.admits(x.label())) {
                    contradictions.add(x.label() + ": worst observed response of a reaction " + JobTimingTest.ms(o.worstNs()) + " (" + o.jobs()
                            + " jobs, " + o.sched() + ") exceeds its bound (" + verdicts.get(x.label()) + "): " + allowance.explain(x.label()));
                } else {
                    report.append("  ").append(x.label()).append(": worst observed response ").append(JobTimingTest.ms(o.worstNs()))
                            .append(" within its bound: ").append(allowance.explain(x.label())).append('\n');
                }
            }
            assertTrue(contradictions.isEmpty(), name + " on ROS 2 contradicts the timing analysis:\n  " + String.join("\n  ", contradictions)
                    + "\n" + report);
            report.append("  checked against the analysis: ").append(checked.stream().map(Release::label).toList()).append('\n');
            checked.forEach(r -> held.add(r.label()));
            report.append("  reactions checked against the bound: ").append(reacting.stream().map(Reaction::label).toList()).append('\n');
        }
        // Each node measures its reactions to data as the C++ program does: from the arrival that
        // starts one to its completion, against the modeled deadline and cost and the analysis's bound.
        for (PlannedModule pm : plan.modules()) {
            if (!pm.reactive()) {
                continue;
            }
            Reaction x = pm.reaction();
            JobSummary o = observed.get(x.label());
            assertNotNull(o, "no summary of the reactions " + x.label() + ":\n" + Tools.last(trace, 6000));
            long bound = bounds.getOrDefault(x.label(), -1L);
            assertEquals(bound < 0 ? "none" : JobTimingTest.ms(bound), o.bound(), x.label() + ": the analysis's bound, written into the node: " + o);
            assertEquals(x.deadlineNs(), o.deadlineNs(), 500, x.label() + ": the modeled deadline: " + o);
            assertEquals(x.costNs(), o.modeledNs(), 500, x.label() + ": the modeled execution time: " + o);
            boolean fed = pm.inputs().stream().anyMatch(p -> ports.containsKey(pm.qualifiedName() + ":" + p.name()));
            assertTrue(!fed || o.jobs() > 0, x.label() + ": messages arrived but no reaction was measured: " + o);
            report.append(String.format(java.util.Locale.ROOT, "  %s: %d jobs, worst response %s (execution %s, start latency %s, stall %s), bound %s, %s%n",
                    x.label(), o.jobs(), JobTimingTest.ms(o.worstNs()), JobTimingTest.ms(o.executionNs()), JobTimingTest.ms(o.latencyNs()),
                    JobTimingTest.ms(o.stallNs()), o.bound(), o.sched()));
        }
        if (!unchecked.isEmpty()) {
            report.append("  not checked against the bound (the response times are reported only): ").append(unchecked).append('\n');
        }

        // On one core, the long low-priority planning job no longer delays the short safety stop.
        if (name.endsWith("ros2-preemption.rsaml")) {
            JobSummary plan150 = observed.get("planning/globalPlanner.plan");
            JobSummary stop = observed.get("safety/safetyStop.check");
            assertTrue(plan150.executionNs() >= 150_000_000 * LOAD * 0.9, "the planning job did not run long: " + plan150);
            if (stop.asAnalysed() && others.tolerated()) { // (else said above)
                assertTrue(stop.worstNs() < 20_000_000, "the safety stop waited for the planner: " + stop + "\n" + report);
            }
        }
        // A boolean trigger asserts its link only with true: the overseer sends false every 100 ms
        // (as generated), so the inhibitor never blocks the producer, whose every message arrives.
        if (name.endsWith("inhibitor-window.rsaml")) {
            // (about a third of them would be blocked if any message asserted it: 30 ms of every 100)
            double[] sink = ports.get("low/sink:in");
            long sent = 1 + Math.round((sink[2] - sink[1]) / 10.0);
            assertTrue(observed.get("high/overseer.watch").jobs() >= 10, "the overseer hardly ran: " + observed.get("high/overseer.watch"));
            assertTrue(sink[0] >= 0.95 * sent, "the sink received " + (long) sink[0] + " messages from " + sink[1] + " to " + sink[2]
                    + " ms, the producer sent about " + sent + " every 10 ms: false on the overseer's boolean trigger must not inhibit them\n" + report);
        }
        System.out.print(report);
        return out;
    }

    /**
     * Whether the threads of {@code module} have a CPU to themselves on this machine as the launch places them
     * ({@link PlatformCheck#notApart}); where not, {@code label} is noted in {@code unchecked} with the reason: its bound
     * is not the analysis's claim there, and it is reported, not held.
     */
    static boolean apart(Architecture arch, org.rsaml.model.Module module, String label, List<String> unchecked) {
        String why = PlatformCheck.notApart(arch, module, PlatformCheck.Placement.ROS2);
        if (why != null) {
            unchecked.add(label + " (" + why + ")");
        }
        return why == null;
    }

    /**
     * A release's misses as its node said them: jobs completed past the deadline, and releases ROS 2's timer dropped,
     * with the late calls that made it drop them ({@code lateCalls}: each the release before them and when the timer
     * called it, on CLOCK_MONOTONIC).
     */
    record Missed(long late, long dropped, List<long[]> lateCalls) {
        static final Missed NONE = new Missed(0, 0, List.of());
        /** "miss <label> released 130.298 ms response 12.001 ms ..." or "miss <label> released 130.298..150.298 ms not run (3 releases) ...". */
        private static final Pattern LINE = Pattern.compile("\\] miss (\\S+) released [0-9.]+(?:\\.\\.[0-9.]+)? ms (?:response |not run \\((\\d+) releases?\\)"
                + "(?:.*? late \\(on CLOCK_MONOTONIC: released (\\d+) ns, called (\\d+) ns\\))?)");

        /** Per release label, from the launch's output. */
        static Map<String, Missed> of(String out) {
            Map<String, Missed> all = new TreeMap<>();
            Matcher m = LINE.matcher(out);
            while (m.find()) {
                long dropped = m.group(2) == null ? 0 : Long.parseLong(m.group(2));
                List<long[]> calls = m.group(3) == null ? List.of() : List.of(new long[] {Long.parseLong(m.group(3)), Long.parseLong(m.group(4))});
                all.merge(m.group(1), new Missed(dropped == 0 ? 1 : 0, dropped, calls), (a, b) -> new Missed(a.late + b.late, a.dropped + b.dropped,
                        java.util.stream.Stream.concat(a.lateCalls.stream(), b.lateCalls.stream()).toList()));
            }
            return all;
        }
    }

    /**
     * What a run shows against the timing analysis, for the releases scheduled as analysed in a run whose
     * allowance is known: one message per contradiction, naming the release, what was observed and what
     * the analysis says. A release ROS 2's timer dropped is a job that never ran: of a task the analysis
     * says meets its deadline, none may be dropped unless the late call that made the timer drop it is the
     * platform's ({@link #dropped}). No worst
     * observed response may exceed its bound computed again with the platform's loss as the monitor
     * measured it ({@link PlatformCheck.Allowance#of}; a job past its deadline by more than that is such a
     * response). Jobs past the deadline that stay within it (the bound close to the deadline, as EDF's is)
     * are the platform's part of the response the analysis does not count: written to {@code report}, not a
     * contradiction.
     */
    static List<String> contradictions(List<Release> checked, Map<String, Verdict> verdicts, Map<String, Long> bounds,
            Map<String, JobSummary> observed, Map<String, Missed> missed, PlatformCheck.Allowance allowance, StringBuilder report) {
        List<String> found = new ArrayList<>();
        for (Release r : checked) {
            JobSummary o = observed.get(r.label());
            Missed x = missed.getOrDefault(r.label(), Missed.NONE);
            long bound = bounds.get(r.label());
            Verdict verdict = verdicts.get(r.label());
            if (verdict == Verdict.MEETS && x.dropped() > 0) {
                dropped(r.label(), o, x, bound, allowance, found, report);
            }
            if (!allowance.admits(r.label())) {
                found.add(r.label() + ": worst observed response " + JobTimingTest.ms(o.worstNs()) + " exceeds its bound (" + verdict + "): "
                        + allowance.explain(r.label()));
            } else if (x.late() == 0) {
                report.append("  ").append(r.label()).append(": worst observed response ").append(JobTimingTest.ms(o.worstNs()))
                        .append(" within its bound: ").append(allowance.explain(r.label())).append('\n');
            } else {
                report.append("  ").append(r.label()).append(": ").append(x.late()).append(" jobs past the deadline ")
                        .append(JobTimingTest.ms(o.deadlineNs())).append(", the worst at ").append(JobTimingTest.ms(o.worstNs()))
                        .append(", within its bound with the platform as measured (").append(verdict).append("): ")
                        .append(allowance.explain(r.label())).append('\n');
            }
        }
        return found;
    }

    /**
     * The releases of {@code label}, a task the analysis says meets its deadline, that ROS 2's timer dropped: jobs that never
     * ran. The timer drops the releases due while it calls a release a period or more late, so each drop is judged by that
     * late call: the call's latency (from the release to the call, before the job even began) may not exceed the task's
     * bound with the platform's loss in the job's window, as a job's response may not ({@link PlatformCheck.TaskCheck#at}).
     * A late call within it is the platform's (written to {@code report}); past it, or where the run's bounds are not
     * checked against the platform, a contradiction.
     */
    static void dropped(String label, JobSummary o, Missed x, long bound, PlatformCheck.Allowance allowance, List<String> found,
            StringBuilder report) {
        String said = label + ": " + x.dropped() + " of its " + o.jobs() + " releases dropped by ROS 2's timer (never run, each a missed"
                + " deadline), though the analysis says it meets its deadline " + JobTimingTest.ms(o.deadlineNs()) + " (bound " + JobTimingTest.ms(bound) + ")";
        String unchecked = allowance.unchecked(label);
        if (unchecked != null) {
            found.add(said + "; not held to the platform's loss: " + unchecked);
            return;
        }
        if (x.lateCalls().isEmpty()) {
            found.add(said + "; the node did not say when the release before them was called (no \"on CLOCK_MONOTONIC\" on its miss lines)");
            return;
        }
        for (long[] call : x.lateCalls()) {
            PlatformCheck.JobCheck late = allowance.at(label, call[0], call[1]);
            String how = "the release before them called late: " + lateCall(late, allowance);
            if (late.contradicts()) {
                found.add(said + "; " + how);
                return;
            }
        }
        PlatformCheck.JobCheck latest = x.lateCalls().stream().map(c -> allowance.at(label, c[0], c[1]))
                .max(java.util.Comparator.comparingLong(PlatformCheck.JobCheck::responseNs)).orElseThrow();
        report.append("  ").append(label).append(": ").append(x.dropped()).append(" releases dropped by ROS 2's timer after ")
                .append(x.lateCalls().size()).append(" late calls, each within the bound with the platform as measured; the latest: ")
                .append(lateCall(latest, allowance)).append('\n');
    }

    /** A late call held to the task's bound, said as a call: its latency from the release where a job's check says its response. */
    private static String lateCall(PlatformCheck.JobCheck call, PlatformCheck.Allowance allowance) {
        return call.describe(allowance.platform().fromNs()).replaceFirst(", response ", ", called after ");
    }

    /**
     * Which case an EDF processor's release saw, checked: SCHED_DEADLINE in force with the modeled
     * runtime, deadline and period as the kernel reports them back (sched_getattr), or the kernel's
     * refusal and the fallback, said by the node.
     */
    static String edfCase(Release r, JobSummary o) {
        String modeled = "SCHED_DEADLINE runtime " + JobTimingTest.ms(r.costNs()) + " deadline " + JobTimingTest.ms(r.deadlineNs()) + " period "
                + JobTimingTest.ms(r.periodNs());
        if (o.sched().startsWith("SCHED_DEADLINE")) {
            assertTrue(o.sched().startsWith(modeled) && o.sched().matches(".*\\(kernel: " + Pattern.quote(modeled) + "( reclaim)?\\)"), r.label()
                    + ": SCHED_DEADLINE with the modeled runtime, deadline and period, as the kernel reports them: " + o.sched());
            assertTrue(o.sched().contains(", its periods from its first release (asked "), r.label()
                    + ": a deadline thread from its first release, released by the kernel's periods: " + o.sched());
            return "EDF " + r.label() + ": SCHED_DEADLINE in force (kernel: " + modeled.substring("SCHED_DEADLINE ".length())
                    + ")";
        }
        assertTrue(o.sched().matches("(SCHED_FIFO rank \\d+|default) instead of EDF: .+"), r.label()
                + ": without SCHED_DEADLINE, the refusal and the fallback: " + o.sched());
        return "EDF " + r.label() + ": SCHED_DEADLINE refused (" + o.sched().replaceFirst("^.* instead of EDF: ", "") + "), fallback "
                + o.sched().replaceFirst(" instead of EDF: .*", "") + ": EDF's bound does not apply";
    }
}
