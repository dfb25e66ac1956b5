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
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.ExecutionPlan.PlannedModule;
import org.rsaml.analysis.plan.ExecutionPlan.Release;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.Names;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.validation.ModelLoader;

/**
 * The generated ROS 2 packages on a real ROS 2 (see {@link Ros2Jazzy}): built with colcon, started
 * with {@code ros2 launch} on the loopback in a domain of their own, every job busy-working
 * {@link #LOAD} of its modeled execution time. Every node starts; every timed release runs at its
 * modeled period, with no job skipped (judged by the nodes' own release times); messages arrive
 * at every connected entry port at the rate their publisher is released; where the system grants
 * real-time priorities, each release's worst observed response (release to completion, measured
 * by the node) is within the timing analysis's bound, allowing only the platform's release latency
 * the analysis does not count (the worst delay before the processor's highest-priority release
 * was called, measured too); and everything exits cleanly on SIGINT. By default a representative
 * set: an example with two processors, a message type of its own and connections, and a model
 * where a long low-priority job must not delay a short high-priority one on the same core;
 * {@code -Drsaml.ros2.examples=all} runs every example without errors as well.
 */
class Ros2LaunchTest {

    /** The share of its modeled execution time each job busy-works (the rest is ROS 2's dispatch and publishing). */
    static final double LOAD = 0.8;
    /** How long the system runs once every node is up. */
    static final long RUN_MS = 5000;

    static List<String> models() throws Exception {
        List<String> models = new ArrayList<>(List.of("mobile-base-latency.rsaml", "resources/ros2-preemption.rsaml", "resources/inhibitor-window.rsaml"));
        if ("all".equals(System.getProperty("rsaml.ros2.examples"))) {
            for (String e : Tools.cleanExamples()) {
                if (!models.contains(e)) {
                    models.add(e);
                }
            }
        }
        return models;
    }

    private static final Pattern RELEASE = Pattern.compile("summary (\\S+) jobs (\\d+) released ([\\d.]+)\\.\\.([\\d.]+) ms worst-response ([\\d.]+) ms"
            + " worst-execution ([\\d.]+) ms worst-latency ([\\d.]+) ms");
    private static final Pattern PORT = Pattern.compile("summary (\\S+) messages (\\d+) received ([\\d.]+)\\.\\.([\\d.]+) ms");

    record Observed(long jobs, double first, double last, double response, double execution, double latency) {
    }

