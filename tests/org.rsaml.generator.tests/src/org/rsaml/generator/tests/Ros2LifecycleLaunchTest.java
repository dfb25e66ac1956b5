/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.internal.ros2.Ros2Shutdown;

/**
 * Managed (rclcpp_lifecycle) nodes of a generated package on a real ROS 2 ({@link Ros2Jazzy}), with
 * each launch file: brought to active by the package's lifecycle manager, and deactivated and
 * cleaned up by it when the launch stops; what the lifecycle manager and a node's process do when the
 * other side is gone; the package's programs given a wrong argument or parameter, and one whose node's own code throws.
 * The package is built once for the four tests; each says in the build's log how long it took (and the machine's load).
 */
class Ros2LifecycleLaunchTest {

    /**
     * Managed nodes (resources/ros2-lifecycle.rsaml: the lidar and the mapper managed, the monitor
     * plain), with each launch file: the package's lifecycle manager configures and activates them,
     * so that ROS 2 itself ({@code ros2 lifecycle get}) reports exactly them as lifecycle nodes, both
     * active; each traced configure, then activate; their messages flow (the mapper receives the
     * lidar's scans, the plain monitor the mapper's maps); on SIGINT the lifecycle manager deactivates
     * each, then cleans it up (traced by the node, seen by the manager) while the node's process waits
     * for it, and everything exits cleanly. ros2 lifecycle get is asked up to 5 times, a second apart, until it sees both
     * (discovery on a loaded machine). Each launch file gives the processes of the managed nodes the grace of two nodes and
     * ros2 launch's wait before SIGTERM beyond it, and the lifecycle manager says each node's deadline and how long each
     * bring-down took (printed, the margin against the deadline). {@code -Dtest=Ros2LifecycleLaunchTest} runs the class alone.
     */
    @Test
    void bothLaunchFilesBringTheManagedNodesToActive() throws Exception {
        Ros2Package b = built();
        Path src = b.src();
        Path install = b.install();
        String pkg = b.pkg();
        Map<String, String> nodes = b.nodes();
        List<String> managed = List.of("perception/lidar", "mapping/mapper");
        for (String file : List.of(pkg + ".launch.py", pkg + "_processes.launch.py")) {
            long started = System.nanoTime();
            Path log = tmp.resolve(file + ".log");
            ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash(Ros2Jazzy.launch(pkg + " " + file), install))
                    .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
            Ros2Jazzy.isolate(pb.environment(), DOMAIN);
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
                states = lifecycleStates(install, expectedStates(managed, nodes));
                Tools.ok(tmp, 10, "kill", "-INT", Long.toString(launch.pid()));
                boolean stopped = launch.waitFor(60, TimeUnit.SECONDS);
                String processes = stopped ? "" : Tools.run(tmp, 10, "bash", "-c", "ps -eo pid,ppid,stat,cls,rtprio,pcpu,args --forest | cut -c1-160"
                        + "; grep -E 'State|Sig' /proc/" + launch.pid() + "/status; uptime").output();
                String shown = Tools.last(processes, 6000);
                assertTrue(stopped, () -> file + ": ros2 launch did not stop within 60 s of SIGINT:\n" + tail(log) + "\n" + shown);
            } finally {
                launch.descendants().forEach(ProcessHandle::destroyForcibly);
                launch.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertEquals(0, launch.exitValue(), () -> file + ": ros2 launch exited with " + launch.exitValue() + ":\n" + Tools.last(out, 6000));
            assertEquals(expectedStates(managed, nodes), reported(states), file
                    + ": the lifecycle nodes and their states, as ros2 lifecycle get reports them:\n" + states);
            for (String m : managed) {
                int configured = out.indexOf("state " + m + " inactive");
                int active = out.indexOf("state " + m + " active");
                assertTrue(configured >= 0 && configured < active,
                        file + ": " + m + " was not configured before it was activated:\n" + Tools.last(out, 6000));
                // On SIGINT the lifecycle manager deactivates it, then cleans it up, while its process waits for that.
                int deactivated = out.indexOf("state " + m + " inactive", active);
                int cleaned = out.indexOf("state " + m + " unconfigured", Math.max(deactivated, 0));
                assertTrue(deactivated > active && cleaned > deactivated, file + ": on SIGINT, " + m
                        + " was not deactivated and then cleaned up:\n" + Tools.last(out, 6000));
                Matcher down = Pattern.compile(": " + Pattern.quote(nodes.get(m)) + " is unconfigured; down in (\\d+\\.\\d) ms").matcher(out);
                assertTrue(down.find(), file + ": the lifecycle manager did not see " + m
                        + " unconfigured, or did not say how long it took:\n" + Tools.last(out, 6000));
                // the margin against the deadline, for the build's log
                System.out.println("Ros2LifecycleLaunchTest: " + file + ": " + m + " down in " + down.group(1) + " ms of its "
                        + Ros2Shutdown.NODE_DEADLINE_MS + " ms");
            }
            // Each node its own deadline, the last one first; the processes' grace and launch's wait before SIGTERM cover them all.
            List<String> lastFirst = List.of(managed.get(1), managed.get(0));
            List<Integer> downs = lastFirst.stream().map(m -> out.indexOf(": bringing " + nodes.get(m) + " down within "
                    + Ros2Shutdown.NODE_DEADLINE_MS + " ms")).toList();
            assertTrue(downs.get(0) >= 0 && downs.get(1) > downs.get(0), () -> file + ": the lifecycle manager does not say it brings "
                    + lastFirst + " down in turn, each within " + Ros2Shutdown.NODE_DEADLINE_MS + " ms:\n" + Tools.last(out, 6000));
            String launchFile = Files.readString(src.resolve(pkg + "/launch/" + file), StandardCharsets.UTF_8);
            assertTrue(launchFile.contains("'" + Ros2Shutdown.GRACE_OPTION + "=" + Ros2Shutdown.graceMs(managed.size()) + "'")
                    && launchFile.contains("sigterm_timeout='" + Ros2Shutdown.sigtermTimeoutS(managed.size()) + "'"),
                    () -> file + ": the processes of the managed nodes are given the grace and the wait before SIGTERM of "
                            + managed.size() + " managed nodes:\n" + launchFile);
            assertFalse(out.contains("escalating to 'SIGTERM'"), () -> file + ": ros2 launch had to send SIGTERM:\n" + Tools.last(out, 6000));
            assertFalse(out.contains("no lifecycle manager deactivated it"), () -> file + ": a managed node was left configured:\n"
                    + Tools.last(out, 6000));
            assertFalse(out.contains("process has died"), () -> file + ": a process died:\n" + Tools.last(out, 6000));
            Map<String, double[]> ports = new TreeMap<>();
            Matcher p = Ros2LaunchTest.PORT.matcher(out);
            while (p.find()) {
                ports.put(p.group(1), new double[] {Long.parseLong(p.group(2))});
            }
            for (String port : List.of("mapping/mapper:scan", "supervision/monitor:map")) {
                assertTrue(ports.containsKey(port) && ports.get(port)[0] >= 5, file + ": hardly any message reached " + port + " ("
                        + (ports.containsKey(port) ? (long) ports.get(port)[0] : 0) + "):\n" + Tools.last(out, 6000));
            }
            took(file, started);
        }
    }

    /**
     * When one side of a managed node is gone, without the launch files (both cases at once, the first in a namespace of
     * its own): a node process whose lifecycle manager was killed says on SIGINT that its node was left active and exits;
     * and of two managed nodes, the process of the one brought down first killed, the lifecycle manager on SIGINT waits
     * that node's deadline out, says it was not cleaned up, still brings the other down within a deadline of its own
     * (whose process, given the grace of two nodes as the launch files give it, serves it meanwhile) and exits with 1.
     */
    @Test
    void aManagedNodeOrItsManagerGoneIsSaidAndNothingWaitsLong() throws Exception {
        Ros2Package b = built();
        long started = System.nanoTime();
        String pkg = b.pkg();
        String lidar = b.nodes().get("perception/lidar");
        String mapper = b.nodes().get("mapping/mapper");
        String orphans = " --ros-args -r __ns:=/orphaned";
        try (Ros2Process orphan = start(b.install(), pkg, lidar + orphans, "orphaned-node");
                Ros2Process orphanManager = start(b.install(), pkg, pkg + "_lifecycle_manager" + orphans + " -p node_names:=[" + lidar + "]",
                        "orphaned-node-manager");
                Ros2Process node = start(b.install(), pkg, lidar + " " + Ros2Shutdown.GRACE_OPTION + "=" + Ros2Shutdown.graceMs(2),
                        "lost-node");
                Ros2Process lost = start(b.install(), pkg, mapper, "lost-node-mapper");
                Ros2Process manager = start(b.install(), pkg, pkg + "_lifecycle_manager --ros-args -p node_names:=[" + lidar + ","
                        + mapper + "] -p node_deadline_ms:=" + Ros2Shutdown.NODE_DEADLINE_MS, "lost-node-manager")) {
            // The lifecycle manager killed: the node's process, on SIGINT, serves it a while, says it is left active and exits.
            orphan.await("state perception/lidar active");
            orphanManager.process().destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            orphan.signal();
            // The process of the node brought down first killed.
            manager.await(mapper + " is active");
            lost.process().destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            node.signal();
            manager.signal();
            String left = orphan.exited();
            assertTrue(left.contains("state perception/lidar active at exit: no lifecycle manager deactivated it"),
                    "a node left active says so at exit:\n" + Tools.last(left, 4000));
            assertEquals(0, orphan.process().exitValue(), () -> "the node's process exits cleanly:\n" + Tools.last(left, 4000));
            String out = manager.exited();
            int gone = out.indexOf(mapper + " did not say its state in time: it was not deactivated and cleaned up");
            assertTrue(gone >= 0, "the lifecycle manager says which node it could not bring down:\n" + Tools.last(out, 4000));
            assertTrue(out.indexOf(lidar + " is unconfigured", gone) > gone, "after waiting out the lost node's deadline, the"
                    + " lifecycle manager still brings the other node down:\n" + Tools.last(out, 4000));
            assertEquals(1, manager.process().exitValue(), () -> "the lifecycle manager fails:\n" + Tools.last(out, 4000));
            String served = node.exited();
            assertTrue(served.contains("state perception/lidar unconfigured") && !served.contains("no lifecycle manager deactivated it"),
                    "the other node's process served it until it was cleaned up:\n" + Tools.last(served, 4000));
            assertEquals(0, node.process().exitValue(), () -> "the other node's process exits cleanly:\n" + Tools.last(served, 4000));
        }
        took("a side gone", started);
    }

    /**
     * A wrong argument or parameter of a node's executable, the container or the lifecycle manager ends the program at
     * once with one line that names the program, the argument or parameter, what is wrong and how to fix it, and status 2:
     * an argument that is not a number, a parameter out of its range (-p), a parameter of the wrong type (a parameters
     * file, -p); never std::terminate. A component with a wrong parameter is not loaded into the container, which says
     * why (rclcpp_components) and stays.
     */
    @Test
    void aWrongArgumentOrParameterEndsTheProgramWithOneLine() throws Exception {
        Ros2Package b = built();
        long started = System.nanoTime();
        String pkg = b.pkg();
        String lidar = b.nodes().get("perception/lidar");
        String manager = pkg + "_lifecycle_manager";
        String container = pkg + "_component_container";
        Matcher declared = Pattern.compile("declare_parameter<double>\\(\"([\\w.]+\\.period_ms)\"").matcher(lidarBase(b));
        assertTrue(declared.find(), "the lidar node declares a period parameter");
        String period = declared.group(1);
        Path params = tmp.resolve("wrong-type.params.yaml");
        Files.writeString(params, "/**:\n  ros__parameters:\n    " + period + ": fast\n");
        String grace = Ros2Shutdown.GRACE_OPTION;
        assertWrong(b, lidar, lidar + " " + grace + "=soon", "argument " + grace + "=soon: not a whole number of milliseconds", grace + "=");
        assertWrong(b, container, container + " " + grace + "=-1", "argument " + grace + "=-1: not a whole number of milliseconds", grace + "=");
        assertWrong(b, lidar, lidar + " --ros-args --params-file " + params, "parameter '" + period + "' has invalid type",
                "params_file:=");
        assertWrong(b, lidar, lidar + " --ros-args -p " + period + ":=-5.0", "node " + lidar + ": parameter " + period + " is -5: it must be"
                + " a positive time", "set it so in the parameters file");
        assertWrong(b, lidar, lidar + " --ros-args -p rsaml.simulated_load:=1.5", "parameter rsaml.simulated_load is 1.5: it must be a fraction from 0 to 1",
                "simulated_load:=");
        assertWrong(b, manager, manager + " --ros-args -p node_deadline_ms:=0", "parameter node_deadline_ms is 0: it must be a positive",
                "node_deadline_ms:=");
        assertWrong(b, manager, manager + " --ros-args -p node_deadline_ms:=soon", "parameter 'node_deadline_ms' has invalid type", "-p");
        assertWrong(b, manager, manager + " --ros-args -p node_names:=[perception/1idar]", "parameter node_names: 'perception/1idar' is not"
                + " the name of a node", "-p node_names:=");
        // A component with a wrong parameter: the container does not load it, says why, and stays.
        try (Ros2Process running = start(b.install(), pkg, container + " --ros-args -r __node:=wrong_parameters_container",
                "wrong-parameters-container")) {
            String load = "ros2 component load --no-daemon /wrong_parameters_container " + pkg + " " + plugin(b)
                    + " -p rsaml.simulated_load:=3.0";
            Tools.Result loaded = null;
            for (int attempt = 1; attempt <= 5 && (loaded == null || !loaded.output().contains("Component constructor")); attempt++) {
                Thread.sleep(1000); // discovery of the container
                loaded = Tools.run(tmp, 60, Ros2Jazzy.bash("export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST ROS_DOMAIN_ID=" + DOMAIN + "; "
                        + load, b.install()).toArray(String[]::new));
            }
            String said = load + " said:\n" + Tools.last(loaded.output(), 4000);
            assertTrue(loaded.exit() != 0 && loaded.output().contains("Component constructor threw an exception: node /" + lidar
                    + ": parameter rsaml.simulated_load is 3: it must be a fraction from 0 to 1"), () -> "the container refuses the"
                    + " component and says why: " + said);
            assertTrue(running.process().isAlive(), () -> "the container stays: " + said);
            String out = running.stop();
            assertEquals(0, running.process().exitValue(), () -> "the container exits cleanly:\n" + Tools.last(out, 4000));
        }
        took("wrong arguments and parameters", started);
    }

    /**
     * An exception the nodes' own code lets escape is that code's error, not a wrong argument or parameter, even a
     * std::invalid_argument: the lidar's class (the architect's, made by {@link #built()} to read a calibration from its
     * environment with std::stoi, as a driver might) given a word throws one from its constructor. The program says so in a
     * line naming the exception's type and what(), as an error in the node's code, and aborts as an uncaught exception
     * makes a C++ program do: not status 2, not the line of a wrong argument.
     */
    @Test
    void anExceptionOfTheNodesOwnCodeIsNotTakenForAWrongArgument() throws Exception {
        Ros2Package b = built();
        long started = System.nanoTime();
        String lidar = b.nodes().get("perception/lidar");
        Tools.Result r = run(b, "export " + CALIBRATION + "=fine; ", lidar);
        String said = lidar + " with " + CALIBRATION + "=fine said:\n" + Tools.last(r.output(), 4000);
        assertTrue(r.exit() != 0 && r.exit() != 2, () -> "exited with " + r.exit() + ", not as a failed program (neither 0 nor 2,"
                + " the status of a wrong argument); " + said);
        List<String> lines = r.output().lines().filter(l -> l.startsWith(lidar + ": ")).toList();
        assertEquals(1, lines.size(), () -> "one line of the program, not " + lines.size() + "; " + said);
        assertTrue(lines.get(0).startsWith(lidar + ": uncaught std::invalid_argument: stoi; an error in the node's code")
                && lines.get(0).contains("not a wrong argument or parameter"), () -> "the line names the exception (its type and"
                        + " what()) as an error of the node's code, not a wrong argument; " + said);
        took("an exception of the node's code", started);
    }

    /**
     * Runs an executable of the package with a wrong argument or parameter: it must exit with 2 within 30 s, saying
     * "PROGRAM: ..." with {@code wrong} and {@code fix} in one line, and nothing else.
     */
    private static void assertWrong(Ros2Package b, String program, String command, String wrong, String fix) throws Exception {
        Tools.Result r = run(b, "", command);
        String said = command + " said:\n" + Tools.last(r.output(), 4000);
        assertFalse(r.output().contains("terminate called"), () -> "std::terminate: " + said);
        assertEquals(2, r.exit(), () -> command + " exited with " + r.exit() + ", not 2 (usage); " + said);
        List<String> lines = r.output().lines().filter(l -> !l.isBlank()).toList();
        assertEquals(1, lines.size(), () -> "one line, not " + lines.size() + "; " + said);
        String line = lines.get(0);
        assertTrue(line.startsWith(program + ": ") && line.contains(wrong) && line.contains(fix), () -> "the line names the program ("
                + program + "), what is wrong (" + wrong + ") and how to fix it (" + fix + "); " + said);
    }

    /** Runs an installed executable of the package (with its arguments) after {@code setup} (shell commands), at most 30 s. */
    private static Tools.Result run(Ros2Package b, String setup, String command) throws Exception {
        return Tools.run(tmp, 30, Ros2Jazzy.bash("export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST ROS_DOMAIN_ID=" + DOMAIN + "; " + setup
                + "\"$(ros2 pkg prefix " + b.pkg() + ")/lib/" + b.pkg() + "/\"" + command, b.install()).toArray(String[]::new));
    }

    /** The rclcpp component of the lidar node, as its registration names it. */
    private static String plugin(Ros2Package b) throws Exception {
        Path registration = b.src().resolve(b.pkg() + "/gen/perception/LidarComponent.cpp");
        Matcher m = Pattern.compile("RCLCPP_COMPONENTS_REGISTER_NODE\\(([\\w:]+)\\)").matcher(Files.readString(registration));
        assertTrue(m.find(), "the lidar node is registered as a component: " + registration);
        return m.group(1);
    }

    /** The generated base class of the lidar node. */
    private static String lidarBase(Ros2Package b) throws Exception {
        try (java.util.stream.Stream<Path> s = Files.walk(b.src().resolve(b.pkg() + "/gen"))) {
            for (Path p : s.filter(f -> f.toString().endsWith("Base.hpp")).toList()) {
                String text = Files.readString(p, StandardCharsets.UTF_8);
                if (text.contains("* Node " + b.nodes().get("perception/lidar") + ":")) {
                    return text;
                }
            }
        }
        return fail("no generated base class of the lidar node under " + b.src());
    }

    @TempDir
    static Path tmp;

    /** ROS 2's domain of this test's processes, apart from other tests' on the machine. */
    private static final int DOMAIN = 1 + (int) ((ProcessHandle.current().pid() + 50) % 100);

    private static Ros2Package built;

    /**
     * The package of resources/ros2-lifecycle.rsaml, generated (the lidar's class {@link #calibrated}) and built with colcon
     * once for every test of the class; the test is skipped, saying why, when there is no ROS 2 ({@link Ros2Jazzy#missing()}).
     */
    private static synchronized Ros2Package built() throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        if (built == null) {
            built = Ros2Package.of("resources/ros2-lifecycle.rsaml", tmp, "Ros2LifecycleLaunchTest",
                    folder -> calibrated(folder.resolve("src/perception/Lidar.hpp")));
        }
        return built;
    }

    /** The environment variable from which the lidar's class reads its calibration ({@link #calibrated}). */
    private static final String CALIBRATION = "LIDAR_CALIBRATION";

    /**
     * The architect's class of the lidar node, given a constructor that reads a calibration from the environment variable
     * {@link #CALIBRATION}, if set, with std::stoi (which throws std::invalid_argument on a word).
     */
    private static void calibrated(Path lidar) throws Exception {
        String text = Files.readString(lidar, StandardCharsets.UTF_8);
        String inherited = "  using LidarBase::LidarBase;\n";
        String include = "#include \"perception/LidarBase.hpp\"\n";
        assertTrue(text.contains(inherited) && text.contains(include), () -> "the lidar's class as generated: " + lidar + ":\n" + text);
        Files.writeString(lidar, text.replace(include, include + "\n#include <cstdlib>\n#include <string>\n").replace(inherited, """
                  explicit Lidar(const rclcpp::NodeOptions& options) : LidarBase(options) {
                    if (const char* calibration = std::getenv("%s")) {
                      calibration_ = std::stoi(calibration);
                    }
                  }

                 private:
                  int calibration_ = 0;

                 public:
                """.formatted(CALIBRATION)), StandardCharsets.UTF_8);
    }

    private static void took(String what, long startedNanos) {
        Tools.took("Ros2LifecycleLaunchTest", what, startedNanos);
    }

    /** What ros2 lifecycle get must report: each managed node active. */
    private static List<String> expectedStates(List<String> managed, Map<String, String> nodes) {
        return managed.stream().map(m -> "/" + nodes.get(m) + ": active [3]").sorted().toList();
    }

    /** The nodes and states in the output of ros2 lifecycle get. */
    private static List<String> reported(String states) {
        return states.lines().filter(l -> l.startsWith("/")).map(String::strip).sorted().toList();
    }

    /**
     * The output of {@code ros2 lifecycle get}, asked up to 5 times a second apart until it reports {@code expected}: on a
     * loaded machine discovery may not have seen every node within one call's spin time.
     */
    private static String lifecycleStates(Path install, List<String> expected) throws Exception {
        String states = "";
        for (int attempt = 1; attempt <= 5; attempt++) {
            states = Tools.ok(tmp, 60, Ros2Jazzy.bash("export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST ROS_DOMAIN_ID=" + DOMAIN
                    + "; ros2 lifecycle get --no-daemon --spin-time 3", install).toArray(String[]::new));
            if (reported(states).equals(expected)) {
                if (attempt > 1) {
                    System.out.println("Ros2LifecycleLaunchTest: ros2 lifecycle get saw every managed node at attempt " + attempt);
                }
                break;
            }
            Thread.sleep(1000);
        }
        return states;
    }

    /** The end of a log, for a failure's message. */
    private static String tail(Path log) {
        try {
            return Tools.last(Files.readString(log, StandardCharsets.UTF_8), 8000);
        } catch (java.io.IOException e) {
            return "(" + log + " unreadable: " + e.getMessage() + ")";
        }
    }

    private static Ros2Process start(Path install, String pkg, String executable, String name) throws Exception {
        return Ros2Process.start(tmp, install, DOMAIN, pkg, executable, "", name);
    }
}
