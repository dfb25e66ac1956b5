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
     * for it, and everything exits cleanly.
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
    }
}
