/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.ros2.Ros2Shutdown;

/**
 * The three times of bringing managed nodes down agree in the generated files: the lifecycle
 * manager's deadline per node, times its nodes, within the grace of their processes, within
 * {@code ros2 launch}'s wait before SIGTERM; and the runtime's values without the launch files' are
 * those of one node. (Ros2LifecycleLaunchTest shows them on a real ROS 2.)
 */
class Ros2ShutdownTest {

    private static final Pattern GRACE = Pattern.compile("arguments=\\['" + Pattern.quote(Ros2Shutdown.GRACE_OPTION)
            + "=(\\d+)'\\], sigterm_timeout='([0-9.]+)'");

    @Test
    void theManagersDeadlinesFitInTheProcessesGraceWhichFitsInLaunchsWaitBeforeSigterm(@TempDir Path tmp) throws Exception {
        // Two managed nodes (lidar, mapper) and a plain one (monitor), one container: one lifecycle manager of two nodes.
        Path src = tmp.resolve("src");
        new RsamlGenerator().generate(Ros2Test.model("resources/ros2-lifecycle.rsaml"), Target.ROS2, src, false);
        Path pkg = src.resolve("managed_robot");
        String composed = Files.readString(pkg.resolve("launch/managed_robot.launch.py"));
        String processes = Files.readString(pkg.resolve("launch/managed_robot_processes.launch.py"));
        int managed = 2;
        long grace = Ros2Shutdown.graceMs(managed);
        String sigterm = Ros2Shutdown.sigtermTimeoutS(managed);
        assertTrue(managed * Ros2Shutdown.NODE_DEADLINE_MS < grace && grace < Double.parseDouble(sigterm) * 1000,
                "n deadlines < the grace < the wait before SIGTERM: " + managed + " x " + Ros2Shutdown.NODE_DEADLINE_MS + ", " + grace
                        + ", " + sigterm);
        assertEquals(List.of("5000 7"), given(composed), "the container of the two managed nodes: a grace of 2 x 2 s + 1 s, SIGTERM"
                + " 2 s later:\n" + composed);
        assertEquals(List.of("5000 7", "5000 7"), given(processes), "each managed node's process (not the plain monitor's):\n" + processes);
        for (String launch : List.of(composed, processes)) {
            assertTrue(launch.contains("sigterm_timeout='7',\n") && launch.contains("'node_deadline_ms': 2000}]"),
                    "the lifecycle manager: 2 s per node, and launch's wait before SIGTERM as for its nodes' processes:\n" + launch);
        }
        Path runtime = pkg.resolve("gen/rsaml");
        String scheduling = Files.readString(runtime.resolve("scheduling.hpp"));
        assertTrue(scheduling.contains("GRACE_OPTION = \"" + Ros2Shutdown.GRACE_OPTION + "\";")
                && scheduling.contains("GRACE_WITHOUT_ARGUMENT_MS = " + Ros2Shutdown.graceMs(1) + ";"),
                "a process takes the launch files' option, and without it the grace of one node:\n" + scheduling);
        assertTrue(Files.readString(runtime.resolve("lifecycle_manager.cpp")).contains("NODE_DEADLINE_WITHOUT_PARAMETER_MS = "
                + Ros2Shutdown.NODE_DEADLINE_MS + ";"), "a lifecycle manager without node_deadline_ms gives each node the launch files' deadline");
        for (Path launch : List.of(pkg.resolve("launch/managed_robot.launch.py"), pkg.resolve("launch/managed_robot_processes.launch.py"))) {
            Tools.Result r = Tools.run(tmp, 60, "/usr/bin/python3", "-m", "py_compile", launch.toString());
            assertEquals(0, r.exit(), () -> launch.getFileName() + " is not valid Python:\n" + r.output());
        }
    }

    /** The grace and the wait before SIGTERM each action of a launch file is given, as "grace seconds". */
    private static List<String> given(String launch) {
        List<String> given = new ArrayList<>();
        Matcher m = GRACE.matcher(launch);
        while (m.find()) {
            given.add(m.group(1) + " " + m.group(2));
        }
        return given;
    }
}
