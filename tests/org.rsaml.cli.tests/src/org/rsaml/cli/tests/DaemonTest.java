/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.cli.daemon.Server;
import org.rsaml.tests.support.ChainModels;

/**
 * The resident process ({@code RSAML_DAEMON=1}, {@code rsaml daemon start|stop|status}), through the launcher as users
 * call it: a command it serves prints, writes and exits exactly as the same command in a JVM of its own; a model
 * changed on disk is read anew; a command no process serves runs in a JVM of its own, unchanged.
 */
class DaemonTest {

    /** The commands compared, run from a working directory holding copies of the models (relative paths). */
    private static final List<List<String>> COMMANDS = List.of(
            List.of("validate", "exp2-defects.rsaml"),
            List.of("validate", "--format", "json", "exp2-defects.rsaml"),
            List.of("validate", "--format", "sarif", "--output", "junit=reports/exp2.xml", "exp2-defects.rsaml"),
            List.of("validate", "--quiet", "--fail-on", "warning", "."),
            List.of("validate", "malformed.rsaml", "exp1-hybrid.rsaml"),
            List.of("validate", "nowhere.rsaml"),
            List.of("analyze", "exp1-hybrid.rsaml"),
            List.of("analyze", "--format", "json", "--timeline", "timelines", "mobile-base-latency-missed.rsaml"),
            List.of("generate", "--target", "cpp", "--output", "generated", "exp1-hybrid.rsaml"),
            List.of("generate", "--target", "ros2", "--output", "refused", "exp2-defects.rsaml"),
            List.of("valdate", "exp1-hybrid.rsaml"),
            List.of("validate", "--fromat", "json", "exp1-hybrid.rsaml"),
            List.of("--help"),
            List.of("validate", "--help"),
            List.of("rules"),
            List.of("--version"));

    @Test
    void servedCommandsPrintWriteAndExitAsInAJvmOfTheirOwn(@TempDir Path dir) throws Exception {
        withResident(dir, true, (runtime, work) -> {
            int served = served(runtime, work);
            for (List<String> command : COMMANDS) {
                Cli.Result own = launcher(runtime, work, false, command.toArray(String[]::new));
                Map<String, String> ownFiles = takeFiles(work);
                Cli.Result resident = launcher(runtime, work, true, command.toArray(String[]::new));
                Map<String, String> residentFiles = takeFiles(work);
                assertEquals(own.toString(), resident.toString(), () -> "rsaml " + String.join(" ", command));
                assertEquals(ownFiles, residentFiles, () -> "the files written by rsaml " + String.join(" ", command));
                assertEquals(++served, served(runtime, work), () -> "the resident process ran rsaml " + String.join(" ", command));
            }
        });
    }

    @Test
    void aModelChangedOnDiskIsReadAnew(@TempDir Path dir) throws Exception {
        withResident(dir, true, (runtime, work) -> {
            int served = served(runtime, work);
            Cli.Result before = launcher(runtime, work, true, "validate", "exp2-defects.rsaml");
            assertEquals(1, before.code(), before::toString);
            // Experiment 2 with its defects replaced by a clean model, in place, with the same name.
            Files.copy(work.resolve("exp1-hybrid.rsaml"), work.resolve("exp2-defects.rsaml"), StandardCopyOption.REPLACE_EXISTING);
            Cli.Result after = launcher(runtime, work, true, "validate", "exp2-defects.rsaml");
            Cli.Result own = launcher(runtime, work, false, "validate", "exp2-defects.rsaml");
            assertEquals(own.toString(), after.toString(), "the changed file as a JVM of its own reads it");
            assertEquals(0, after.code(), after::toString);
            assertNotEquals(before.out(), after.out());
            assertEquals(served + 2, served(runtime, work), "both runs were served by the resident process");
        });
    }

    @Test
    void withoutAResidentProcessTheCommandRunsInAJvmOfItsOwnAndOneIsStartedForTheNext(@TempDir Path dir) throws Exception {
        withResident(dir, false, (runtime, work) -> {
            Cli.Result own = launcher(runtime, work, false, "validate", "--format", "json", "exp2-defects.rsaml");
            Cli.Result fallback = launcher(runtime, work, true, "validate", "--format", "json", "exp2-defects.rsaml");
            assertEquals(own.toString(), fallback.toString(), "no resident process yet: the same run");
            Cli.Result status = awaitRunning(runtime, work);
            assertTrue(status.out().contains("rsaml: resident process "), status::toString);
            Cli.Result served = launcher(runtime, work, true, "validate", "--format", "json", "exp2-defects.rsaml");
            assertEquals(own.toString(), served.toString());
        });
        Cli.Result stopped = launcher(dir.resolve("run"), dir.resolve("work"), false, "daemon", "status");
        assertEquals(1, stopped.code(), stopped::toString);
        assertEquals("rsaml: no resident process running (a command at a terminal, RSAML_DAEMON=1 or 'rsaml daemon start' starts one)\n",
                stopped.out());
    }

