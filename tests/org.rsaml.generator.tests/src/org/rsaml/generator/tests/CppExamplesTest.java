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
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Processor;
import org.rsaml.model.RealTimeElement;
import org.rsaml.validation.ModelLoader;

/**
 * Every example that validates without errors becomes a C++ project that builds (warnings as
 * errors), runs for a bounded time, releases every periodic function and action about as often
 * as its period says, and carries data along every modeled connection. Expectations come from the
 * model, not from the generator.
 */
class CppExamplesTest {

    static final long RUN_MS = 600;

    static List<String> examples() throws Exception {
        return Tools.cleanExamples();
    }

    @ParameterizedTest
    @MethodSource("examples")
    void generatedProjectBuildsAndRunsAsModeled(String example, @TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("project");
        GenerationResult result = new RsamlGenerator().generate(Tools.example(example), Target.CPP, out, false);
        assertTrue(result.warnings().isEmpty(), () -> "warnings: " + result.warnings());

        Path exe = Tools.cmakeBuild(out, executableName(out));
        RunTrace trace = new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", Long.toString(RUN_MS)));
        long ranMs = trace.durationMs();
        assertTrue(ranMs >= RUN_MS && ranMs < RUN_MS + 5000, "ran for " + ranMs + " ms");

        Architecture arch = ModelLoader.load(Tools.example(example), example).architecture();
        int periodicActions = 0;
        for (Layer layer : arch.getLayers()) {
            for (Module module : layer.getModules()) {
                for (Function f : module.getFunctions()) {
                    String fn = layer.getName() + "/" + module.getName() + "." + f.getName();
                    if (periodic(f)) {
                        assertPlausible(trace, "release " + fn, nanos(f, f.getPeriod()), 0, ranMs);
                        assertActionsInOrder(trace, f, fn);
                    }
                    for (Action a : f.getActions()) {
                        if (periodic(a)) {
                            periodicActions++;
                            long period = nanos(a, a.getPeriod());
                            assertPlausible(trace, "action " + fn + "." + a.getName(), period, nanos(a, a.getStartDate()) % period, ranMs);
                        }
                    }
                }
            }
        }
        assertTrue(periodicActions > 0 || trace.matching("release ").size() > 0 || arch.getConnections().size() > 0, "the example's program releases something to trace");
        assertPinnedAsDeployed(arch, trace);
        assertPlacedBeforeFirstJob(trace);

        for (Connection c : arch.getConnections()) {
            String source = name(c.getSource());
            String target = name(c.getTarget());
            List<Long> received = trace.received(target, source, false);
            assertFalse(received.isEmpty(), "no data flowed from " + source + " to " + target + ":\n" + Tools.last(trace.output, 4000));
            assertTrue(received.size() <= trace.sends(source), "more received at " + target + " than " + source + " sent");
        }
    }

