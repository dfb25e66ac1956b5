/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An EDF processor's nodes on a real ROS 2 ({@link Ros2Jazzy}), in the two cases where its release thread leaves or never
 * takes {@code SCHED_DEADLINE} (docs/timing.md, "EDF on ROS 2"): a managed node deactivated and activated again, and a
 * node on simulated time. The package of resources/ros2-edf-managed.rsaml is built once for both; each node is started
 * as its own program, without a launch file, and a managed node is moved through its states by ROS 2's own lifecycle
 * services ({@code ros2 service call <node>/change_state}). {@code -Dtest=Ros2ManagedEdfTest} runs the class alone.
 */
class Ros2ManagedEdfTest {

    private static final String A = "tasks/a";
    private static final String S = "tasks/s";
    /** A's period (ms), as modeled. */
    private static final long A_PERIOD_MS = 10;

    private static final Pattern AT = Pattern.compile("^\\[\\s*([0-9.]+) ms\\] (.*)$", Pattern.MULTILINE);

    /**
     * The managed node of an EDF processor (a: T 10 ms, D 8 ms, C 1 ms, no core, alone on the machine, so the kernel admits
     * its deadline thread): configured and activated, its release becomes a deadline thread and runs jobs; deactivated,
     * its release loop ends (the timer cancelled) and no job runs while it is inactive; activated again, the release asks
     * for {@code SCHED_DEADLINE} anew (a second {@code sched} line, granted) and its jobs resume; no job misses its
     * deadline, and the process exits cleanly on SIGINT. The jobs it counts are those of its active time alone: 2.5 s
     * inactive would be some 250 more.
     */
    @Test
    void aManagedEdfNodeStopsItsJobsWhenDeactivatedAndResumesThemWhenActivatedAgain() throws Exception {
        Ros2Package b = built();
        long started = System.nanoTime();
        String node = b.nodes().get(A);
        String out;
        try (Ros2Process p = Ros2Process.start(tmp, b.install(), DOMAIN, b.pkg(), node, "", "managed-edf")) {
            transition(b, node, 1, "configure");
            transition(b, node, 3, "activate");
            p.awaitAfter(Pattern.compile("sched " + Pattern.quote(A) + "\\.f (SCHED_DEADLINE|[^\\n]*instead of EDF)"), 0, 1);
            grantedOrSaid(edf(lines(p.output(), "sched " + A + ".f ")).get(0));
            Thread.sleep(1500);
            transition(b, node, 4, "deactivate");
            p.await("state " + A + " inactive", 2);
            Thread.sleep(2500);
            transition(b, node, 3, "activate");
            p.await("sched " + A + ".f SCHED_DEADLINE", 2);
            Thread.sleep(1500);
            out = p.stop();
            assertEquals(0, p.process().exitValue(), "the node's process exits cleanly on SIGINT:\n" + Tools.last(out, 4000));
        }
        String shown = Tools.last(out, 5000);
        List<String> sched = edf(lines(out, "sched " + A + ".f "));
        assertEquals(2, sched.size(), "one sched line of EDF's per activation, after the rank its thread starts at:\n" + shown);
        for (String s : sched) {
            assertTrue(s.contains("SCHED_DEADLINE runtime 1.000 ms deadline 8.000 ms period 10.000 ms") && !s.contains("instead of EDF"),
                    "each activation asks for SCHED_DEADLINE anew, and the kernel grants it: " + s + "\n" + shown);
        }
        double[] active = instants(out, "state " + A + " active", true);
        double[] inactive = instants(out, "state " + A + " inactive", true);
        assertTrue(active.length == 2 && inactive.length >= 2 && inactive[0] < active[0] && active[0] < inactive[1] && inactive[1] < active[1],
                "configured, activated, deactivated, activated again, in that order:\n" + shown);
        JobSummary summary = JobSummary.of(out).get(A + ".f");
        assertTrue(summary != null, "a summary of " + A + ".f at exit:\n" + shown);
        double end = instants(out, "summary " + A + ".f ", false)[0];
        double activeMs = (inactive[1] - active[0]) + (end - active[1]);
        long most = Math.round(activeMs / A_PERIOD_MS) + 3;
        long inactiveJobs = Math.round((active[1] - inactive[1]) / A_PERIOD_MS);
        assertTrue(summary.jobs() <= most && summary.jobs() >= most / 2, summary.jobs() + " jobs of " + A + ".f, expected about " + most
                + " in its " + Math.round(activeMs) + " ms active, and none in its " + Math.round(active[1] - inactive[1])
                + " ms inactive (some " + inactiveJobs + " more if it had gone on): " + summary + "\n" + shown);
        assertEquals(0, summary.misses(), "no job missed its deadline: " + summary + "\n" + shown);
        assertTrue(summary.sched().startsWith("SCHED_DEADLINE"), "its summary says SCHED_DEADLINE: " + summary);
        assertFalse(out.contains("miss " + A + ".f"), "no miss line:\n" + shown);
        System.out.println("Ros2ManagedEdfTest: " + A + ".f " + summary.jobs() + " jobs in " + Math.round(activeMs) + " ms active, none in "
                + Math.round(active[1] - inactive[1]) + " ms inactive; worst response " + JobTimingTest.ms(summary.worstNs()) + " of its 8 ms deadline");
        Tools.took("Ros2ManagedEdfTest", "deactivated and activated again", started);
    }