    @Test
    void aRebuiltJarIsNotServedByTheProcessOfTheOldOneWhichStops(@TempDir Path dir) throws Exception {
        Path tree = ProcessTest.copyTree(dir.resolve("tree"));
        Path runtime = runtime(dir);
        try {
            assertEquals(0, launcher(tree, runtime, tree, false, "daemon", "start").code());
            long old = pid(launcher(tree, runtime, tree, false, "daemon", "status"));
            Cli.Result served = launcher(tree, runtime, tree, true, "validate", "examples/exp2-defects.rsaml");
            assertEquals(1, served.code(), served::toString);
            // As a build rewrites the jar: a new modification (and status-change) time.
            Path jar = tree.resolve("cli/org.rsaml.cli/target/rsaml.jar");
            Files.setLastModifiedTime(jar, FileTime.fromMillis(Files.getLastModifiedTime(jar).toMillis() + 2000));
            Cli.Result rebuilt = launcher(tree, runtime, tree, true, "validate", "examples/exp2-defects.rsaml");
            assertEquals(served.toString(), rebuilt.toString(), "the command ran, in a JVM of its own");
            String log = Files.readString(runtime.resolve("rsaml").resolve(socketName(runtime) + ".log"));
            assertTrue(log.contains("resident process stops: a command came with other settings"), log);
            long now = pid(awaitRunning(tree, runtime, tree));
            assertNotEquals(old, now, "a new resident process for the rebuilt jar");
            assertTrue(ProcessHandle.of(old).map(p -> !p.isAlive()).orElse(true), "the old process stopped");
        } finally {
            launcher(tree, runtime, tree, false, "daemon", "stop");
        }
    }

    @Test
    void theLanguageServerArgumentFilesAndUnknownVerbsAreNotSent(@TempDir Path dir) throws Exception {
        withResident(dir, true, (runtime, work) -> {
            Cli.Result usage = launcher(runtime, work, false, "daemon", "restart");
            assertEquals("usage: rsaml daemon start|stop|status (the resident process that commands at a terminal and RSAML_DAEMON=1 use)\n",
                    usage.err());
            assertEquals(2, usage.code(), usage::toString);
            int served = served(runtime, work);
            Cli.Result help = launcher(runtime, work, true, "language-server", "--help");
            assertEquals(launcher(runtime, work, false, "language-server", "--help").toString(), help.toString());
            // picocli reads an argument file from the process's working directory.
            Files.writeString(work.resolve("arguments.txt"), "validate\nexp2-defects.rsaml\n");
            Cli.Result file = launcher(runtime, work, true, "@arguments.txt");
            assertEquals(launcher(runtime, work, false, "@arguments.txt").toString(), file.toString());
            assertEquals(1, file.code(), file::toString);
            assertEquals(served, served(runtime, work), "declined: the language server talks on standard input, @FILE is"
                    + " read from the process's working directory");
        });
    }

    @Test
    void aSocketFolderOthersCanEnterIsNotUsed(@TempDir Path dir) throws Exception {
        withResident(dir, false, (runtime, work) -> {
            Path sockets = Files.createDirectory(runtime.resolve("rsaml"));
            Files.setPosixFilePermissions(sockets, PosixFilePermissions.fromString("rwxr-xr-x"));
            Cli.Result own = launcher(runtime, work, false, "validate", "exp2-defects.rsaml");
            Cli.Result refused = launcher(runtime, work, true, "validate", "exp2-defects.rsaml");
            assertEquals(own.code(), refused.code(), refused::toString);
            assertEquals(own.out(), refused.out());
            assertEquals("rsaml: RSAML_DAEMON=1 not in effect: " + sockets + " is not a folder of this user's that only this"
                    + " user can enter\n", refused.err());
            Thread.sleep(1000); // what a process started in the background would have written by now
            try (Stream<Path> files = Files.list(sockets)) {
                assertEquals(List.of(), files.toList(), "nothing written into the folder, no resident process started");
            }
        });
    }