    @ParameterizedTest
    @MethodSource("models")
    void buildsStartsAndRunsAsAnalysed(String name, @TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Path model = Ros2Test.model(name);
        Architecture arch = ModelLoader.load(model, name).architecture();
        String pkg = Names.snake(arch.getName());
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        Path install = Ros2Jazzy.colconBuild(src, tmp);

        // Launch, wait for every node, let it run, interrupt it.
        Map<String, String> nodes = Ros2Test.nodes(src.resolve(pkg));
        Path log = tmp.resolve("launch.log");
        int domain = 1 + (int) (ProcessHandle.current().pid() % 100);
        ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash("exec ros2 launch " + pkg + " " + pkg + ".launch.py simulated_load:=" + LOAD, install))
                .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
        Ros2Jazzy.isolate(pb.environment(), domain);
        Process launch = pb.start();
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
            Thread.sleep(RUN_MS);
            Tools.ok(tmp, 10, "kill", "-INT", Long.toString(launch.pid()));
            assertTrue(launch.waitFor(60, TimeUnit.SECONDS), "ros2 launch did not stop within 60 s of SIGINT");
        } finally {
            launch.destroyForcibly();
        }
        out = Files.readString(log, StandardCharsets.UTF_8);
        String trace = out;
        assertEquals(0, launch.exitValue(), () -> "ros2 launch exited with " + launch.exitValue() + ":\n" + Tools.last(trace, 6000));
        int containers = (int) Pattern.compile("ComposableNodeContainer\\(").matcher(
                Files.readString(src.resolve(pkg + "/launch/" + pkg + ".launch.py"))).results().count();
        assertEquals(containers, Pattern.compile("process has finished cleanly").matcher(out).results().count(),
                () -> "not every container exited cleanly on SIGINT:\n" + Tools.last(trace, 6000));

        Map<String, Observed> observed = new TreeMap<>();
        Matcher m = RELEASE.matcher(out);
        while (m.find()) {
            observed.put(m.group(1), new Observed(Long.parseLong(m.group(2)), Double.parseDouble(m.group(3)), Double.parseDouble(m.group(4)),
                    Double.parseDouble(m.group(5)), Double.parseDouble(m.group(6)), Double.parseDouble(m.group(7))));
        }
        Map<String, double[]> ports = new TreeMap<>();
        m = PORT.matcher(out);
        while (m.find()) {
            ports.put(m.group(1), new double[] {Long.parseLong(m.group(2)), Double.parseDouble(m.group(3)), Double.parseDouble(m.group(4))});
        }

        // Every release at its modeled period: releases on the grid, none skipped, for the whole run.
        ExecutionPlan plan = ExecutionPlan.of(arch);
        StringBuilder report = new StringBuilder(name + ": observed on ROS 2 (simulated load " + LOAD + ")\n");
        for (PlannedModule pm : plan.modules()) {
            for (Release r : pm.releases()) {
                Observed o = observed.get(r.label());
                assertNotNull(o, "no summary of release " + r.label() + ":\n" + Tools.last(trace, 6000));
                double period = r.periodNs() / 1e6;
                assertTrue(o.jobs() >= Math.max(2, (long) (RUN_MS * 0.8 / period)), r.label() + " ran " + o.jobs() + " jobs in a run of "
                        + RUN_MS + " ms, period " + period + " ms");
                assertEquals((o.jobs() - 1) * period, o.last() - o.first(), 0.01,
                        r.label() + ": " + o.jobs() + " jobs released from " + o.first() + " to " + o.last() + " ms, not every " + period + " ms");
            }
        }

        // Messages arrive at every connected entry port, at the rate its publisher is released.
        for (Connection c : arch.getConnections()) {
            String port = c.getTarget().getModule().getLayer().getName() + "/" + c.getTarget().getModule().getName() + ":" + c.getTarget().getName();
            double[] p = ports.get(port);
            assertNotNull(p, "no message reached " + port + ":\n" + Tools.last(trace, 6000));
            PlannedModule source = plan.modules().stream().filter(x -> x.module() == c.getSource().getModule()).findFirst().orElseThrow();
            if (!source.reactive() && !source.releases().isEmpty() && p[0] >= 3) {
                double expected = source.releases().stream().mapToDouble(r -> 1e6 / r.periodNs()).sum();
                double rate = (p[0] - 1) / (p[2] - p[1]);
                assertEquals(expected, rate, expected * 0.15, port + " received " + (long) p[0] + " messages from " + p[1] + " to " + p[2]
                        + " ms: " + rate * 1000 + " a second, its publisher is released " + expected * 1000 + " times a second");
            }
            report.append("  ").append(port).append(": ").append((long) p[0]).append(" messages\n");
        }

        // Observed response times within the analysis's bounds, where real-time priorities are granted.
        boolean realtime = !out.contains(" default: real-time priority not permitted");
        ArchitectureTiming timing = TimingAnalysis.analyse(arch);
        for (ProcessorTiming pt : timing.processors()) {
            int top = pt.result().tasks().stream().mapToInt(t -> t.task().priority()).max().orElse(0);
            double allowance = pt.result().tasks().stream().filter(t -> t.task().priority() == top && observed.containsKey(t.task().name()))
                    .mapToDouble(t -> observed.get(t.task().name()).latency()).min().orElse(0);
            for (TaskResult t : pt.result().tasks()) {
                Observed o = observed.get(t.task().name());
                if (o == null) {
                    continue;
                }
                String bound = t.responseTime().isPresent() ? t.responseTime().getAsLong() / 1e6 + " ms" : "none (" + t.verdict() + ")";
                report.append(String.format("  %s: %d jobs, worst response %.3f ms (execution %.3f, release latency %.3f), analysed bound %s%n",
                        t.task().name(), o.jobs(), o.response(), o.execution(), o.latency(), bound));
                if (realtime && t.responseTime().isPresent()) {
                    double b = t.responseTime().getAsLong() / 1e6;
                    assertTrue(o.response() <= b + allowance, t.task().name() + ": worst observed response " + o.response()
                            + " ms exceeds the analysed bound " + b + " ms plus the platform's release latency " + allowance + " ms\n" + report);
                }
            }
            report.append("  processor ").append(pt.name()).append(": platform release latency ").append(allowance).append(" ms\n");
        }
        if (!realtime) {
            report.append("  real-time priorities are not permitted here: the response times are reported, not checked against the bounds\n");
        }

        // On one core, the long low-priority planning job no longer delays the short safety stop.
        if (name.endsWith("ros2-preemption.rsaml")) {
            Observed plan150 = observed.get("planning/globalPlanner.plan");
            Observed stop = observed.get("safety/safetyStop.check");
            assertTrue(plan150.execution() >= 150 * LOAD * 0.9, "the planning job did not run long: " + plan150);
            if (realtime) {
                assertTrue(stop.response() < 20, "the safety stop waited for the planner: worst response " + stop.response() + " ms\n" + report);
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
    }
}
