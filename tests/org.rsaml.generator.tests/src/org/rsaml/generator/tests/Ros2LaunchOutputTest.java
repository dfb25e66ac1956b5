/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every line a process writes reaches the output of {@code ros2 launch} as the tests start it ({@link Ros2Jazzy#launch}), once,
 * when launch takes SIGINT while it is behind with that process's output, as on a loaded machine: the lines a node writes
 * (one per miss) are counted against its summary ({@link Ros2LaunchTest}). The process writes numbered lines of a node's
 * trace, a hundred at a time as fast as launch takes them, launch is held back (SIGSTOP, SIGCONT) so that its lines wait in the pipe, and
 * it is sent SIGINT while held; the process then writes its last lines and the number it wrote. Started as a user starts it
 * ({@code ros2 launch}, Python's SIGINT handler raising KeyboardInterrupt), ROS 2's launch (Jazzy) repeated and lost lines in
 * each of three runs of this test on 2026-11-28 (99, 231 and 171 lines repeated; 0, 69 and 28 lost): the likely cause of
 * the ROS 2 runs of {@code ros2-edf} that had, twice under load, one {@code miss} line fewer than the summary's misses, and
 * of hierarchical-nasrem's 12 more once.
 */
class Ros2LaunchOutputTest {

    /** The process: numbered lines in batches until SIGINT, then 300 more and how many it wrote in all. */
    private static final String WRITER = """
            import signal, sys, time
            stop = []
            signal.signal(signal.SIGINT, lambda signum, frame: stop.append(signum))
            n = 0
            pad = 'x' * 120
            def lines(count):
                global n
                out = []
                for _ in range(count):
                    n += 1
                    out.append('[%10.3f ms] miss tasks/c.f released %d.496 ms not run (1 release): %s #%d\\n' % (n / 10, n, pad, n))
                sys.stdout.write(''.join(out))
                sys.stdout.flush()
            while not stop:
                lines(100)
                time.sleep(0.001)
            lines(300)
            sys.stdout.write('written %d\\n' % n)
            sys.stdout.flush()
            """;

    private static final Pattern NUMBERED = Pattern.compile(" #(\\d+)$", Pattern.MULTILINE);
    private static final Pattern WRITTEN = Pattern.compile("written (\\d+)$", Pattern.MULTILINE);

    @Test
    void everyLineOfAProcessReachesTheOutputOnceWhenLaunchTakesSigintBehindIt(@TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        Path writer = tmp.resolve("writer.py");
        Files.writeString(writer, WRITER);
        Path file = tmp.resolve("writer.launch.py");
        Files.writeString(file, "import sys\n\nfrom launch import LaunchDescription\nfrom launch.actions import ExecuteProcess\n\n\n"
                + "def generate_launch_description():\n    return LaunchDescription([ExecuteProcess(cmd=[sys.executable, '-u', '"
                + writer + "'], output='screen', name='writer')])\n");
        Path log = tmp.resolve("launch.log");
        ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash(Ros2Jazzy.launch("'" + file + "'"))).directory(tmp.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile());
        Ros2Jazzy.isolate(pb.environment(), 1 + (int) (ProcessHandle.current().pid() % 100));
        Process launch = pb.start();
        String pid = Long.toString(launch.pid());
        try {
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!NUMBERED.matcher(Files.readString(log, StandardCharsets.UTF_8)).find()) {
                assertTrue(launch.isAlive() && System.nanoTime() < until, "the process wrote nothing within 60 s:\n"
                        + Tools.last(Files.readString(log, StandardCharsets.UTF_8), 3000));
                Thread.sleep(100);
            }
            // launch held back, its process's lines waiting in the pipe, then SIGINT while it is held
            for (int i = 0; i < 12; i++) {
                Tools.ok(tmp, 10, "kill", "-STOP", pid);
                Thread.sleep(250);
                Tools.ok(tmp, 10, "kill", "-CONT", pid);
                Thread.sleep(50);
            }
            Tools.ok(tmp, 10, "kill", "-STOP", pid);
            Tools.ok(tmp, 10, "kill", "-INT", pid);
            Thread.sleep(500);
            Tools.ok(tmp, 10, "kill", "-CONT", pid);
            assertTrue(launch.waitFor(60, TimeUnit.SECONDS), "ros2 launch did not stop within 60 s of SIGINT");
        } finally {
            launch.descendants().forEach(ProcessHandle::destroyForcibly);
            launch.destroyForcibly();
        }
        String out = Files.readString(log, StandardCharsets.UTF_8);
        assertEquals(0, launch.exitValue(), () -> "ros2 launch exited with " + launch.exitValue() + ":\n" + Tools.last(out, 3000));
        assertTrue(out.contains("user interrupted with ctrl-c (SIGINT)") && out.contains("process has finished cleanly"),
                () -> "launch took SIGINT through its own handling and the process stopped on it:\n" + Tools.last(out, 3000));
        Matcher w = WRITTEN.matcher(out);
        assertTrue(w.find(), () -> "the process did not say how many lines it wrote:\n" + Tools.last(out, 3000));
        long written = Long.parseLong(w.group(1));
        Map<Long, Integer> seen = new TreeMap<>();
        Matcher m = NUMBERED.matcher(out);
        while (m.find()) {
            seen.merge(Long.parseLong(m.group(1)), 1, Integer::sum);
        }
        long lost = written - seen.size();
        long repeated = seen.values().stream().filter(c -> c > 1).count();
        System.out.println("Ros2LaunchOutputTest: " + written + " lines written, " + seen.size() + " seen, " + repeated + " more than once");
        assertTrue(lost == 0 && repeated == 0 && seen.keySet().stream().allMatch(n -> n >= 1 && n <= written), "of the " + written
                + " lines the process wrote, " + lost + " did not reach launch's output and " + repeated + " reached it more than once");
    }
}