    /**
     * A command whose client goes away while it runs (the client killed, or stopped by Ctrl-C's signal) is stopped: the
     * resident process stops working on it within a moment, writes none of its report files, and serves the next command
     * as a JVM of its own would.
     */
    @Test
    void aCommandWhoseClientGoesAwayIsStoppedAndTheProcessServesTheNext(@TempDir Path dir) throws Exception {
        withResident(dir, true, (runtime, work) -> {
            // Some 35 MB: seconds of reading and validating, also in a resident process with its code compiled.
            ChainModels.write(work.resolve("chain.rsaml"), 100_000, false);
            long pid = pid(launcher(runtime, work, false, "daemon", "status"));
            int served = served(runtime, work);
            Path log = runtime.resolve("rsaml").resolve(socketName(runtime) + ".log");
            int stopped = 0;
            for (String signal : List.of("KILL", "INT")) {
                List<String> command = new ArrayList<>(List.of("env", "-u", "RSAML_DAEMON", "XDG_RUNTIME_DIR=" + runtime,
                        "RSAML_DAEMON=1", Cli.ROOT.resolve("rsaml").toString(), "validate", "--output", "json=reports/chain.json",
                        "chain.rsaml"));
                Process launcher = new ProcessBuilder(command).directory(work.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                        .redirectError(ProcessBuilder.Redirect.DISCARD).start();
                try {
                    ProcessHandle client = awaitClient(launcher);
                    // The resident process is at work on the command: a second of its CPU since the command was sent.
                    long cpu = cpu(pid);
                    for (int i = 0; i < 600 && cpu(pid) < cpu + 1_000; i++) {
                        assertTrue(launcher.isAlive(), "the command ended before its client could be stopped: make the model larger");
                        Thread.sleep(50);
                    }
                    Process kill = new ProcessBuilder("kill", "-" + signal, Long.toString(client.pid())).start();
                    assertEquals(0, kill.waitFor());
                    assertTrue(launcher.waitFor(30, TimeUnit.SECONDS), "the launcher ends with its client");
                } finally {
                    launcher.destroyForcibly();
                }
                stopped++;
                String text = "";
                for (int i = 0; i < 100 && count(text, "after its client went away") < stopped; i++) {
                    Thread.sleep(100);
                    text = Files.readString(log);
                }
                String said = text;
                Matcher m = Pattern.compile("command (\\d+) stopped (\\d+) ms after its client went away").matcher(said);
                long ms = -1;
                while (m.find()) {
                    ms = Long.parseLong(m.group(2));
                }
                assertEquals(stopped, count(said, "after its client went away"), () -> "SIG" + signal + ": " + said);
                assertTrue(ms >= 0 && ms < Server.STOPPING.toMillis(), () -> "SIG" + signal + ": " + said);
                assertTrue(ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false), () -> "the process goes on: " + said);
                // Nothing of the stopped command's: no report, no temporary file beside one.
                assertEquals(Map.of(), takeFiles(work), "SIG" + signal);
                // Idle again: no more CPU spent on a command that nobody waits for. The JIT may still finish compiling
                // what the command ran hot for a moment: a quiet second within the next five, not a busy one each.
                boolean quiet = false;
                for (int second = 0; second < 5 && !quiet; second++) {
                    long idle = cpu(pid);
                    Thread.sleep(1000);
                    quiet = cpu(pid) - idle < 300;
                }
                assertTrue(quiet, () -> "SIG" + signal + ": the process still works: " + said);
            }
            Files.delete(work.resolve("chain.rsaml"));
            // The next command: served by the same process, as a JVM of its own runs it.
            Cli.Result own = launcher(runtime, work, false, "validate", "--format", "json", "exp2-defects.rsaml");
            Cli.Result next = launcher(runtime, work, true, "validate", "--format", "json", "exp2-defects.rsaml");
            assertEquals(own.toString(), next.toString());
            assertEquals(served + 3, served(runtime, work), "the two stopped commands and the next, all by one process");
            assertEquals(pid, pid(launcher(runtime, work, false, "daemon", "status")));
        });
    }

    /** The variables by which the launcher knows it runs in CI: none of them is set for a command typed at a terminal. */
    private static final List<String> CI = List.of("CI", "GITHUB_ACTIONS", "GITLAB_CI", "JENKINS_URL", "BUILDKITE", "TF_BUILD",
            "CIRCLECI", "TRAVIS", "TEAMCITY_VERSION", "BITBUCKET_BUILD_NUMBER", "CODEBUILD_BUILD_ID", "DRONE", "APPVEYOR",
            "SEMAPHORE", "BUILD_BUILDID");

    /** The line said, once per user, when a resident process is first started by default. */
    private static final String NOTICE = "rsaml: a resident process now keeps RsaML loaded for quicker commands at this terminal"
            + " (RSAML_DAEMON=0 turns it off; 'rsaml daemon stop' stops it; said once)\n";

