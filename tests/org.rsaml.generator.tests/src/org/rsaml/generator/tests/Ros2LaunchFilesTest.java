/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.Names;
import org.rsaml.validation.ModelLoader;

/**
 * What the generated ROS 2 packages' launch files and build do on a real ROS 2 ({@link Ros2Jazzy}),
 * apart from running a system ({@link Ros2LaunchTest}): host:= starts only one host's containers or
 * nodes, the launch prefixes pin each to its CPU (those of a processor without a core to the CPUs no processor claims), an invalid parameters file is refused with its
 * line, and the package's own launch test passes under colcon test where ROS 2 has launch_testing.
 */
class Ros2LaunchFilesTest {

    /**
     * The package's own launch test (launch_testing, test/test_&lt;pkg&gt;_launch.py), run by colcon test
     * as a ROS 2 developer runs it: it starts the nodes, stops them and checks that messages reached
     * the ports timed modules feed and that every process exited cleanly. Where ROS 2 has no
     * launch_testing (the Jazzy core of the shared folder), it is skipped and says so: the package's
     * CMakeLists.txt then adds no launch test (Ros2Test checks that it looks for launch_testing under
     * BUILD_TESTING, and every colcon build here configures that block).
     */
    @Test
    void thePackagesLaunchTestPassesUnderColconTest(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String absent = Ros2Jazzy.launchTestingMissing();
        if (absent != null) {
            System.err.println("Ros2LaunchFilesTest: skipped: " + absent);
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

    /**
     * Loads the launch file sys.argv[1] and sets its arguments as ROS 2's launch would, with host:=sys.argv[2] and
     * params_file:=sys.argv[3]; the scripts below go on from its context and entities.
     */
    private static final String LAUNCH_CONTEXT = """
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
            """;

    /** Which containers (or nodes) a launch file starts for host:=ARG, evaluated by ROS 2's launch itself. */
    private static final String STARTED = LAUNCH_CONTEXT + """
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
    @Test
    void theHostArgumentStartsOnlyTheNodesOfOneHost(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String text = Files.readString(Tools.example("mobile-base-latency.rsaml"));
        String nav = "<processors name=\"core1\"";
        assertTrue(text.contains(nav), "the example has the navigation processor");
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
    private static final String PINNED = LAUNCH_CONTEXT + """
            for e in [a for e in entities if type(e).__name__ == 'OpaqueFunction' for a in e.execute(context)]:
                if type(e).__name__ in ('Node', 'ComposableNodeContainer') and (e.condition is None or e.condition.evaluate(context)):
                    name = perform_substitutions(context, normalize_to_list_of_substitutions(e._Node__node_name))
                    prefix = shlex.split(perform_substitutions(context, e.process_description.prefix))
                    out = subprocess.run(prefix + ['sh', '-c', 'grep Cpus_allowed_list /proc/self/status; echo "${RSAML_CPU:--}"'],
                                         capture_output=True, text=True)
                    print(name, out.stdout.split()[-2], out.stderr.strip())
                    print('placed', name, out.stdout.split()[-1])
            """;

    /**
     * An invalid edit of a parameters file, on ROS 2's own launch: refused before any node starts,
     * with the file, the line and what is wrong, as launch reports an error (no Python traceback).
     */
    @Test
    void anInvalidParametersFileIsRefusedWithItsLine(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Path model = Tools.example(Ros2LaunchTest.TUNED);
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        String pkg = Names.snake(ModelLoader.load(model, Ros2LaunchTest.TUNED).architecture().getName());
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
     * Two hosts' "core 0" on one machine: mobile-base-latency with its navigation processor on core 0
     * of the board "nav-board". The analysis counts the two apart; a launch without host:= (one
     * machine starts every host) pins the board's core 0 to CPU 1, as the C++ program does, and one
     * with host:=nav-board pins it to its core 0. ROS 2's launch evaluates the prefixes, which are run.
     */
    @Test
    void oneMachineGivesEachHostsCoreACpuOfItsOwn(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Assumptions.assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "one CPU: no second CPU to pin to");
        Pinned run = Pinned.of(tmp, "two-hosts", "<processors name=\"core1\" description=\"Core 0 of the board.\" core=\"0\" host=\"nav-board\"");
        String pkg = run.pkg();
        Map<String, String> expected = Map.of("", pkg + "_core0_container 0\n" + pkg + "_core1_container 1", "nav-board",
                pkg + "_core1_container 0");
        for (Map.Entry<String, String> e : expected.entrySet()) {
            String out = run.cpus(".launch.py", e.getKey());
            List<String> lines = out.lines().filter(l -> l.startsWith(pkg + "_")).map(String::strip).sorted().toList();
            assertEquals(e.getValue(), String.join("\n", lines), "host:=" + e.getKey() + ": each container and the CPU it is pinned to:\n" + out);
        }
        String processes = run.cpus("_processes.launch.py", "");
        assertTrue(processes.contains("navigation_obstacle_detector 1") && processes.contains("control_velocity_controller 0"),
                "without host:=, the board's nodes on CPU 1, the main host's on CPU 0:\n" + processes);
        // each process is told the CPU it was placed on (RSAML_CPU), where its nodes pin their threads, not the model's core
        assertTrue(processes.contains("placed navigation_obstacle_detector 1") && processes.contains("placed control_velocity_controller 0"),
                "the processes told their CPUs:\n" + processes);
        String board = run.cpus(".launch.py", "nav-board");
        assertTrue(board.contains("placed " + pkg + "_core1_container 0"), "host:=nav-board: the board's container told its core 0:\n" + board);
    }

    /**
     * The processes of a processor without a core, placed as the C++ program places the threads of its modules: on the
     * CPUs no processor claims (OneMachineCpus.claimed), saying so; where every CPU is claimed, where the operating system
     * puts them, saying that. mobile-base-latency with its navigation processor's core taken away: its container (and,
     * in the other launch file, each of its nodes' processes) runs on the CPUs this machine leaves beside core 0. ROS 2's
     * launch evaluates the prefixes, which are run and print the CPUs each process may use. The same when that processor is
     * an EDF one (docs/timing.md, "EDF beside processors with cores"): placed by the same rule, so that core 0 stays the
     * control processor's, where the kernel refuses its releases SCHED_DEADLINE, which they say ('instead of EDF':
     * CppExamplesTest shows the C++ program's, Ros2LaunchTest a launch's).
     */
    @ParameterizedTest(name = "policy ''{0}''")
    @ValueSource(strings = {"", " schedPolicy=\"EDF\""})
    void theProcessesOfAProcessorWithoutACoreRunOnTheCpusNoProcessorClaims(String policy, @TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String allowed = Tools.ok(tmp, 60, "sh", "-c", "grep Cpus_allowed_list /proc/self/status").strip().replaceFirst(".*\\s", "");
        java.util.TreeSet<Integer> cpus = cpuSet(allowed);
        Assumptions.assumeTrue(cpus.size() >= 2 && cpus.contains(0), "one CPU, or no CPU 0: no CPU left beside core 0 (" + allowed + ")");
        Pinned run = Pinned.of(tmp, "coreless", "<processors name=\"core1\" description=\"Navigation, on no core of its own.\"" + policy);
        String pkg = run.pkg();
        cpus.remove(0);
        String left = cpuList(cpus);
        String out = run.cpus(".launch.py", "");
        List<String> lines = out.lines().filter(l -> l.startsWith(pkg + "_")).map(String::strip).sorted().toList();
        assertEquals(pkg + "_core0_container 0\n" + pkg + "_core1_container " + left + " RsaML: cpu " + pkg + "_core1_container cores " + left
                + " unclaimed", String.join("\n", lines), "core 0's container on CPU 0, the other on the CPUs left, saying so:\n" + out);
        String processes = run.cpus("_processes.launch.py", "");
        assertTrue(processes.contains("navigation_path_planner " + left + " RsaML: cpu navigation_path_planner cores " + left + " unclaimed")
                && processes.contains("control_velocity_controller 0"), "the navigation nodes on the CPUs left beside core 0:\n" + processes);
        if (!allowed.equals("0-1") || !policy.isEmpty()) {
            return; // every CPU claimed: shown on two CPUs, once
        }
        // every CPU claimed (core 0 and core 1), the path planner on no processor: where the operating system puts it, said
        String planner = " //@layers[name='navigation']/@modules[name='pathPlanner']\"/>";
        String every = Pinned.of(tmp, "claimed", planner, "\"/>").cpus(".launch.py", "");
        assertTrue(every.contains(pkg + "_container 0-1 RsaML: cpu " + pkg + "_container no unclaimed core: default (the processors claim CPUs 0-1: it runs"
                + " on them)"), "the modules no processor names on every CPU, saying so:\n" + every);
    }

    /**
     * A release of an EDF processor with a core that the kernel refuses SCHED_DEADLINE is put back on its core, as the C++
     * runtime's is (docs/timing.md, "What the generators make of it"). Its thread is pinned to the core, then given every CPU
     * of its process for the request; a node started outside the launch (as ros2 run starts it, on every CPU) without
     * CAP_SYS_NICE is refused, and its release's thread must end on its core alone again, as its cpu line says: read
     * from /proc, the threads of the process allowed on CPU 1 alone are the release's (and no other thread is pinned).
     */
    @Test
    void aReleaseRefusedSchedDeadlineIsPutBackOnItsCore(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Assumptions.assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "one CPU: no core 1 to put the thread back on");
        Path model = tmp.resolve("refused.rsaml");
        Files.writeString(model, JobTimingTest.modelText("refusedEdf", JobTimingTest.module("a", 10, 1, "EDF"),
                "  <processors name=\"edf\" schedPolicy=\"EDF\" core=\"1\" modules=\"//@layers[name='tasks']/@modules[name='a']\"/>\n"));
        String pkg = Names.snake(ModelLoader.load(model, "refused.rsaml").architecture().getName());
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(model, Target.ROS2, src, false);
        Matcher exe = Pattern.compile("executable='(\\w+)'").matcher(Files.readString(src.resolve(pkg + "/launch/" + pkg + "_processes.launch.py")));
        assertTrue(exe.find(), "the processes launch file starts the node's executable");
        Path install = Ros2Jazzy.colconBuild(src, tmp);
        Path log = tmp.resolve("node.log");
        // as ros2 run starts it (no taskset, every CPU), without CAP_SYS_NICE: SCHED_DEADLINE is refused (EPERM)
        ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash("exec setpriv --inh-caps=-sys_nice --bounding-set=-sys_nice '"
                + install.resolve(pkg + "/lib/" + pkg + "/" + exe.group(1)) + "' --ros-args -p rsaml.simulated_load:=0.0", install))
                .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
        Ros2Jazzy.isolate(pb.environment(), 1 + (int) (ProcessHandle.current().pid() % 100));
        pb.environment().remove("RSAML_CPU");
        Process node = pb.start();
        String out = "";
        Map<String, String> allowed = new TreeMap<>();
        try {
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!(out = Files.readString(log, StandardCharsets.UTF_8)).contains("sched tasks/a.f ") || !out.contains(" instead of EDF")) {
                if (!node.isAlive() || System.nanoTime() > until) {
                    fail("the node did not say how its EDF release runs within 60 s:\n" + Tools.last(out, 4000));
                }
                Thread.sleep(100);
            }
            try (java.util.stream.Stream<Path> tasks = Files.list(Path.of("/proc/" + node.pid() + "/task"))) {
                for (Path t : tasks.toList()) {
                    String status = Files.readString(t.resolve("status"));
                    Matcher m = Pattern.compile("Cpus_allowed_list:\\s*(\\S+)").matcher(status);
                    allowed.put(t.getFileName().toString(), m.find() ? m.group(1) : "?");
                }
            }
        } finally {
            Tools.ok(tmp, 10, "kill", "-INT", Long.toString(node.pid()));
            if (!node.waitFor(30, TimeUnit.SECONDS)) {
                node.destroyForcibly();
            }
        }
        String said = out;
        // its placing (at the default priority: no CAP_SYS_NICE, no rtprio limit), then the refusal, said
        List<String> sched = out.lines().filter(l -> l.contains("] sched tasks/a.f ")).toList();
        assertTrue(out.lines().anyMatch(l -> l.endsWith("] cpu tasks/a.f core 1")), "the release pinned to core 1 first:\n" + said);
        assertTrue(!sched.isEmpty() && sched.get(sched.size() - 1).matches(
                ".*sched tasks/a\\.f (SCHED_FIFO rank \\d+|default) instead of EDF: .+, back on CPU 1 alone"),
                "refused SCHED_DEADLINE, it says it is back on CPU 1: " + sched + "\n" + Tools.last(said, 3000));
        String process = allowed.get(Long.toString(node.pid())); // the main thread's: every CPU the process may use
        assertTrue(process != null && !process.equals("1") && allowed.containsValue("1") && allowed.values().stream().allMatch(
                c -> c.equals("1") || c.equals(process)), "the release's thread back on CPU 1 alone, the process's other threads where"
                + " the process may run (" + process + "): " + allowed);
    }

    /**
     * The ROS 2 package of mobile-base-latency with {@code from} replaced by {@code to} (by default, its navigation processor
     * on core 1 by {@code to}), generated under tmp/name, and the script that runs its launch prefixes ({@link #PINNED}).
     */
    private record Pinned(Path tmp, Path src, String pkg, Path script) {
        private static final String NAV = "<processors name=\"core1\" description=\"CPU core 1: navigation.\" core=\"1\"";

        static Pinned of(Path tmp, String name, String to) throws Exception {
            return of(tmp, name, NAV, to);
        }

        static Pinned of(Path tmp, String name, String from, String to) throws Exception {
            String text = Files.readString(Tools.example("mobile-base-latency.rsaml"));
            assertTrue(text.contains(from), "the example has " + from);
            Path model = tmp.resolve(name + ".rsaml");
            Files.writeString(model, text.replace(from, to));
            Path src = tmp.resolve(name);
            new RsamlGenerator().generate(model, Target.ROS2, src, false);
            Path script = tmp.resolve("pinned.py");
            Files.writeString(script, PINNED);
            return new Pinned(tmp, src, Names.snake(ModelLoader.load(model, name + ".rsaml").architecture().getName()), script);
        }

        /** What the prefixes of launch file {@code <pkg><file>} print for host:=HOST: "process cpus [what it said]" a line. */
        String cpus(String file, String host) throws Exception {
            return Tools.ok(tmp, 120, Ros2Jazzy.bash("python3 '" + script + "' '" + src.resolve(pkg + "/launch/" + pkg + file) + "' '" + host + "' '"
                    + src.resolve(pkg + "/config/" + pkg + ".params.yaml") + "'").toArray(String[]::new));
        }
    }

    /** CPUs as Linux lists them ("0-3,6"). */
    private static java.util.TreeSet<Integer> cpuSet(String list) {
        java.util.TreeSet<Integer> cpus = new java.util.TreeSet<>();
        for (String part : list.split(",")) {
            String[] ends = part.split("-");
            for (int c = Integer.parseInt(ends[0]); c <= Integer.parseInt(ends[ends.length - 1]); c++) {
                cpus.add(c);
            }
        }
        return cpus;
    }

    /** CPUs as taskset and Linux list them: 0-3,6. */
    private static String cpuList(java.util.SortedSet<Integer> cpus) {
        StringBuilder out = new StringBuilder();
        Integer from = null;
        Integer to = null;
        for (int c : cpus) {
            if (to != null && c == to + 1) {
                to = c;
                continue;
            }
            if (from != null) {
                out.append(out.length() == 0 ? "" : ",").append(from.equals(to) ? "" + from : from + "-" + to);
            }
            from = c;
            to = c;
        }
        if (from != null) {
            out.append(out.length() == 0 ? "" : ",").append(from.equals(to) ? "" + from : from + "-" + to);
        }
        return out.toString();
    }

    /**
     * A build run as a background job (`./mvnw verify &`, `nohup`, a CI step in the background) starts
     * with SIGINT ignored, and an ignored signal stays ignored in everything it starts: `ros2 launch`
     * and its nodes would then never stop on the SIGINT with which the tests (and a user) end a run.
     * Every ROS 2 command of the tests starts with SIGINT at its default, whatever the build started with.
     */
    @Test
    void rosCommandsStopOnSigintEvenWhenTheBuildIgnoresIt(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        List<String> command = new ArrayList<>(List.of("bash", "-c", "trap '' INT; grep SigIgn /proc/self/status; exec \"$@\"", "background"));
        command.addAll(Ros2Jazzy.bash("grep SigIgn /proc/self/status"));
        String[] lines = Tools.ok(tmp, 60, command.toArray(String[]::new)).lines().filter(l -> l.startsWith("SigIgn:")).toArray(String[]::new);
        assertEquals(2, lines.length, () -> "expected the ignored signals of the background shell and of the ROS 2 command: " + String.join("\n", lines));
        long sigint = 1L << (2 - 1);
        assertTrue((Long.parseLong(lines[0].substring(7).trim(), 16) & sigint) != 0,
                () -> "the background shell of this test should ignore SIGINT, as a background job does: " + lines[0]);
        assertEquals(0, Long.parseLong(lines[1].substring(7).trim(), 16) & sigint,
                () -> "a ROS 2 command started from a build that ignores SIGINT ignores it too, so ros2 launch would never stop on it: " + lines[1]);
    }
}
