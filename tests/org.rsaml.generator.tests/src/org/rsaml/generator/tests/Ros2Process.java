/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A process of an installed executable of a generated ROS 2 package (with its arguments), started against ROS 2 Jazzy
 * on an isolated domain, its output in a log; killed with its descendants when closed.
 */
record Ros2Process(Process process, Path log) implements AutoCloseable {

    /**
     * Starts {@code executable} of package {@code pkg} from {@code install}, after the shell commands {@code setup}
     * (empty, or ending with {@code ;}), its output in {@code <tmp>/<name>.log}.
     */
    static Ros2Process start(Path tmp, Path install, int domain, String pkg, String executable, String setup, String name) throws Exception {
        Path log = tmp.resolve(name + ".log");
        ProcessBuilder pb = new ProcessBuilder(Ros2Jazzy.bash(setup + "exec \"$(ros2 pkg prefix " + pkg + ")/lib/" + pkg + "/\""
                + executable, install)).directory(tmp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
        Ros2Jazzy.isolate(pb.environment(), domain);
        return new Ros2Process(pb.start(), log);
    }

    String output() throws IOException {
        return Files.readString(log, StandardCharsets.UTF_8);
    }

    /** Waits (at most 120 s) until the output says {@code text}. */
    void await(String text) throws Exception {
        await(text, 1);
    }

    /** Waits (at most 120 s) until the output says {@code text} {@code times} times. */
    void await(String text, int times) throws Exception {
        awaitAfter(Pattern.compile(Pattern.quote(text)), 0, times);
    }

    /** Waits (at most 120 s) until the output matches {@code pattern} {@code times} times after {@code from}. */
    void awaitAfter(Pattern pattern, int from, int times) throws Exception {
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (true) {
            String o = output();
            Matcher m = pattern.matcher(o);
            int found = 0;
            int at = Math.max(from, 0);
            while (at <= o.length() && m.find(at)) {
                found++;
                at = m.end();
            }
            if (found >= times) {
                return;
            }
            if (!process.isAlive() || System.nanoTime() > until) {
                fail(log.getFileName() + ": did not say '" + pattern + "' " + times + " times within 120 s:\n" + Tools.last(o, 4000));
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
        String out = output();
        assertTrue(exited, () -> log.getFileName() + ": still running 30 s after SIGINT:\n" + Tools.last(out, 4000));
        return out;
    }

    @Override
    public void close() {
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        process.destroyForcibly();
    }
}