    /**
     * Without RSAML_DAEMON, a resident process is used only for commands typed at a terminal (standard input and error
     * terminals) outside CI: a script's run, or one in CI even at a terminal, runs in a JVM of its own and starts none;
     * the first process started by default says so once, on standard error, and never again for this user; it stops
     * after 30 minutes unused and has a bounded heap (a process started on request: 3 hours, the JDK's default heap).
     */
    @Test
    void byDefaultOnlyACommandAtATerminalOutsideCiUsesOneWhichIsSaidOnce(@TempDir Path dir) throws Exception {
        withResident(dir, false, (runtime, work) -> {
            Path state = dir.resolve("state");
            Cli.Result own = launcher(runtime, work, false, "validate", "exp2-defects.rsaml");
            assertEquals("", own.err(), own::toString);
            // A script's run: standard input and error are pipes.
            Cli.Result script = Cli.process(work, defaults(runtime, state, List.of(), "validate", "exp2-defects.rsaml"));
            assertEquals(own.toString(), script.toString());
            for (String ci : List.of("CI=true", "GITHUB_ACTIONS=true", "RSAML_DAEMON=0")) {
                Cli.Result atTerminal = terminal(work, defaults(runtime, state, List.of(ci), "validate", "exp2-defects.rsaml"));
                assertEquals(new Cli.Result(own.code(), own.out(), "").toString(), atTerminal.toString(), ci);
            }
            Thread.sleep(2000); // what a process started in the background would have made by now
            assertTrue(!Files.exists(runtime.resolve("rsaml")), "no resident process, no socket folder");
            assertEquals(1, launcher(runtime, work, false, "daemon", "status").code());
            assertTrue(!Files.exists(state), "nothing said, nothing remembered");

            // Typed at a terminal, outside CI: the command runs in a JVM of its own and starts one for the next, saying so.
            Cli.Result first = terminal(work, defaults(runtime, state, List.of(), "validate", "exp2-defects.rsaml"));
            assertEquals(new Cli.Result(own.code(), NOTICE + own.out(), "").toString(), first.toString());
            Cli.Result status = awaitRunning(runtime, work);
            assertTrue(status.out().contains("\nrsaml: started by default for a terminal (RSAML_DAEMON=0 turns that off); stops"
                    + " after 30 minutes without a command; heap at most "), status::toString);
            assertTrue(heap(status) <= 1024, status::toString);
            int served = served(runtime, work);
            Cli.Result next = terminal(work, defaults(runtime, state, List.of(), "validate", "exp2-defects.rsaml"));
            assertEquals(new Cli.Result(own.code(), own.out(), "").toString(), next.toString(), "served, nothing said");
            assertEquals(served + 1, served(runtime, work));
            // Stopped, the next command at a terminal starts another: the notice is not said again.
            stop(runtime, work);
            Cli.Result again = terminal(work, defaults(runtime, state, List.of(), "validate", "exp2-defects.rsaml"));
            assertEquals(new Cli.Result(own.code(), own.out(), "").toString(), again.toString(), "said once");
            awaitRunning(runtime, work);
            stop(runtime, work);
            // Started on request: the longer idle time and the JDK's default heap (a quarter of this machine's memory).
            assertEquals(0, launcher(runtime, work, false, "daemon", "start").code());
            Cli.Result requested = launcher(runtime, work, false, "daemon", "status");
            assertTrue(requested.out().contains("\nrsaml: started on request; stops after 3 hours without a command; heap at most "),
                    requested::toString);
            long memory = ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean()).getTotalMemorySize();
            if (memory >= 8L << 30) {
                assertTrue(heap(requested) > 1024, requested::toString);
            }
        });
    }

    /**
     * A wrong setting of the resident process (RSAML_DAEMON, RSAML_DAEMON_IDLE, RSAML_DAEMON_HEAP) is said, naming the
     * variable and how to set it, and the command does not run; no process is started, nothing is remembered as said.
     */
    @Test
    void aWrongResidentProcessSettingIsSaidAndNothingRuns(@TempDir Path dir) throws Exception {
        withResident(dir, false, (runtime, work) -> {
            Path state = dir.resolve("state");
            Map<String, String> wrong = Map.of(
                    "RSAML_DAEMON_IDLE=30m", "rsaml: RSAML_DAEMON_IDLE='30m' is not a whole number of seconds",
                    "RSAML_DAEMON_HEAP=lots", "rsaml: RSAML_DAEMON_HEAP='lots' is not a heap size as -Xmx takes it",
                    "RSAML_DAEMON=yes", "rsaml: RSAML_DAEMON='yes' is neither 0 (never the resident process) nor 1 (always)");
            for (Map.Entry<String, String> setting : wrong.entrySet()) {
                List<String> command = defaults(runtime, state, List.of(setting.getKey()), "validate", "--output",
                        "json=report.json", "exp2-defects.rsaml");
                Cli.Result piped = Cli.process(work, command);
                assertEquals(2, piped.code(), piped::toString);
                assertEquals("", piped.out(), piped::toString);
                assertTrue(piped.err().startsWith(setting.getValue()) && piped.err().lines().count() == 1, piped::toString);
                Cli.Result typed = terminal(work, command);
                assertEquals(2, typed.code(), typed::toString);
                assertTrue(typed.out().strip().startsWith(setting.getValue()), typed::toString);
                assertTrue(!Files.exists(work.resolve("report.json")), "the command did not run: " + setting.getKey());
            }
            Thread.sleep(2000); // what a process started in the background would have made by now
            assertTrue(!Files.exists(runtime.resolve("rsaml")), "no resident process, no socket folder");
            assertTrue(!Files.exists(state), "nothing said, nothing remembered");
        });
    }

    /**
     * A process started by default stops after its idle time (here a few seconds) without a command; its heap is
     * bounded unless RSAML_JAVA_OPTS says otherwise.
     */
    @Test
    void aProcessStartedByDefaultStopsWhenIdleAndRsamlJavaOptsSetsItsHeap(@TempDir Path dir) throws Exception {
        withResident(dir, false, (runtime, work) -> {
            Path state = dir.resolve("state");
            List<String> settings = List.of("RSAML_DAEMON_IDLE=6", "RSAML_JAVA_OPTS=-Xmx1500m");
            Cli.Result first = terminal(work, defaults(runtime, state, settings, "validate", "exp2-defects.rsaml"));
            assertEquals(1, first.code(), first::toString);
            Cli.Result status = awaitRunning(runtime, work);
            assertTrue(status.out().contains("started by default for a terminal (RSAML_DAEMON=0 turns that off); stops after 6"
                    + " seconds without a command; heap at most "), status::toString);
            assertTrue(heap(status) > 1024, () -> "RSAML_JAVA_OPTS's heap, not the default bound: " + status);
            Path log = runtime.resolve("rsaml").resolve(socketName(runtime) + ".log");
            long pid = pid(status);
            // Started from a terminal, it does not keep the start's ignored SIGHUP and SIGINT: either stops it, as any JVM.
            Matcher ignored = Pattern.compile("(?m)^SigIgn:\\s*([0-9a-f]+)$")
                    .matcher(Files.readString(Path.of("/proc/" + pid + "/status")));
            assertTrue(ignored.find(), "the process's signal dispositions");
            assertEquals(0, Long.parseLong(ignored.group(1), 16) & 0b11, "SIGHUP and SIGINT ignored by the resident process");
            for (int i = 0; i < 120 && ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false); i++) {
                Thread.sleep(250);
            }
            String said = Files.readString(log);
            assertTrue(said.contains("rsaml: resident process stops after 6 seconds without a command"), said);
            assertTrue(ProcessHandle.of(pid).map(p -> !p.isAlive()).orElse(true), said);
        });
    }

    /**
     * A command the resident process cannot serve as a JVM of its own would (here one that needs more than its small
     * heap) runs in a JVM of its own instead: the same output, files and exit code, nothing of the first attempt.
     */
    @Test
    void aCommandTooLargeForTheProcesssHeapRunsInAJvmOfItsOwnWithTheSameResult(@TempDir Path dir) throws Exception {
        Path work = models(dir);
        Path runtime = runtime(dir);
        // As text, some 450 KB: within a sixteenth of the heap, so sent, but more than 32 MB of heap to load and check.
        ChainModels.write(work.resolve("chain.rsaml"), 4000, false);
        assertEquals(0, launcher(runtime, work, false, "convert", "chain.rsaml", "chain.rsa").code());
        Files.delete(work.resolve("chain.rsaml"));
        try {
            Cli.Result started = Cli.process(work, List.of("env", "-u", "RSAML_DAEMON", "XDG_RUNTIME_DIR=" + runtime,
                    "RSAML_DAEMON_HEAP=24m", Cli.ROOT.resolve("rsaml").toString(), "daemon", "start"));
            assertEquals(0, started.code(), started::toString);
            long pid = pid(launcher(runtime, work, false, "daemon", "status"));
            Cli.Result own = launcher(runtime, work, false, "validate", "--output", "json=reports/chain.json", "chain.rsa");
            Map<String, String> ownFiles = takeFiles(work);
            assertEquals(0, own.code(), own::toString);
            Cli.Result resident = launcher(runtime, work, true, "validate", "--output", "json=reports/chain.json", "chain.rsa");
            assertEquals(own.toString(), resident.toString());
            assertEquals(ownFiles, takeFiles(work));
            String log = Files.readString(runtime.resolve("rsaml").resolve(socketName(runtime) + ".log"));
            // Either the process found the command near its heap's limit, or the JVM's own OutOfMemoryError ended it.
            boolean near = log.contains("rsaml: command 2 found this process's heap too small (");
            boolean ended = log.contains("OutOfMemoryError") && ProcessHandle.of(pid).map(p -> !p.isAlive()).orElse(true);
            assertTrue(near || ended, log);
            // A command that fits is still served (by a new process, if the error ended the first).
            awaitRunning(runtime, work);
            Cli.Result small = launcher(runtime, work, false, "validate", "exp2-defects.rsaml");
            int served = served(runtime, work);
            assertEquals(small.toString(), launcher(runtime, work, true, "validate", "exp2-defects.rsaml").toString());
            assertEquals(served + 1, served(runtime, work));

            // A generation that runs out of the small heap half-way: run again in a JVM of its own, it writes and counts
            // every file as it would have alone (none found already written by the first attempt).
            stop(runtime, work);
            assertEquals(0, Cli.process(work, List.of("env", "-u", "RSAML_DAEMON", "XDG_RUNTIME_DIR=" + runtime,
                    "RSAML_DAEMON_HEAP=32m", Cli.ROOT.resolve("rsaml").toString(), "daemon", "start")).code());
            long generating = pid(launcher(runtime, work, false, "daemon", "status"));
            ChainModels.write(work.resolve("chain.rsaml"), 4000, false);
            Cli.Result ownGeneration = launcher(runtime, work, false, "generate", "--target", "cpp", "--output", "generated", "chain.rsaml");
            assertTrue(ownGeneration.out().contains(" written, 0 unchanged, 0 of yours kept"), ownGeneration::toString);
            Map<String, String> generated = takeFiles(work);
            Cli.Result residentGeneration = launcher(runtime, work, true, "generate", "--target", "cpp", "--output", "generated",
                    "chain.rsaml");
            assertEquals(ownGeneration.toString(), residentGeneration.toString());
            assertEquals(generated, takeFiles(work));
            String after = Files.readString(runtime.resolve("rsaml").resolve(socketName(runtime) + ".log"));
            assertTrue(after.contains("found this process's heap too small") || after.contains("OutOfMemoryError")
                    && ProcessHandle.of(generating).map(p -> !p.isAlive()).orElse(true), after);
        } finally {
            stop(runtime, work);
        }
    }

    /**
     * Only model files count toward the size above which the resident process sends a command to a JVM of its own (a
     * sixteenth of its heap): a folder's large log and its hidden folders do not, nor a large file named that is not a
     * model, and the command is served; a model larger than that, named or found in a folder, is not, and runs in a JVM of
     * its own with the same result.
     */
    @Test
    void onlyModelFilesCountTowardTheSizeTheResidentProcessServes(@TempDir Path dir) throws Exception {
        Path work = models(dir);
        Path runtime = runtime(dir);
        // A valid model of some 6 MB: experiment 1 with a long comment, quick to read and check.
        String hybrid = Files.readString(work.resolve("exp1-hybrid.rsaml"));
        int afterDeclaration = hybrid.indexOf("?>") + 2;
        String padded = hybrid.substring(0, afterDeclaration) + "\n<!-- " + "padding ".repeat(750_000) + "-->" + hybrid.substring(afterDeclaration);
        Path small = Files.createDirectories(work.resolve("small"));
        Files.copy(work.resolve("exp1-hybrid.rsaml"), small.resolve("exp1-hybrid.rsaml"));
        Files.writeString(small.resolve("run.log"), "x".repeat(8_000_000));
        Files.createDirectories(small.resolve(".history"));
        Files.writeString(small.resolve(".history").resolve("old.rsaml"), padded);
        Path large = Files.createDirectories(work.resolve("large"));
        Files.writeString(large.resolve("padded.rsaml"), padded);
        try {
            // 64 MiB of heap: a sixteenth is 4 MiB, below the padded model's 6 MB and above every model that is not padded.
            Cli.Result started = Cli.process(work, List.of("env", "-u", "RSAML_DAEMON", "XDG_RUNTIME_DIR=" + runtime,
                    "RSAML_DAEMON_HEAP=64m", Cli.ROOT.resolve("rsaml").toString(), "daemon", "start"));
            assertEquals(0, started.code(), started::toString);
            assertTrue(heap(launcher(runtime, work, false, "daemon", "status")) <= 64);
            List<List<String>> served = List.of(List.of("validate", "small"),
                    List.of("validate", "small/run.log"));
            List<List<String>> declined = List.of(List.of("validate", "large/padded.rsaml"), List.of("validate", "large"),
                    List.of("validate", "small", "large"));
            for (List<String> command : served) {
                int before = served(runtime, work);
                Cli.Result own = launcher(runtime, work, false, command.toArray(String[]::new));
                Cli.Result resident = launcher(runtime, work, true, command.toArray(String[]::new));
                assertEquals(own.toString(), resident.toString(), () -> "rsaml " + String.join(" ", command));
                assertEquals(before + 1, served(runtime, work), () -> "served: rsaml " + String.join(" ", command));
            }
            for (List<String> command : declined) {
                int before = served(runtime, work);
                Cli.Result own = launcher(runtime, work, false, command.toArray(String[]::new));
                Cli.Result resident = launcher(runtime, work, true, command.toArray(String[]::new));
                assertEquals(own.toString(), resident.toString(), () -> "rsaml " + String.join(" ", command));
                assertEquals(0, own.code(), own::toString);
                assertEquals(before, served(runtime, work), () -> "run in a JVM of its own: rsaml " + String.join(" ", command));
            }
        } finally {
            stop(runtime, work);
        }
    }

    /** {@code rsaml args...} as run without RSAML_DAEMON, outside CI, with the given extra variables. */
    private static List<String> defaults(Path runtime, Path state, List<String> variables, String... args) {
        List<String> command = new ArrayList<>(List.of("env", "-u", "RSAML_DAEMON", "-u", "RSAML_DAEMON_IDLE", "-u",
                "RSAML_DAEMON_HEAP", "-u", "RSAML_JAVA_OPTS"));
        for (String name : CI) {
            command.addAll(List.of("-u", name));
        }
        command.addAll(List.of("XDG_RUNTIME_DIR=" + runtime, "XDG_STATE_HOME=" + state));
        command.addAll(variables);
        command.add(Cli.ROOT.resolve("rsaml").toString());
        command.addAll(List.of(args));
        return command;
    }

    /**
     * {@code command} with a terminal for its standard input, output and error (util-linux {@code script}), as typed at
     * one: what it wrote on either, in the order written, is the result's output.
     */
    private static Cli.Result terminal(Path work, List<String> command) throws Exception {
        StringBuilder line = new StringBuilder("exec");
        for (String word : command) {
            line.append(" '").append(word.replace("'", "'\\''")).append('\'');
        }
        Cli.Result result = Cli.process(work, List.of("script", "--quiet", "--return", "--command", line.toString(), "/dev/null"));
        assertEquals("", result.err(), result::toString);
        return new Cli.Result(result.code(), result.out().replace("\r\n", "\n"), "");
    }

    /** The heap a resident process's status names, in MiB. */
    private static long heap(Cli.Result status) {
        Matcher m = Pattern.compile("heap at most (\\d+) MiB").matcher(status.out());
        assertTrue(m.find(), status::toString);
        return Long.parseLong(m.group(1));
    }

    /** The client's JVM, once the launcher has started it. */
    private static ProcessHandle awaitClient(Process launcher) throws InterruptedException {
        for (int i = 0; i < 600; i++) {
            var client = launcher.descendants().filter(p -> p.info().commandLine().orElse("").contains("org.rsaml.cli.daemon.Client"))
                    .findFirst();
            if (client.isPresent()) {
                return client.get();
            }
            assertTrue(launcher.isAlive(), "the launcher ended before its client started");
            Thread.sleep(50);
        }
        throw new AssertionError("the launcher started no client");
    }

    /** The CPU time (user and system) of process {@code pid} so far, in milliseconds. */
    private static long cpu(long pid) throws IOException {
        String[] fields = Files.readString(Path.of("/proc", Long.toString(pid), "stat")).replaceFirst(".*\\) ", "").split(" ");
        // After the name: state is field 3 of stat, utime 14 and stime 15, in clock ticks (100 a second on Linux).
        return (Long.parseLong(fields[11]) + Long.parseLong(fields[12])) * 10;
    }

    private static int count(String text, String part) {
        int n = 0;
        for (int at = text.indexOf(part); at >= 0; at = text.indexOf(part, at + 1)) {
            n++;
        }
        return n;
    }

    /** What a test does with a runtime folder and a working directory of models. */
    private interface WithResident {
        void run(Path runtime, Path work) throws Exception;
    }

    /** Runs {@code test} in {@code dir}, a resident process started first if asked, and stopped after in any case. */
    private static void withResident(Path dir, boolean start, WithResident test) throws Exception {
        Path work = models(dir);
        Path runtime = runtime(dir);
        try {
            if (start) {
                Cli.Result started = launcher(runtime, work, false, "daemon", "start");
                assertEquals(0, started.code(), started::toString);
            }
            test.run(runtime, work);
        } finally {
            stop(runtime, work);
        }
    }

    /** A working directory with copies of the examples and of some bad inputs. */
    private static Path models(Path dir) throws IOException {
        Path work = Files.createDirectories(dir.resolve("work"));
        for (String example : List.of("exp1-hybrid.rsaml", "exp2-defects.rsaml", "mobile-base-latency-missed.rsaml")) {
            Files.copy(Cli.ROOT.resolve("examples").resolve(example), work.resolve(example));
        }
        Files.copy(Cli.INPUTS.resolve("malformed.rsaml"), work.resolve("malformed.rsaml"));
        return work;
    }

    /** The user's runtime folder of these tests (XDG_RUNTIME_DIR): their resident processes' sockets are there. */
    private static Path runtime(Path dir) throws IOException {
        return Files.createDirectory(dir.resolve("run"), PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
    }

    private static Cli.Result launcher(Path runtime, Path work, boolean daemon, String... args) throws Exception {
        return launcher(Cli.ROOT, runtime, work, daemon, args);
    }

    /** {@code tree/rsaml args...} in {@code work}, with or without {@code RSAML_DAEMON=1}. */
    private static Cli.Result launcher(Path tree, Path runtime, Path work, boolean daemon, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of("env", "-u", "RSAML_DAEMON", "XDG_RUNTIME_DIR=" + runtime));
        if (daemon) {
            command.add("RSAML_DAEMON=1");
        }
        command.add(tree.resolve("rsaml").toString());
        command.addAll(List.of(args));
        return Cli.process(work, command);
    }

    /** How many commands the resident process has run. */
    private static int served(Path runtime, Path work) throws Exception {
        Cli.Result status = launcher(runtime, work, false, "daemon", "status");
        Matcher m = Pattern.compile(", (\\d+) commands run,").matcher(status.out());
        assertTrue(m.find(), status::toString);
        return Integer.parseInt(m.group(1));
    }

    private static long pid(Cli.Result status) {
        Matcher m = Pattern.compile("resident process (\\d+) running").matcher(status.out());
        assertTrue(m.find(), status::toString);
        return Long.parseLong(m.group(1));
    }

    private static Cli.Result awaitRunning(Path runtime, Path work) throws Exception {
        return awaitRunning(Cli.ROOT, runtime, work);
    }

    private static Cli.Result awaitRunning(Path tree, Path runtime, Path work) throws Exception {
        Cli.Result status = null;
        for (int i = 0; i < 120; i++) {
            status = launcher(tree, runtime, work, false, "daemon", "status");
            if (status.code() == 0) {
                return status;
            }
            Thread.sleep(250);
        }
        throw new AssertionError("no resident process started for the next command: " + status);
    }

    private static String socketName(Path runtime) throws IOException {
        try (Stream<Path> files = Files.list(runtime.resolve("rsaml"))) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".sock")).findFirst().orElseThrow();
        }
    }

    /**
     * Stops the test's resident process, and any process still starting for it (a test that failed before its process
     * was listening would otherwise leave it running, unreachable once its folder is deleted).
     */
    private static void stop(Path runtime, Path work) throws Exception {
        launcher(runtime, work, false, "daemon", "stop");
        String folder = runtime.toString();
        for (int i = 0; i < 10; i++) {
            List<ProcessHandle> left = ProcessHandle.allProcesses()
                    .filter(p -> p.info().commandLine().map(line -> line.contains(folder)).orElse(false)).toList();
            left.forEach(ProcessHandle::destroyForcibly);
            for (ProcessHandle p : left) {
                p.onExit().get(10, TimeUnit.SECONDS);
            }
            Thread.sleep(100);
        }
    }

    /** The files a command wrote below {@code work} (besides the models), by relative path; then deleted. */
    private static Map<String, String> takeFiles(Path work) throws IOException {
        Map<String, String> files = new TreeMap<>();
        List<Path> written;
        try (Stream<Path> all = Files.walk(work)) {
            // Everything but the models at the top: the commands write into folders of their own.
            written = all.filter(p -> !p.equals(work) && (Files.isDirectory(p) || !p.getParent().equals(work)))
                    .sorted((a, b) -> b.getNameCount() - a.getNameCount()).toList();
        }
        for (Path p : written) {
            if (Files.isRegularFile(p)) {
                // A JUnit report's times are the one thing that differs between two runs of the same command.
                files.put(work.relativize(p).toString(), Files.readString(p).replaceAll(" time=\"[0-9.]+\"", " time=\"…\""));
            }
        }
        for (Path p : written) {
            Files.delete(p);
        }
        return files;
    }
}
