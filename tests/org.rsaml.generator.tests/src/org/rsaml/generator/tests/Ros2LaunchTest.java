/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.math.BigDecimal;
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
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.analysis.TimingAnalysis;
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
 * grants real-time priorities, each release's worst observed response (release to completion,
 * measured by the node on its clock) is within that bound plus the platform's allowance for what the
 * analysis does not count on ROS 2, measured at test time ({@link PlatformCheck}: the worst start
 * latency of the run's releases that nothing in the model delays, or a calibration run, plus a stated
 * constant for the bookkeeping; the check says which), unless other programs' real-time threads ran
 * beyond a tolerance ({@link OtherRealtime}: said, naming them; a failure under {@code RSAML_TIMING_BOUNDS=required}, as in CI); the topics the model
 * names exist under those names with their publisher and subscribers (one of them renamed through
 * its launch argument, its QoS set by the model's name in the parameters file and in effect under
 * the new name); an invalid parameters file is refused with its line; managed nodes reach active with either launch file
 * ({@link #bothLaunchFilesBringTheManagedNodesToActive}); and everything exits cleanly on SIGINT. By default a representative set: an example with two processors, a message
 * type of its own and connections, a model where a long low-priority job must not delay a short
 * high-priority one on the same core, an inhibitor, two EDF processors (one pinned to a core, one not: each
 * release under SCHED_DEADLINE with the kernel's runtime, deadline and period, or the kernel's refusal and the
 * fallback, and the test says which it saw), and one seeded random task set (two processors of rate-monotonic
 * tasks, as {@link JobTimingTest} runs on the C++ runtime); {@code -Drsaml.ros2.examples=all} runs every example
 * without errors as well,
 * {@code -Drsaml.ros2.examples=mobile-base-latency.rsaml,resources/inhibitor-window.rsaml} only
 * those, and {@code -Drsaml.ros2.seeds=1,2,3} other random sets.
 */
class Ros2LaunchTest {

    /** The share of its modeled execution time each job busy-works (the rest is ROS 2's dispatch and publishing). */
    static final double LOAD = 0.8;
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
                "resources/ros2-edf.rsaml"));
        if ("all".equals(chosen)) {
            for (String e : Tools.cleanExamples()) {
                if (!models.contains(e)) {
                    models.add(e);
                }
            }
        }
        return models;
    }

    private static final Pattern PORT = Pattern.compile("summary (\\S+) messages (\\d+) received ([\\d.]+)\\.\\.([\\d.]+) ms");

    /** The model whose parameters file the test edits, as a user tunes the system without generating again. */
    static final String TUNED = "mobile-base-latency.rsaml";

    /**
     * Doubles, in the package's parameters file, the period of the longest release of a module
     * released only by it: the node must run at the file's period. The file holds the model's value
     * first, in the model's unit.
     */
    private static void tune(Path root, ExecutionPlan plan, Map<Release, Long> periodsNs) throws Exception {
        Release r = plan.releases().stream().filter(x -> x.module().releases().size() == 1)
                .max(java.util.Comparator.comparingLong(Release::periodNs)).orElseThrow();
        String node = Ros2Test.nodes(root.getParent()).get(r.module().qualifiedName());
        Path file = root.resolve("config/" + root.getFileName() + ".params.yaml");
        List<String> lines = new ArrayList<>(Files.readAllLines(file));
        int section = lines.indexOf(node + ":");
        assertTrue(section >= 0, "no section for node " + node + " in " + file + ":\n" + String.join("\n", lines));
        Pattern period = Pattern.compile("(\\s+[\\w.]+\\.period_(ns|us|ms|s): )([\\d.]+)");
        for (int i = section + 1; i < lines.size() && lines.get(i).startsWith(" "); i++) {
            Matcher m = period.matcher(lines.get(i));
            if (m.matches()) {
                long unitNs = switch (m.group(2)) { case "ns" -> 1L; case "us" -> 1_000L; case "ms" -> 1_000_000L; default -> 1_000_000_000L; };
                BigDecimal value = new BigDecimal(m.group(3));
                assertEquals(r.periodNs(), value.multiply(BigDecimal.valueOf(unitNs)).longValueExact(), "the parameters file's " + lines.get(i).strip()
                        + " is not the model's period of " + r.label());
                lines.set(i, m.group(1) + value.multiply(BigDecimal.valueOf(2)).toPlainString());
                Files.write(file, lines);
                periodsNs.put(r, 2 * r.periodNs());
                return;
            }
        }
        fail("no period parameter of " + r.label() + " in the section of node " + node + " in " + file);
    }

    /**
     * Flips, in the package's parameters file, the reliability of a topic the model names, by the
     * model's name: its publisher's from best effort to reliable, or else its subscriptions' from
     * reliable to best effort (either way the publisher still reaches its subscribers). Returns the
     * endpoint type ROS 2 reports the change on and the reliability it must report.
     */
    private static String[] tuneQos(Path root, String topic) throws Exception {
        Path file = root.resolve("config/" + root.getFileName() + ".params.yaml");
        String text = Files.readString(file);
        String publisher = "qos_overrides." + topic + ".publisher.reliability: ";
        String subscription = "qos_overrides." + topic + ".subscription.reliability: ";
        String[] change = text.contains(publisher + "best_effort") ? new String[] {publisher + "best_effort", publisher + "reliable", "PUBLISHER", "RELIABLE"}
                : new String[] {subscription + "reliable", subscription + "best_effort", "SUBSCRIPTION", "BEST_EFFORT"};
        assertTrue(text.contains(change[0]), "the parameters file has no " + change[0] + ":\n" + text);
        Files.writeString(file, text.replace(change[0], change[1]));
        return new String[] {change[2], change[3]};
    }

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

    /** The architect's code written into the generated packages (under src/) before they are built. */
    interface UserCode {
        void write(Path src) throws Exception;
    }

    private static final Pattern SHARED = Pattern.compile("shared (left|right) (\\d+) (\\S+)");

    /**
     * Messages are shared, not copied, in a component container: the producer of
     * resources/ros2-shared-messages.rsaml publishes 1, 2, 3, ... every 20 ms to two reactive
     * modules of the same container, whose handlers (the architect's code) print the address of
     * each message they get. With intra-process communication both get the one message the producer
     * published (the same address for each value); over the middleware each subscription would
     * take a copy of its own, while in_in still holds the previous one. The run also checks what
     * every run does (releases, rates, reactions measured).
     */
    @org.junit.jupiter.api.Test
    void aMessageIsSharedByTheSubscriptionsOfAContainer(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String name = "resources/ros2-shared-messages.rsaml";
        String out = run(Ros2Test.model(name), name, tmp, src -> {
            Path pkg = src.resolve("shared_messages/src");
            replace(pkg.resolve("high/Producer.cpp"), "void Producer::compute() {}", "void Producer::compute() { out_value.data += 1.0; }");
            for (String module : List.of("left", "right")) {
                String cls = Character.toUpperCase(module.charAt(0)) + module.substring(1);
                Path cpp = pkg.resolve("low/" + cls + ".cpp");
                replace(cpp, "{ (void)message; }", "{\n  std::printf(\"shared " + module + " %.0f %p\\n\", message.data, static_cast<const void*>(&message));\n"
                        + "  std::fflush(stdout);\n}");
                replace(cpp, "#include \"low/" + cls + ".hpp\"", "#include \"low/" + cls + ".hpp\"\n\n#include <cstdio>");
            }
        });
        Map<String, Map<String, String>> seen = new TreeMap<>();
        Matcher m = SHARED.matcher(out);
        while (m.find()) {
            seen.computeIfAbsent(m.group(2), v -> new TreeMap<>()).put(m.group(1), m.group(3));
        }
        List<String> both = seen.entrySet().stream().filter(e -> e.getValue().size() == 2).map(Map.Entry::getKey).toList();
        assertTrue(both.size() >= 50, "both subscribers should have printed most of the producer's messages (every 20 ms for "
                + RUN_MS + " ms): " + both.size() + " values seen by both\n" + Tools.last(out, 4000));
        for (String value : both) {
            Map<String, String> at = seen.get(value);
            assertEquals(at.get("left"), at.get("right"), "message " + value + " was copied for each subscriber of the container: " + at);
        }
    }

    /**
     * The package's own launch test (launch_testing, test/test_&lt;pkg&gt;_launch.py), run by colcon test
     * as a ROS 2 developer runs it: it starts the nodes, stops them and checks that messages reached
     * the ports timed modules feed and that every process exited cleanly. Where ROS 2 has no
     * launch_testing (the Jazzy core of the shared folder), it is skipped and says so: the package's
     * CMakeLists.txt then adds no launch test (Ros2Test checks that it looks for launch_testing under
     * BUILD_TESTING, and every colcon build here configures that block).
     */
    @org.junit.jupiter.api.Test
    void thePackagesLaunchTestPassesUnderColconTest(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String absent = Ros2Jazzy.launchTestingMissing();
        if (absent != null) {
            System.err.println("Ros2LaunchTest: skipped: " + absent);
        }
        Assumptions.assumeTrue(absent == null, absent);
        Path model = Ros2Test.model("resources/ros2-shared-messages.rsaml");
        String pkg = Names.snake(ModelLoader.load(model, "ros2-shared-messages.rsaml").architecture().getName());
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        Ros2Jazzy.colconBuild(src, tmp);
        String paths = " --build-base '" + tmp.resolve("build") + "' --install-base '" + tmp.resolve("install") + "'";
        Tools.Result test = Tools.run(tmp, 600, Ros2Jazzy.bash("colcon --log-base '" + tmp.resolve("log") + "' test --base-paths '" + src + "'"
                + paths + " --packages-select " + pkg + " --event-handlers console_direct+").toArray(String[]::new));
        Tools.Result result = Tools.run(tmp, 60, Ros2Jazzy.bash("colcon test-result --verbose --test-result-base '" + tmp.resolve("build/" + pkg)
                + "'").toArray(String[]::new));
        assertTrue(test.exit() == 0 && result.exit() == 0 && result.output().contains("0 errors, 0 failures"),
                "colcon test of " + pkg + ":\n" + Tools.last(test.output(), 6000) + "\n" + result.output());
        assertTrue(result.output().contains("test_" + pkg + "_launch"), "the launch test did not run:\n" + result.output());
    }

    private static void replace(Path file, String what, String with) throws java.io.IOException {
        String text = Files.readString(file);
        assertTrue(text.contains(what), file + " does not contain " + what + ":\n" + text);
        Files.writeString(file, text.replace(what, with));
    }

    /** Which containers (or nodes) a launch file starts for host:=ARG, evaluated by ROS 2's launch itself. */
    private static final String STARTED = """
            import importlib.util, sys
            from launch import LaunchContext
            from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions
            sys.dont_write_bytecode = True
            spec = importlib.util.spec_from_file_location('l', sys.argv[1]); m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)
            context = LaunchContext()
            entities = m.generate_launch_description().entities
            for e in entities:
                if type(e).__name__ == 'DeclareLaunchArgument':
                    context.launch_configurations[e.name] = perform_substitutions(context, e.default_value) if e.name != 'params_file' else sys.argv[3]
            context.launch_configurations['host'] = sys.argv[2]
            started = []
            for e in [a for e in entities if type(e).__name__ == 'OpaqueFunction' for a in e.execute(context)]:
                if e.condition is None or e.condition.evaluate(context):
                    started.append(perform_substitutions(context, normalize_to_list_of_substitutions(e._Node__node_name)))
            print('started', ' '.join(sorted(started)))
            """;

    /**
     * A processor on another host: mobile-base-latency with its navigation processor on the board
     * "nav-board". Both launch files take host:=, and ROS 2's launch starts only that host's
     * containers (or nodes): main is the processors without a host; empty, every one.
     */
    @org.junit.jupiter.api.Test
    void theHostArgumentStartsOnlyTheNodesOfOneHost(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String text = Files.readString(Tools.example("mobile-base-latency.rsaml"));
        String nav = "<processors name=\"core1\"";
        assertTrue(text.contains(nav));
        Path model = tmp.resolve("two-hosts.rsaml");
        Files.writeString(model, text.replace(nav, nav + " host=\"nav-board\" linkLatency=\"2.0\""));
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        String pkg = Names.snake(ModelLoader.load(model, "two-hosts.rsaml").architecture().getName());
        Path script = tmp.resolve("started.py");
        Files.writeString(script, STARTED);
        Map<String, String> expected = Map.of("", "started " + pkg + "_core0_container " + pkg + "_core1_container", "main",
                "started " + pkg + "_core0_container", "nav-board", "started " + pkg + "_core1_container", "elsewhere", "started");
        String params = src.resolve(pkg + "/config/" + pkg + ".params.yaml").toString();
        for (Map.Entry<String, String> e : expected.entrySet()) {
            String out = Tools.ok(tmp, 120, Ros2Jazzy.bash("python3 '" + script + "' '" + src.resolve(pkg + "/launch/" + pkg + ".launch.py")
                    + "' '" + e.getKey() + "' '" + params + "'").toArray(String[]::new));
            assertTrue(out.strip().endsWith(e.getValue()), "host:=" + e.getKey() + " should start " + e.getValue() + ":\n" + out);
        }
        String processes = Tools.ok(tmp, 120, Ros2Jazzy.bash("python3 '" + script + "' '" + src.resolve(pkg + "/launch/" + pkg
                + "_processes.launch.py") + "' nav-board '" + params + "'").toArray(String[]::new));
        assertTrue(processes.strip().endsWith("started navigation_obstacle_detector navigation_path_planner"),
                "the navigation nodes alone:\n" + processes);
    }

    /** Runs each started process's launch prefix for host:=ARG on a command that prints the CPUs it may use, as "node cpus". */
    private static final String PINNED = """
            import importlib.util, shlex, subprocess, sys
            from launch import LaunchContext
            from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions
            sys.dont_write_bytecode = True
            spec = importlib.util.spec_from_file_location('l', sys.argv[1]); m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)
            context = LaunchContext()
            entities = m.generate_launch_description().entities
            for e in entities:
                if type(e).__name__ == 'DeclareLaunchArgument':
                    context.launch_configurations[e.name] = perform_substitutions(context, e.default_value) if e.name != 'params_file' else sys.argv[3]
            context.launch_configurations['host'] = sys.argv[2]
            for e in [a for e in entities if type(e).__name__ == 'OpaqueFunction' for a in e.execute(context)]:
                if type(e).__name__ in ('Node', 'ComposableNodeContainer') and (e.condition is None or e.condition.evaluate(context)):
                    name = perform_substitutions(context, normalize_to_list_of_substitutions(e._Node__node_name))
                    prefix = shlex.split(perform_substitutions(context, e.process_description.prefix))
                    out = subprocess.run(prefix + ['sh', '-c', 'grep Cpus_allowed_list /proc/self/status'], capture_output=True, text=True)
                    print(name, out.stdout.split()[-1], out.stderr.strip())
            """;

    /**
     * An invalid edit of a parameters file, on ROS 2's own launch: refused before any node starts,
     * with the file, the line and what is wrong, as launch reports an error (no Python traceback).
     */
    @org.junit.jupiter.api.Test
    void anInvalidParametersFileIsRefusedWithItsLine(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Path model = Tools.example(TUNED);
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        String pkg = Names.snake(ModelLoader.load(model, TUNED).architecture().getName());
        Path params = src.resolve(pkg + "/config/" + pkg + ".params.yaml");
        List<String> lines = new ArrayList<>(Files.readAllLines(params));
        int line = java.util.stream.IntStream.range(0, lines.size()).filter(i -> lines.get(i).matches("\\s+[\\w.]+\\.period_ms: [\\d.]+"))
                .findFirst().orElseThrow() + 1;
        String name = lines.get(line - 1).strip().split(":")[0];
        lines.set(line - 1, lines.get(line - 1).replaceFirst(": [\\d.]+$", ": -5"));
        Files.write(params, lines);
        Tools.Result r = Tools.run(tmp, 120, Ros2Jazzy.bash("ros2 launch '" + src.resolve(pkg + "/launch/" + pkg + ".launch.py") + "' params_file:='"
                + params + "'").toArray(String[]::new));
        assertTrue(r.exit() != 0, "ros2 launch took the invalid parameters file:\n" + r.output());
        assertTrue(r.output().contains(params + ":" + line + ": " + name + " of node ") && r.output().contains("must be a positive number of ms"),
                "no error naming " + params + ", line " + line + " and " + name + ":\n" + r.output());
        assertTrue(!r.output().contains("Traceback"), "a traceback instead of an error:\n" + r.output());
    }

    /**
     * Managed nodes (resources/ros2-lifecycle.rsaml: the lidar and the mapper managed, the monitor
     * plain), with each launch file: the package's lifecycle manager configures and activates them,
     * so that ROS 2 itself ({@code ros2 lifecycle get}) reports exactly them as lifecycle nodes, both
     * active; each traced configure, then activate; their messages flow (the mapper receives the
     * lidar's scans, the plain monitor the mapper's maps); everything exits cleanly on SIGINT.
     * {@code -Dtest=Ros2LaunchTest -Dgroups=lifecycle} runs it alone.
     */
    @org.junit.jupiter.api.Test
    @org.junit.jupiter.api.Tag("lifecycle")
    void bothLaunchFilesBringTheManagedNodesToActive(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Path model = Ros2Test.model("resources/ros2-lifecycle.rsaml");
        Architecture arch = ModelLoader.load(model, "ros2-lifecycle.rsaml").architecture();
        String pkg = Names.snake(arch.getName());
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        Path install = Ros2Jazzy.colconBuild(src, tmp);
        Map<String, String> nodes = Ros2Test.nodes(src.resolve(pkg));
        List<String> managed = List.of("perception/lidar", "mapping/mapper");
        int domain = 1 + (int) ((ProcessHandle.current().pid() + 50) % 100);
        for (String file : List.of(pkg + ".launch.py", pkg + "_processes.launch.py")) {
            Path log = tmp.resolve(file + ".log");
            ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash("exec ros2 launch " + pkg + " " + file, install))
                    .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
            Ros2Jazzy.isolate(pb.environment(), domain);
            Process launch = pb.start();
            String states;
            try {
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
                while (true) {
                    String o = Files.readString(log, StandardCharsets.UTF_8);
                    if (managed.stream().allMatch(m -> o.contains("state " + m + " active"))) {
                        break;
                    }
                    if (!launch.isAlive() || System.nanoTime() > until) {
                        fail(file + ": the managed nodes " + managed + " did not become active within 120 s:\n" + Tools.last(o, 6000));
                    }
                    Thread.sleep(200);
                }
                Thread.sleep(1500); // messages flow
                states = Tools.ok(tmp, 60, Ros2Jazzy.bash("export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST ROS_DOMAIN_ID=" + domain
                        + "; ros2 lifecycle get --no-daemon --spin-time 3", install).toArray(String[]::new));
                Tools.ok(tmp, 10, "kill", "-INT", Long.toString(launch.pid()));
                assertTrue(launch.waitFor(60, TimeUnit.SECONDS), file + ": ros2 launch did not stop within 60 s of SIGINT");
            } finally {
                launch.descendants().forEach(ProcessHandle::destroyForcibly);
                launch.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertEquals(0, launch.exitValue(), () -> file + ": ros2 launch exited with " + launch.exitValue() + ":\n" + Tools.last(out, 6000));
            List<String> expected = managed.stream().map(m -> "/" + nodes.get(m) + ": active [3]").sorted().toList();
            List<String> reported = states.lines().filter(l -> l.startsWith("/")).map(String::strip).sorted().toList();
            assertEquals(expected, reported, file + ": the lifecycle nodes and their states, as ros2 lifecycle get reports them:\n" + states);
            for (String m : managed) {
                int configured = out.indexOf("state " + m + " inactive");
                assertTrue(configured >= 0 && configured < out.indexOf("state " + m + " active"),
                        file + ": " + m + " was not configured before it was activated:\n" + Tools.last(out, 6000));
            }
            assertFalse(out.contains("process has died"), () -> file + ": a process died:\n" + Tools.last(out, 6000));
            Map<String, double[]> ports = new TreeMap<>();
            Matcher p = PORT.matcher(out);
            while (p.find()) {
                ports.put(p.group(1), new double[] {Long.parseLong(p.group(2))});
            }
            for (String port : List.of("mapping/mapper:scan", "supervision/monitor:map")) {
                assertTrue(ports.containsKey(port) && ports.get(port)[0] >= 5, file + ": hardly any message reached " + port + " ("
                        + (ports.containsKey(port) ? (long) ports.get(port)[0] : 0) + "):\n" + Tools.last(out, 6000));
            }
        }
    }

    /**
     * Two hosts' "core 0" on one machine: mobile-base-latency with its navigation processor on core 0
     * of the board "nav-board". The analysis counts the two apart; a launch without host:= (one
     * machine starts every host) pins the board's core 0 to CPU 1, as the C++ program does, and one
     * with host:=nav-board pins it to its core 0. ROS 2's launch evaluates the prefixes, which are run.
     */
    @org.junit.jupiter.api.Test
    void oneMachineGivesEachHostsCoreACpuOfItsOwn(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Assumptions.assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "one CPU: no second CPU to pin to");
        String text = Files.readString(Tools.example("mobile-base-latency.rsaml"));
        String nav = "<processors name=\"core1\" description=\"CPU core 1: navigation.\" core=\"1\"";
        assertTrue(text.contains(nav));
        Path model = tmp.resolve("two-hosts.rsaml");
        Files.writeString(model, text.replace(nav, "<processors name=\"core1\" description=\"Core 0 of the board.\" core=\"0\" host=\"nav-board\""));
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        String pkg = Names.snake(ModelLoader.load(model, "two-hosts.rsaml").architecture().getName());
        Path script = tmp.resolve("pinned.py");
        Files.writeString(script, PINNED);
        String params = src.resolve(pkg + "/config/" + pkg + ".params.yaml").toString();
        Map<String, String> expected = Map.of("", pkg + "_core0_container 0\n" + pkg + "_core1_container 1", "nav-board",
                pkg + "_core1_container 0");
        for (Map.Entry<String, String> e : expected.entrySet()) {
            String out = Tools.ok(tmp, 120, Ros2Jazzy.bash("python3 '" + script + "' '" + src.resolve(pkg + "/launch/" + pkg + ".launch.py")
                    + "' '" + e.getKey() + "' '" + params + "'").toArray(String[]::new));
            List<String> lines = out.lines().filter(l -> l.startsWith(pkg + "_")).map(String::strip).sorted().toList();
            assertEquals(e.getValue(), String.join("\n", lines), "host:=" + e.getKey() + ": each container and the CPU it is pinned to:\n" + out);
        }
        String processes = Tools.ok(tmp, 120, Ros2Jazzy.bash("python3 '" + script + "' '" + src.resolve(pkg + "/launch/" + pkg
                + "_processes.launch.py") + "' '' '" + params + "'").toArray(String[]::new));
        assertTrue(processes.contains("navigation_obstacle_detector 1") && processes.contains("control_velocity_controller 0"),
                "without host:=, the board's nodes on CPU 1, the main host's on CPU 0:\n" + processes);
    }

    /**
     * Null when a release's threads have its processor's CPU to themselves on ROS 2: its processor has
     * a core of this machine, and every other release's process is pinned too (a container without a
     * core runs its threads on any CPU) and none runs under SCHED_DEADLINE (on every CPU).
     */
    static String apartOnRos2(ExecutionPlan plan, Release r) {
        org.rsaml.model.Processor p = r.module().processor();
        if (p == null || p.getCore() < 0 || p.getCore() >= Runtime.getRuntime().availableProcessors()) {
            return "no core of this machine of its own";
        }
        for (Release o : plan.releases()) {
            if (o.module().processor() == null || o.module().processor().getCore() < 0) {
                return "the threads of " + o.label() + " have no core and run on any CPU";
            }
            if (o.edf()) {
                return "the deadline threads of " + o.label() + " may run on every CPU";
            }
        }
        return null;
    }

    /** Generates, builds, launches and checks one model; the launch's output. */
    static String run(Path model, String name, Path tmp, UserCode code) throws Exception {
        Architecture arch = ModelLoader.load(model, name).architecture();
        String pkg = Names.snake(arch.getName());
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
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
            tune(src.resolve(pkg), plan, periodsNs);
            assertNotNull(renamed, TUNED + " names no topic");
            qos = tuneQos(src.resolve(pkg), renamed);
        }
        Path install = Ros2Jazzy.colconBuild(src, tmp);

        // Launch, wait for every node, let it run, interrupt it.
        Map<String, String> nodes = Ros2Test.nodes(src);
        Path log = tmp.resolve("launch.log");
        int domain = 1 + (int) (ProcessHandle.current().pid() % 100);
        ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash("exec ros2 launch " + pkg + " " + pkg + ".launch.py simulated_load:=" + LOAD + remaps, install))
                .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
        Ros2Jazzy.isolate(pb.environment(), domain);
        OtherRealtime.Watch watch = new OtherRealtime.Watch();
        Process launch = pb.start();
        OtherRealtime.Use others;
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
                String info = Tools.ok(tmp, 60, Ros2Jazzy.bash(script, install).toArray(String[]::new));
                assertTrue(info.matches("(?s).*Publisher count: [1-9].*Subscription count: [1-9].*"), "the model's topic '" + t.getKey()
                        + "' is not " + t.getValue() + " with its publisher and subscribers:\n" + info);
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
            others = watch.stop();
        }
        out = Files.readString(log, StandardCharsets.UTF_8);
        String trace = out;
        assertEquals(0, launch.exitValue(), () -> "ros2 launch exited with " + launch.exitValue() + ":\n" + Tools.last(trace, 6000));
        int containers = (int) Pattern.compile("ComposableNodeContainer\\(").matcher(
                Files.readString(src.resolve(pkg + "/launch/" + pkg + ".launch.py"))).results().count();
        assertEquals(containers, Pattern.compile("process has finished cleanly").matcher(out).results().count(),
                () -> "not every container exited cleanly on SIGINT:\n" + Tools.last(trace, 6000));

        Map<String, JobSummary> observed = JobSummary.of(out);
        Map<String, double[]> ports = new TreeMap<>();
        Matcher m = PORT.matcher(out);
        while (m.find()) {
            ports.put(m.group(1), new double[] {Long.parseLong(m.group(2)), Double.parseDouble(m.group(3)), Double.parseDouble(m.group(4))});
        }

        // Every release at its modeled period: releases on the grid, none skipped, for the whole run.
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
            }
        }

        // Messages arrive at every connected entry port, at the rate its publisher is released.
        for (Connection c : arch.getConnections()) {
            String port = c.getTarget().getModule().getLayer().getName() + "/" + c.getTarget().getModule().getName() + ":" + c.getTarget().getName();
            double[] p = ports.get(port);
            assertNotNull(p, "no message reached " + port + ":\n" + Tools.last(trace, 6000));
            PlannedModule source = plan.modules().stream().filter(x -> x.module() == c.getSource().getModule()).findFirst().orElseThrow();
            if (!source.reactive() && !source.releases().isEmpty() && p[0] >= 3) {
                double expected = source.releases().stream().mapToDouble(r -> 1e6 / periodsNs.get(r)).sum();
                double rate = (p[0] - 1) / (p[2] - p[1]);
                assertEquals(expected, rate, expected * 0.15, port + " received " + (long) p[0] + " messages from " + p[1] + " to " + p[2]
                        + " ms: " + rate * 1000 + " a second, its publisher is released " + expected * 1000 + " times a second");
            }
            report.append("  ").append(port).append(": ").append((long) p[0]).append(" messages\n");
        }

        // Each node reports the analysis's bound of its releases; the observed response times are
        // within it (plus the platform's measured allowance) where the release got the scheduling the
        // analysis assumes and other programs' real-time threads used at most OtherRealtime.TOLERATED_NS.
        Map<String, Long> bounds = JobTimingTest.bounds(TimingAnalysis.analyse(arch));
        List<String> unchecked = new ArrayList<>();
        List<Release> checked = new ArrayList<>();
        for (Release r : plan.releases()) {
            JobSummary o = observed.get(r.label());
            long bound = bounds.getOrDefault(r.label(), -1L);
            assertEquals(bound < 0 ? "none" : JobTimingTest.ms(bound), o.bound(), r.label() + ": the analysis's bound, written into the node: " + o);
            assertEquals(r.deadlineNs(), o.deadlineNs(), 500, r.label() + ": the modeled deadline: " + o);
            assertEquals(r.costNs(), o.modeledNs(), 500, r.label() + ": the modeled execution time: " + o);
            report.append(String.format(java.util.Locale.ROOT, "  %s: %d jobs (%d missed), worst response %s (execution %s, start latency %s), bound %s, %s%n",
                    r.label(), o.jobs(), o.misses(), JobTimingTest.ms(o.worstNs()), JobTimingTest.ms(o.executionNs()), JobTimingTest.ms(o.latencyNs()),
                    o.bound(), o.sched()));
            if (r.edf()) {
                report.append("  ").append(edfCase(r, o)).append('\n');
            }
            if (bound < 0) {
                continue;
            }
            if (!o.asAnalysed()) {
                unchecked.add(r.label() + " (" + o.sched() + ")");
                continue;
            }
            checked.add(r);
        }
        if (!checked.isEmpty()) {
            PlatformCheck.BoundCheck check = PlatformCheck.boundCheck("Ros2LaunchTest " + name, others,
                    () -> PlatformCheck.probes(arch, plan, observed, r -> apartOnRos2(plan, r)), observed);
            PlatformCheck.Allowance allowance = check.allowance();
            if (allowance == null) {
                checked.forEach(r -> unchecked.add(r.label() + " (" + check.notChecked() + ")"));
                checked.clear();
            } else {
                report.append("  allowance for the platform: ").append(allowance).append('\n');
            }
            for (Release r : checked) {
                JobSummary o = observed.get(r.label());
                long bound = bounds.get(r.label());
                assertTrue(o.worstNs() <= bound + allowance.ns(), r.label() + ": worst observed response " + JobTimingTest.ms(o.worstNs())
                        + " exceeds the analysed bound " + JobTimingTest.ms(bound) + " plus the platform's allowance " + allowance + "\n" + report);
            }
            report.append("  checked against the bound: ").append(checked.stream().map(Release::label).toList()).append('\n');
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
            report.append(String.format(java.util.Locale.ROOT, "  %s: %d jobs, worst response %s (execution %s, start latency %s), bound %s, %s%n",
                    x.label(), o.jobs(), JobTimingTest.ms(o.worstNs()), JobTimingTest.ms(o.executionNs()), JobTimingTest.ms(o.latencyNs()),
                    o.bound(), o.sched()));
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
     * Which case an EDF processor's release saw, checked: SCHED_DEADLINE in force with the modeled
     * runtime, deadline and period as the kernel reports them back (sched_getattr), or the kernel's
     * refusal and the fallback, said by the node.
     */
    static String edfCase(Release r, JobSummary o) {
        String modeled = "SCHED_DEADLINE runtime " + JobTimingTest.ms(r.costNs()) + " deadline " + JobTimingTest.ms(r.deadlineNs()) + " period "
                + JobTimingTest.ms(r.periodNs());
        if (o.sched().startsWith("SCHED_DEADLINE")) {
            assertTrue(o.sched().startsWith(modeled) && o.sched().endsWith("(kernel: " + modeled + ")"), r.label()
                    + ": SCHED_DEADLINE with the modeled runtime, deadline and period, as the kernel reports them: " + o.sched());
            return "EDF " + r.label() + ": SCHED_DEADLINE in force (kernel: " + modeled.substring("SCHED_DEADLINE ".length())
                    + ")";
        }
        assertTrue(o.sched().matches("(SCHED_FIFO rank \\d+|default) instead of EDF: .+"), r.label()
                + ": without SCHED_DEADLINE, the refusal and the fallback: " + o.sched());
        return "EDF " + r.label() + ": SCHED_DEADLINE refused (" + o.sched().replaceFirst("^.* instead of EDF: ", "") + "), fallback "
                + o.sched().replaceFirst(" instead of EDF: .*", "") + ": EDF's bound does not apply";
    }
}
