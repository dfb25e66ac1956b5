/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

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

/**
 * The README's walk-through of experiment 3 is what the program really does: its sample trace
 * appears, in order, in a real run, and at start every module runs once, lowest layer first, and
 * sends its initial outputs, which are received but start no reaction.
 */
class ReadmeTraceTest {

    private static final Pattern EVENT = Pattern.compile("^\\[\\s*[0-9.]+ ms\\] (.*)$");

    @Test
    void sampleTraceAndStartStatementMatchARealRun(@TempDir Path tmp) throws Exception {
        String readme = Files.readString(Tools.root().resolve("README.md"));
        String command = "./out/exp3/build/pick_and_place_arm --run-for-ms 100";
        assertTrue(readme.contains(command), "the README no longer runs experiment 3 as this test does");
        assertTrue(readme.contains("In the C++ program every module runs a start step once, lowest\nlayer first, and sends its initial outputs"),
                "the README's start statement changed: check it against the run below");
        int commandsEnd = readme.indexOf("```", readme.indexOf(command));
        String block = readme.substring(readme.indexOf("```\n", commandsEnd + 3) + 4);
        block = block.substring(0, block.indexOf("```"));
        List<String> sample = new ArrayList<>();
        for (String line : block.split("\n")) {
            Matcher m = EVENT.matcher(line);
            if (m.matches()) {
                sample.add(m.group(1));
            }
        }
        assertTrue(sample.size() > 10, "no sample trace found after the run command:\n" + block);

        Path out = tmp.resolve("exp3");
        new RsamlGenerator().generate(Tools.example("exp3-task-interpreter.rsaml"), Target.CPP, out, false);
        Path exe = Tools.cmakeBuild(out, "pick_and_place_arm");
        RunTrace trace = new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", "100"));

        // Every line of the sample happens (the policy a sched line names depends on the system's
        // permissions); a module's own lines come in the sample's order, but for messages received
        // and sched lines, whose order against the module's timers depends on the threads.
        for (String event : sample) {
            String sched = event.startsWith("sched ") ? event.substring(0, event.indexOf(' ', 6) + 1) : null;
            assertTrue(sched != null ? trace.lines.stream().anyMatch(l -> l.startsWith(sched)) : trace.lines.contains(event),
                    "README trace line '" + event + "' does not happen in a real run:\n" + trace.output);
        }
        for (String module : sample.stream().map(ReadmeTraceTest::module).distinct().toList()) {
            List<String> mine = trace.lines.stream().filter(l -> ordered(l) && module(l).equals(module)).toList();
            int at = 0;
            for (String event : sample.stream().filter(l -> ordered(l) && module(l).equals(module)).toList()) {
                while (at < mine.size() && !mine.get(at).equals(event)) {
                    at++;
                }
                assertTrue(at < mine.size(), "README trace line '" + event + "' is out of order for " + module + ":\n" + trace.output);
                at++;
            }
        }

        // Start: each module once, lowest layer first, its initial outputs sent, before any release.
        List<String> start = List.of("start motionControl/motionController", "send motionControl/motionController.s0_motionController #1",
                "start interpretation/taskInterpreter", "send interpretation/taskInterpreter.s0_taskInterpreter #1");
        assertTrue(trace.lines.size() > start.size() && trace.lines.get(0).startsWith("run ")
                && trace.lines.subList(1, 1 + start.size()).equals(start), trace.output);
        assertTrue(trace.count("start motionControl/motionController") == 1 && trace.count("start interpretation/taskInterpreter") == 1,
                trace.output);
        // The initial outputs are received ...
        List<Long> received = trace.received("interpretation/taskInterpreter.e1_taskInterpreter",
                "motionControl/motionController.s0_motionController", false);
        assertTrue(!received.isEmpty() && received.get(0) == 1, trace.output);
        // ... but start no reaction: the first reaction follows the first timed release.
        int firstRelease = trace.lines.indexOf("release motionControl/motionController.executeInstructions");
        int firstReaction = trace.lines.indexOf("react interpretation/taskInterpreter");
        assertTrue(firstRelease >= 0 && firstReaction > firstRelease, trace.output);
    }

    static boolean ordered(String line) {
        return !line.startsWith("recv ") && !line.startsWith("sched ");
    }

    /** The module a trace line is about: layer/module, before any '.'; empty for the run's own lines. */
    static String module(String line) {
        String[] words = line.split(" ");
        if (words.length < 2 || !words[1].contains("/")) {
            return "";
        }
        int dot = words[1].indexOf('.');
        return dot < 0 ? words[1] : words[1].substring(0, dot);
    }
}