    /**
     * A node of an EDF processor on simulated time (use_sim_time, s: T 20 ms, C 1 ms), with a {@code /clock} publisher
     * running the simulation at half the machine's rate: its release stays timer-driven at its rank, saying
     * {@code instead of EDF: simulated time (use_sim_time) ...}, and releases its jobs at the simulation's rate (about one
     * every 40 ms of the machine's time, not every 20 ms as the kernel's periods would).
     */
    @Test
    void anEdfNodeOnSimulatedTimeKeepsItsReleasesTimerDriven() throws Exception {
        Ros2Package b = built();
        long started = System.nanoTime();
        String node = b.nodes().get(S);
        String out;
        long ranNs;
        Path clockLog = tmp.resolve("sim-clock.log");
        ProcessBuilder clockStart = new ProcessBuilder(Ros2Jazzy.bash("exec /usr/bin/python3 -c '" + CLOCK + "'", b.install()))
                .directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(clockLog.toFile());
        Ros2Jazzy.isolate(clockStart.environment(), DOMAIN);
        try (Ros2Process clock = new Ros2Process(clockStart.start(), clockLog);
                Ros2Process p = Ros2Process.start(tmp, b.install(), DOMAIN, b.pkg(), node + " --ros-args -p use_sim_time:=true", "", "sim-time")) {
            p.await("sched " + S + ".f ");
            long from = System.nanoTime();
            Thread.sleep(3000);
            ranNs = System.nanoTime() - from;
            out = p.stop();
            assertEquals(0, p.process().exitValue(), "the node's process exits cleanly on SIGINT:\n" + Tools.last(out, 4000));
            assertTrue(clock.process().isAlive(), "the /clock publisher ran throughout:\n" + Tools.last(clock.output(), 2000));
        }
        String shown = Tools.last(out, 5000);
        List<String> sched = edf(lines(out, "sched " + S + ".f "));
        assertEquals(1, sched.size(), "one sched line of EDF's, after the rank its thread starts at:\n" + shown);
        String how = sched.get(0).substring(("sched " + S + ".f ").length());
        // at its rank where real-time priorities are granted; without them (no CAP_SYS_NICE) at the default, failing only where CI requires them
        PlatformCheck.requireRealtime("Ros2ManagedEdfTest", S + ".f", how);
        assertTrue(how.contains("instead of EDF: simulated time (use_sim_time) releases its jobs, while SCHED_DEADLINE's periods are"
                + " the machine's") && (how.contains(" rank ") || how.startsWith("default")), "at its rank instead of EDF, saying why: " + sched.get(0));
        JobSummary summary = JobSummary.of(out).get(S + ".f");
        assertTrue(summary != null && summary.sched().contains("instead of EDF: simulated time"), "its summary says so: " + summary + "\n" + shown);
        // at the simulation's rate: 20 ms of simulated time every 40 ms of the machine's
        long machine = ranNs / 40_000_000L;
        assertTrue(summary.jobs() >= machine / 2 && summary.jobs() <= machine * 3 / 2 + 5, summary.jobs() + " jobs in "
                + JobTimingTest.ms(ranNs) + " of the machine's time, about " + machine + " at the simulation's half rate (twice as many by the"
                + " kernel's periods): " + summary + "\n" + shown);
        System.out.println("Ros2ManagedEdfTest: " + S + ".f on simulated time: " + summary.jobs() + " jobs in " + JobTimingTest.ms(ranNs)
                + ", " + sched.get(0));
        Tools.took("Ros2ManagedEdfTest", "simulated time", started);
    }

