/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A real ROS 2 for the tests that build and run the generated packages: the installation a user
 * names (property {@code rsaml.ros2.setup} or environment variable {@code RSAML_ROS2_SETUP}: the
 * {@code setup.bash} of a ROS 2 installation), or else the ROS 2 Jazzy core archive of the shared
 * folder beside the repository ({@code ../shared/ros2/jazzy-core-debian12-amd64.tar.xz}, or the
 * archive property {@code rsaml.ros2.archive} names), unpacked once into target/. Colcon comes from
 * Debian ({@code colcon}, {@code python3-colcon-ros}: releng/prerequisites.txt). When neither is
 * there, {@link #missing()} says why, and the tests that need ROS 2 are skipped with that reason.
 */
final class Ros2Jazzy {
    private Ros2Jazzy() {
    }

    static final String ARCHIVE = "jazzy-core-debian12-amd64.tar.xz";

    private static Path setup;
    private static String missing;
    private static boolean said;

    /** The setup.bash to source, or null when there is no ROS 2 here (then {@link #missing()} says why). */
    static synchronized Path setup() throws Exception {
        if (setup != null || missing != null) {
            return setup;
        }
        String named = Tools.option("rsaml.ros2.setup");
        named = named.isBlank() ? System.getenv("RSAML_ROS2_SETUP") : named;
        if (named != null && !named.isBlank()) {
            Path p = Path.of(named);
            if (!Files.isRegularFile(p)) {
                missing = "rsaml.ros2.setup / RSAML_ROS2_SETUP names " + p + ", which is not a file (the setup.bash of a ROS 2 installation)";
            } else {
                setup = p;
            }
        } else {
            String given = Tools.option("rsaml.ros2.archive");
            Path archive = Path.of(given.isBlank() ? Tools.root().resolve("../shared/ros2/" + ARCHIVE).normalize().toString() : given);
            if (!Files.isRegularFile(archive)) {
                missing = "no ROS 2 here: " + archive + " is missing; point the tests at a ROS 2 installation with"
                        + " -Drsaml.ros2.setup=/opt/ros/jazzy/setup.bash (or RSAML_ROS2_SETUP)";
            } else {
                Path dir = Tools.root().resolve("tests/org.rsaml.generator.tests/target/ros2-jazzy");
                Path stamp = dir.resolve("archive.stamp");
                String id = archive.toAbsolutePath() + " " + Files.size(archive) + " " + Files.getLastModifiedTime(archive);
                if (!(Files.exists(stamp) && Files.readString(stamp).equals(id))) {
                    Tools.ok(Tools.root(), 60, "rm", "-rf", dir.toString());
                    Files.createDirectories(dir);
                    Tools.ok(dir, 600, "tar", "-xJf", archive.toString(), "-C", dir.toString());
                    Files.writeString(stamp, id);
                }
                setup = dir.resolve("install/setup.bash");
            }
        }
        if (setup != null && Tools.run(Tools.root(), 60, "bash", "-c", "PATH=/usr/bin:/bin:$PATH command -v colcon").exit() != 0) {
            missing = "colcon is not installed (Debian packages colcon and python3-colcon-ros, see releng/prerequisites.txt)";
            setup = null;
        }
        return setup;
    }

    /** Why there is no ROS 2, printed once per run; null when there is one. */
    static synchronized String missing() throws Exception {
        setup();
        if (missing != null && !said) {
            said = true;
            System.err.println("Ros2LaunchTest: skipped: " + missing);
        }
        return missing;
    }

    private static String launchTesting;

    /**
     * Why the packages' launch tests cannot run here (null when they can): ROS 2's launch_testing
     * (launch_testing_ament_cmake, which their CMakeLists.txt looks for under BUILD_TESTING) is not
     * installed. The ROS 2 Jazzy core of the shared folder does not have it; a full ROS 2 does.
     */
    static synchronized String launchTestingMissing() throws Exception {
        if (launchTesting == null) {
            Tools.Result r = Tools.run(Tools.root(), 60, bash("ros2 pkg prefix launch_testing_ament_cmake").toArray(String[]::new));
            launchTesting = r.exit() == 0 ? "" : "launch_testing is absent: 'ros2 pkg prefix launch_testing_ament_cmake' finds none in the"
                    + " ROS 2 of " + setup() + ", and no registry here has it (PyPI: no launch-testing or launch_testing; Debian 12: no"
                    + " python3-launch-testing or ros-jazzy-launch-testing; checked 2026-11-27): the packages' launch tests"
                    + " (test/test_<package>_launch.py) were not run; they run with colcon test on a ROS 2 that has it"
                    + " (-Drsaml.ros2.setup=/opt/ros/jazzy/setup.bash)";
        }
        return launchTesting.isEmpty() ? null : launchTesting;
    }

    /**
     * A bash command line run with ROS 2 sourced (and the workspaces {@code overlays}), Debian's
     * Python first on PATH (ROS 2's scripts and colcon use /usr/bin/python3). It starts with SIGINT at
     * its default disposition: a process started with SIGINT ignored keeps it ignored, and so does
     * everything it starts, so under a build run as a background job (`./mvnw ... &`, `nohup`, a CI
     * step in the background) {@code ros2 launch} and its nodes would never stop on the SIGINT the
     * tests send them.
     */
    static List<String> bash(String script, Path... overlays) throws Exception {
        StringBuilder sb = new StringBuilder("set -e; export PATH=/usr/bin:/bin:$PATH; unset AMENT_PREFIX_PATH CMAKE_PREFIX_PATH COLCON_PREFIX_PATH; ");
        sb.append("source '").append(setup()).append("'; ");
        for (Path o : overlays) {
            sb.append("source '").append(o.resolve("setup.bash")).append("'; ");
        }
        sb.append(script);
        return new ArrayList<>(List.of("env", "--default-signal=INT", "bash", "-c", sb.toString()));
    }

    /**
     * The shell command that starts {@code ros2 launch ARGUMENTS} (quoted for bash) as a user does, but with Python's
     * own SIGINT handler made harmless. ROS 2's launch (3.4.3, Jazzy) takes SIGINT through its own signal handling (it
     * then interrupts every process it started) and leaves Python's handler in place, so the same signal also raises
     * KeyboardInterrupt wherever its main thread is, and it ignores that exception. When that is in the middle of
     * writing out a process's lines, the line buffer of that process is left half read: its next output overwrites the
     * lines not yet written and the lines before are written again (Ros2LaunchOutputTest). A test that counts a node's
     * lines (one per miss) against its summary would then count lines lost or repeated by launch. The interpreter is
     * the one of the {@code ros2} script on PATH.
     */
    static String launch(String arguments) {
        return "exec $(sed -n '1s/^#!//p' \"$(command -v ros2)\") -c 'import signal, sys; signal.signal(signal.SIGINT, lambda signum, frame: None);"
                + " from ros2cli.cli import main; sys.argv[0] = \"ros2\"; sys.exit(main())' launch " + arguments;
    }

    /** Builds every package under {@code source} with colcon into {@code work}/install; fails with colcon's output. */
    static Path colconBuild(Path source, Path work) throws Exception {
        Path install = work.resolve("install");
        Tools.Result r = Tools.run(work, 1800, bash("colcon --log-base '" + work.resolve("log") + "' build --base-paths '" + source
                + "' --build-base '" + work.resolve("build") + "' --install-base '" + install
                + "' --cmake-args -DPython3_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release")
                .toArray(String[]::new));
        assertEquals(0, r.exit(), () -> "colcon build of " + source + " failed:\n" + Tools.last(r.output(), 8000));
        return install;
    }

    /** The environment of a launched system: discovery on the loopback only, a domain of its own. */
    static void isolate(Map<String, String> env, int domain) {
        env.put("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST");
        env.put("ROS_DOMAIN_ID", Integer.toString(domain));
        env.put("RCUTILS_COLORIZED_OUTPUT", "0");
        env.put("PYTHONUNBUFFERED", "1");
    }
}