    /**
     * Every module of a processor with a core runs its threads there: the runtime pins the module's
     * worker and each of its releases (one 'sched' line each) and traces it, or says the machine
     * lacks that core; the threads of other modules are left to the operating system.
     */
    static void assertPinnedAsDeployed(Architecture arch, RunTrace trace) {
        int cores = Runtime.getRuntime().availableProcessors();
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                String module = layer.getName() + "/" + m.getName();
                Processor p = arch.getProcessors().stream().filter(q -> q.getModules().contains(m)).findFirst().orElse(null);
                List<String> pinned = threadsOf(trace, "cpu ", module);
                if (p == null || p.getCore() < 0) {
                    assertTrue(pinned.isEmpty(), module + " is left to the OS: " + pinned);
                    continue;
                }
                String where = " core " + p.getCore() + (p.getCore() < cores ? "" : " not available: default");
                int threads = threadsOf(trace, "sched ", module).size(); // the worker's and each release's
                assertEquals(threads, pinned.size(), () -> module + ": a line per thread (worker and releases) expected, got "
                        + pinned + "\n" + Tools.last(trace.output, 2000));
                assertTrue(pinned.stream().allMatch(l -> l.endsWith(where)), () -> module + " on" + where + ": " + pinned);
            }
        }
    }

    /**
     * A release thread gets its core and its priority before its first job, so that no job runs at
     * a priority the analysis does not assume: every release's 'sched' line (and 'cpu' line, when
     * placed) comes before its first 'release' line.
     */
    static void assertPlacedBeforeFirstJob(RunTrace trace) {
        List<String> sched = trace.matching("sched ");
        assertFalse(sched.isEmpty(), "no release thread was started:\n" + Tools.last(trace.output, 2000));
        for (String line : sched) {
            String label = line.substring("sched ".length()).replaceFirst(" (SCHED_FIFO|SCHED_RR|SCHED_DEADLINE|default).*$", "");
            int placed = trace.lines.indexOf(line);
            int first = trace.lines.indexOf("release " + label);
            assertTrue(first < 0 || first > placed, "release " + label + " ran before its thread had its priority:\n"
                    + String.join("\n", trace.lines.subList(0, Math.min(trace.lines.size(), placed + 3))));
        }
    }

    @Test
    void aModuleNoProcessorNamesStaysOffTheClaimedCores(@TempDir Path tmp) throws Exception {
        RunTrace trace = runVariant(tmp, "one-unallocated", " //@layers[name='navigation']/@modules[name='pathPlanner']", "", 200);
        // cores 0 and 1 are the processors'; the planner gets the others, or says there are none
        List<String> planned = threadsOf(trace, "cpu ", "navigation/pathPlanner");
        assertEquals(threadsOf(trace, "sched ", "navigation/pathPlanner").size(), planned.size(), trace.output);
        for (String line : planned) {
            Matcher m = Pattern.compile("cpu navigation/pathPlanner(?:\\.\\w+)? (?:cores ([0-9,-]+) unclaimed|no unclaimed core: default)").matcher(line);
            assertTrue(m.matches(), line);
            if (m.group(1) != null) {
                for (String range : m.group(1).split(",")) {
                    int low = Integer.parseInt(range.split("-")[0]);
                    assertTrue(low >= 2, "a claimed core in " + line);
                }
            } else {
                assertTrue(Runtime.getRuntime().availableProcessors() <= 2, "cores left unused: " + line);
            }
        }
        List<String> detector = threadsOf(trace, "cpu ", "navigation/obstacleDetector");
        assertFalse(detector.isEmpty(), trace.output);
        assertTrue(detector.stream().allMatch(l -> l.matches(".* core 1( not available: default)?")), detector::toString);
    }

    /**
     * An EDF processor without a core beside processors with cores (docs/timing.md, "EDF beside processors with cores"):
     * its threads are kept to the cores no processor claims, as every module's without a core, so the processors' cores
     * stay theirs; there the kernel, its deadline admission control on as by default, refuses its releases SCHED_DEADLINE
     * (it admits a deadline thread only on every CPU of its root domain), and they run at their ranks, saying 'instead of
     * EDF'; with it off (sched_rt_runtime_us -1) it grants them, and they say so (still off core 0). mobile-base-latency
     * with its navigation processor made EDF and given no core, beside the control processor on core 0.
     */
    @Test
    void anEdfProcessorWithoutACoreBesideACoreStaysOffItAndSaysItRunsInsteadOfEdf(@TempDir Path tmp) throws Exception {
        Assumptions.assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "one CPU: no core left beside core 0");
        RunTrace trace = runVariant(tmp, "edf-coreless", "description=\"CPU core 1: navigation.\" core=\"1\"",
                "description=\"Navigation, EDF on no core.\" schedPolicy=\"EDF\"", 300);
        for (String module : List.of("navigation/obstacleDetector", "navigation/pathPlanner")) {
            List<String> placed = threadsOf(trace, "cpu ", module);
            assertFalse(placed.isEmpty(), trace.output);
            assertTrue(placed.stream().allMatch(l -> l.matches("cpu " + module + "(\\.\\w+)? cores [0-9,-]+ unclaimed") && !l.matches(".* cores (0|0-.*|0,.*) .*")),
                    "the EDF processor's threads off core 0: " + placed);
        }
        List<String> releases = trace.matching("sched navigation/pathPlanner.plan");
        assertEquals(1, releases.size(), trace.output);
        boolean admission = !Files.readString(Path.of("/proc/sys/kernel/sched_rt_runtime_us")).strip().equals("-1");
        assertTrue(releases.get(0).matches(admission ? "sched navigation/pathPlanner\\.plan (SCHED_FIFO rank \\d+|default) instead of EDF: .+"
                : "sched navigation/pathPlanner\\.plan (SCHED_DEADLINE .+|(SCHED_FIFO rank \\d+|default) instead of EDF: .+)"),
                "refused SCHED_DEADLINE on the cores left (deadline admission control " + (admission ? "on" : "off") + "), it says it runs at"
                        + " its rank instead: " + releases.get(0));
        assertEquals(List.of("cpu control/velocityController core 0"), trace.matching("cpu control/velocityController core"),
                "the controller keeps core 0");
    }

    /** mobile-base-latency with {@code from} replaced by {@code to}, generated, built and run for {@code ms}: its trace. */
    private static RunTrace runVariant(Path tmp, String name, String from, String to, int ms) throws Exception {
        Path model = tmp.resolve(name + ".rsaml");
        String text = Files.readString(Tools.example("mobile-base-latency.rsaml"));
        assertTrue(text.contains(from), "the example has " + from);
        Files.writeString(model, text.replace(from, to));
        Path out = tmp.resolve("project");
        new RsamlGenerator().generate(model, Target.CPP, out, false);
        Path exe = Tools.cmakeBuild(out, executableName(out));
        return new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", Integer.toString(ms)));
    }

    /** The trace lines of a kind ('cpu ', 'sched ') about a module's threads: its worker's and its releases'. */
    private static List<String> threadsOf(RunTrace trace, String kind, String module) {
        return trace.matching(kind + module).stream()
                .filter(l -> l.startsWith(kind + module + " ") || l.startsWith(kind + module + ".")).toList();
    }

    @Test
    void aCoreTheMachineLacksLeavesTheModuleToTheOs(@TempDir Path tmp) throws Exception {
        Path model = tmp.resolve("far-core.rsaml");
        String text = Files.readString(Tools.example("mobile-base-latency.rsaml"));
        assertTrue(text.contains("core=\"1\""), "the example pins a processor to core 1");
        Files.writeString(model, text.replace("core=\"1\"", "core=\"4096\""));
        Path out = tmp.resolve("project");
        new RsamlGenerator().generate(model, Target.CPP, out, false);
        Path exe = Tools.cmakeBuild(out, executableName(out));
        RunTrace trace = new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", "200"));
        List<String> far = trace.matching("cpu navigation/obstacleDetector");
        assertTrue(far.size() >= 2, "the worker and the release:\n" + trace.output);
        assertTrue(far.stream().allMatch(l -> l.endsWith(" core 4096 not available: default")), far::toString);
        assertEquals(List.of("cpu control/velocityController core 0"), trace.matching("cpu control/velocityController core"), "the controller on an available core stays pinned there");
        assertFalse(trace.matching("release control/velocityController").isEmpty(), "the run went on:\n" + trace.output);
    }

    /** Releases happen at offset + k * period: over the run, about that many, at least one. */
    static void assertPlausible(RunTrace trace, String line, long periodNs, long offsetNs, long ranMs) {
        long expected = (ranMs * 1_000_000 - offsetNs) / periodNs + 1;
        long actual = trace.count(line);
        assertTrue(actual >= Math.max(1, expected / 2) && actual <= expected + 1,
                "'" + line + "' " + actual + " times in " + ranMs + " ms, expected about " + expected);
    }

    /** The actions of a periodic function run in their modeled order at each release. */
    static void assertActionsInOrder(RunTrace trace, Function f, String fn) {
        List<String> inline = new ArrayList<>();
        for (Action a : f.getActions()) {
            if (!periodic(a) || nanos(a, a.getPeriod()) == nanos(f, f.getPeriod())) {
                inline.add("action " + fn + "." + a.getName());
            }
        }
        List<String> seen = trace.matching("action " + fn + ".").stream().filter(inline::contains).toList();
        for (int i = 0; i < seen.size(); i++) {
            assertEquals(inline.get(i % inline.size()), seen.get(i), "action " + (i + 1) + " of " + fn + " out of order");
        }
    }

    static boolean periodic(RealTimeElement e) {
        return e.getExecType() == ExecutionType.PERIODIC && e.getPeriod() > 0;
    }

    static long nanos(RealTimeElement e, double value) {
        return Math.round(value * e.getTimeUnit().getValue());
    }

    static String name(org.rsaml.model.Port p) {
        return p.getModule().getLayer().getName() + "/" + p.getModule().getName() + "." + p.getName();
    }

    static String executableName(Path project) throws Exception {
        Matcher m = Pattern.compile("set\\(RSAML_TARGET (\\w+)\\)").matcher(Files.readString(project.resolve("CMakeLists.txt")));
        assertTrue(m.find(), "CMakeLists.txt names no target");
        return m.group(1);
    }
}
