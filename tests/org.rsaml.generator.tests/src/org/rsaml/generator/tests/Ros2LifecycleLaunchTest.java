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

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.Names;
import org.rsaml.generator.internal.ros2.Ros2Shutdown;
import org.rsaml.model.Architecture;
import org.rsaml.validation.ModelLoader;

/**
 * Managed (rclcpp_lifecycle) nodes of a generated package on a real ROS 2 ({@link Ros2Jazzy}), with
 * each launch file: brought to active by the package's lifecycle manager, and deactivated and
 * cleaned up by it when the launch stops.
 */
class Ros2LifecycleLaunchTest {

    /**
     * Managed nodes (resources/ros2-lifecycle.rsaml: the lidar and the mapper managed, the monitor
     * plain), with each launch file: the package's lifecycle manager configures and activates them,
     * so that ROS 2 itself ({@code ros2 lifecycle get}) reports exactly them as lifecycle nodes, both
     * active; each traced configure, then activate; their messages flow (the mapper receives the
     * lidar's scans, the plain monitor the mapper's maps); on SIGINT the lifecycle manager deactivates
     * each, then cleans it up (traced by the node, seen by the manager) while the node's process waits
     * for it, and everything exits cleanly. Then, without the launch files, when one side of a
     * managed node is gone: a node process whose lifecycle manager was killed says on SIGINT that its
     * node was left active and exits, and a lifecycle manager whose node process was killed says on
     * SIGINT that the node was not cleaned up and exits with status 1 (neither waits for long); with two managed nodes, the
     * first of which to be brought down is gone, it waits that node's deadline out and still brings the other down within a
     * deadline of its own. Each launch file gives the processes of the managed nodes the grace of two nodes and ros2
     * launch's wait before SIGTERM beyond it, and the lifecycle manager says each node's deadline.
     * {@code -Dtest=Ros2LifecycleLaunchTest} runs it alone.
     */
    @Test
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
            // SIGINT at its default even where this test was started with it ignored (a background job): launch then ignores it.
            ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash("exec env --default-signal=INT ros2 launch " + pkg + " " + file, install))
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
            List<String> expected = managed.stream().map(m -> "/" + nodes.get(m) + ": active [3]").sorted().toList();
            List<String> reported = states.lines().filter(l -> l.startsWith("/")).map(String::strip).sorted().toList();
            assertEquals(expected, reported, file + ": the lifecycle nodes and their states, as ros2 lifecycle get reports them:\n" + states);
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
                assertTrue(out.contains(": " + nodes.get(m) + " is unconfigured"), file + ": the lifecycle manager did not see "
                        + m + " unconfigured:\n" + Tools.last(out, 6000));
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
        }
        String lidar = nodes.get("perception/lidar");
        // The lifecycle manager killed: the node's process, on SIGINT, serves it a while, says it is left active and exits.
        try (Started node = start(tmp, install, domain, pkg, lidar, "orphaned-node");
                Started manager = start(tmp, install, domain, pkg, pkg + "_lifecycle_manager --ros-args -p node_names:=[" + lidar + "]",
                        "orphaned-node-manager")) {
            node.await("state perception/lidar active");
            manager.process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            String out = node.stop();
            assertTrue(out.contains("state perception/lidar active at exit: no lifecycle manager deactivated it"),
                    "a node left active says so at exit:\n" + Tools.last(out, 4000));
            assertEquals(0, node.process.exitValue(), () -> "the node's process exits cleanly:\n" + Tools.last(out, 4000));
        }
        // Of two managed nodes, the process of the one brought down first killed: the lifecycle manager, on SIGINT, waits
        // that node's deadline out, says it was not cleaned up, still brings the other down within a deadline of its own
        // (whose process, given the grace of two nodes as the launch files give it, serves it meanwhile) and exits with 1.
        String mapper = nodes.get("mapping/mapper");
        try (Started node = start(tmp, install, domain, pkg, lidar + " " + Ros2Shutdown.GRACE_OPTION + "=" + Ros2Shutdown.graceMs(2),
                "lost-node");
                Started lost = start(tmp, install, domain, pkg, mapper, "lost-node-mapper");
                Started manager = start(tmp, install, domain, pkg, pkg + "_lifecycle_manager --ros-args -p node_names:=[" + lidar + ","
                        + mapper + "] -p node_deadline_ms:=" + Ros2Shutdown.NODE_DEADLINE_MS, "lost-node-manager")) {
            manager.await(mapper + " is active");
            lost.process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            node.signal();
            String out = manager.stop();
            int gone = out.indexOf(mapper + " did not say its state in time: it was not deactivated and cleaned up");
            assertTrue(gone >= 0, "the lifecycle manager says which node it could not bring down:\n" + Tools.last(out, 4000));
            assertTrue(out.indexOf(lidar + " is unconfigured", gone) > gone, "after waiting out the lost node's deadline, the"
                    + " lifecycle manager still brings the other node down:\n" + Tools.last(out, 4000));
            assertEquals(1, manager.process.exitValue(), () -> "the lifecycle manager fails:\n" + Tools.last(out, 4000));
            String served = node.exited();
            assertTrue(served.contains("state perception/lidar unconfigured") && !served.contains("no lifecycle manager deactivated it"),
                    "the other node's process served it until it was cleaned up:\n" + Tools.last(served, 4000));
            assertEquals(0, node.process.exitValue(), () -> "the other node's process exits cleanly:\n" + Tools.last(served, 4000));
        }
    }

    /** The end of a log, for a failure's message. */
    private static String tail(Path log) {
        try {
            return Tools.last(Files.readString(log, StandardCharsets.UTF_8), 8000);
        } catch (java.io.IOException e) {
            return "(" + log + " unreadable: " + e.getMessage() + ")";
        }
    }

    /** A process of an installed executable of the package (with its arguments), its output in a log; killed when closed. */
    private record Started(Process process, Path log) implements AutoCloseable {
        /** Waits (at most 120 s) until the output says {@code text}. */
        void await(String text) throws Exception {
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (!Files.readString(log, StandardCharsets.UTF_8).contains(text)) {
                String o = Files.readString(log, StandardCharsets.UTF_8);
                if (!process.isAlive() || System.nanoTime() > until) {
                    fail(log.getFileName() + ": did not say '" + text + "' within 120 s:\n" + Tools.last(o, 4000));
                }
                Thread.sleep(200);
            }
        }

        /** SIGINT, then its output once it exited (it must within 30 s). */
        String stop() throws Exception {
            signal();
            return exited();
        }

        /** Sends it SIGINT. */
        void signal() throws Exception {
            Tools.ok(log.getParent(), 10, "kill", "-INT", Long.toString(process.pid()));
        }

        /** Its output once it exited (it must within 30 s). */
        String exited() throws Exception {
            boolean exited = process.waitFor(30, TimeUnit.SECONDS);
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertTrue(exited, () -> log.getFileName() + ": still running 30 s after SIGINT:\n" + Tools.last(out, 4000));
            return out;
        }

        @Override
        public void close() {
            process.descendants().forEach(ProcessHandle::destroyForcibly);
            process.destroyForcibly();
        }
    }

    private static Started start(Path tmp, Path install, int domain, String pkg, String executable, String name) throws Exception {
        Path log = tmp.resolve(name + ".log");
        ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash("exec env --default-signal=INT \"$(ros2 pkg prefix " + pkg + ")/lib/" + pkg + "/\"" + executable,
                install))
                .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
        Ros2Jazzy.isolate(pb.environment(), domain);
        return new Started(pb.start(), log);
    }
}