    /** A /clock publisher (rclpy): simulated time from 0, advanced 2.5 ms every 5 ms of the machine's time, half its rate. */
    private static final String CLOCK = String.join("\n", "import rclpy", "from rclpy.node import Node",
            "from rosgraph_msgs.msg import Clock", "rclpy.init()", "n = Node(\"rsaml_sim_clock\")",
            "pub = n.create_publisher(Clock, \"/clock\", 10)", "t = [0]",
            "def tick():", "    t[0] += 2500000", "    m = Clock()", "    m.clock.sec = t[0] // 1000000000",
            "    m.clock.nanosec = t[0] % 1000000000", "    pub.publish(m)",
            "n.create_timer(0.005, tick)", "rclpy.spin(n)");

    /**
     * The release loop this test is about runs only where the kernel grants {@code SCHED_DEADLINE} (CAP_SYS_NICE, the
     * test's JVM allowed on every CPU, the kernel's deadline admission control with room): where it refused, the test
     * fails under RSAML_TIMING_BOUNDS=required (CI demands the check) and otherwise is skipped, saying what the node said.
     */
    private static void grantedOrSaid(String sched) {
        if (!sched.contains("instead of EDF")) {
            return;
        }
        String why = A + ".f: the kernel refused SCHED_DEADLINE here (" + sched + "), so the EDF release loop whose deactivation this"
                + " test checks never runs: run the tests as root or with CAP_SYS_NICE, on every CPU";
        if (PlatformCheck.required()) {
            fail("RSAML_TIMING_BOUNDS=required (CI) demands the check: " + why);
        }
        Assumptions.abort(why);
    }

    /** The lines of {@code out} (the trace's text after its time) that begin with {@code prefix}. */
    private static List<String> lines(String out, String prefix) {
        List<String> found = new ArrayList<>();
        Matcher m = AT.matcher(out);
        while (m.find()) {
            if (m.group(2).startsWith(prefix)) {
                found.add(m.group(2));
            }
        }
        return found;
    }

    /** The sched lines that say what became of EDF (granted, or instead of it), not the rank a release thread starts at. */
    private static List<String> edf(List<String> sched) {
        return sched.stream().filter(l -> l.contains("SCHED_DEADLINE") || l.contains("instead of EDF")).toList();
    }

    /** The trace's times (ms since the process started) of the lines that are {@code text} ({@code whole}) or begin with it. */
    private static double[] instants(String out, String text, boolean whole) {
        List<Double> at = new ArrayList<>();
        Matcher m = AT.matcher(out);
        while (m.find()) {
            if (whole ? m.group(2).strip().equals(text) : m.group(2).startsWith(text)) {
                at.add(Double.parseDouble(m.group(1)));
            }
        }
        return at.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /**
     * Asks ROS 2's lifecycle service of {@code node} for transition {@code id} ({@code label}), up to 5 times (the service
     * may not be discovered yet on a loaded machine); fails unless it succeeded.
     */
    private static void transition(Ros2Package b, String node, int id, String label) throws Exception {
        String said = "";
        for (int attempt = 1; attempt <= 5; attempt++) {
            Tools.Result r = Tools.run(tmp, 60, Ros2Jazzy.bash("export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST ROS_DOMAIN_ID=" + DOMAIN
                    + "; timeout 20 ros2 service call /" + node + "/change_state lifecycle_msgs/srv/ChangeState '{transition: {id: " + id + "}}'",
                    b.install()).toArray(String[]::new));
            said = r.output();
            if (r.exit() == 0 && said.contains("success=True")) {
                return;
            }
            Thread.sleep(1000);
        }
        fail("the lifecycle service of " + node + " did not " + label + " it:\n" + Tools.last(said, 3000));
    }

    @TempDir
    static Path tmp;

    /** ROS 2's domain of this test's processes, apart from other tests' on the machine. */
    private static final int DOMAIN = 1 + (int) ((ProcessHandle.current().pid() + 70) % 100);

    private static Ros2Package built;

    /**
     * The package of resources/ros2-edf-managed.rsaml, generated and built with colcon once for both tests; the test is
     * skipped, saying why, when there is no ROS 2 ({@link Ros2Jazzy#missing()}).
     */
    private static synchronized Ros2Package built() throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        if (built == null) {
            built = Ros2Package.of("resources/ros2-edf-managed.rsaml", tmp, "Ros2ManagedEdfTest", folder -> {
            });
        }
        return built;
    }
}
