/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
 * Inhibitors block an output while active; suppressors replace an input while active. A blocked
 * message never arrives, and the replacement does.
 */
class SubsumptionTest {

    /**
     * The overseer's boolean trigger 'quiet' asserts the inhibitor only when true (docs/timing.md,
     * "Inhibitors and suppressors"). As generated, the overseer sends false every 100 ms: nothing is
     * inhibited. With user code that sends true at every other release, the producer's messages are
     * blocked exactly in the 30 ms after those releases, and reach the sink otherwise.
     */
    @Test
    void inhibitorBlocksTheOutputOnlyAfterTrue(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        new RsamlGenerator().generate(Tools.resource("inhibitor-window.rsaml"), Target.CPP, out, false);
        RunTrace asGenerated = new RunTrace(Tools.ok(out, 60, Tools.cmakeBuild(out, "inhibitor_window").toString(), "--run-for-ms", "450"));
        assertTrue(asGenerated.count("release high/overseer.watch") >= 4, asGenerated.output);
        assertTrue(asGenerated.sends("high/overseer.quiet") >= 4, "the overseer sends false:\n" + asGenerated.output);
        assertEquals(List.of(), asGenerated.matching("inhibit "), "a false trigger inhibits nothing");
        assertEquals(asGenerated.sends("mid/producer.value"), asGenerated.received("low/sink.in", "mid/producer.value", false).size(),
                "every message of the producer reaches the sink");

        Path overseer = out.resolve("src/high/Overseer.cpp");
        String user = Files.readString(overseer);
        Matcher action = Pattern.compile("void Overseer::(\\w+)\\(\\) \\{\\}").matcher(user);
        assertTrue(action.find(), user);
        Files.writeString(overseer, user.replace(action.group(), "void Overseer::" + action.group(1)
                + "() { out_quiet.value = !out_quiet.value; }"));
        RunTrace trace = new RunTrace(Tools.ok(out, 60, Tools.cmakeBuild(out, "inhibitor_window").toString(), "--run-for-ms", "450"));

        Pattern inhibit = Pattern.compile("inhibit mid/producer.value #(\\d+) by high/overseer.silence");
        List<Long> blocked = trace.lines.stream().map(inhibit::matcher).filter(Matcher::matches).map(m -> Long.parseLong(m.group(1))).toList();
        List<Long> delivered = trace.received("low/sink.in", "mid/producer.value", false);
        assertFalse(blocked.isEmpty(), "the inhibitor never blocked:\n" + trace.output);
        assertFalse(delivered.isEmpty(), "the inhibitor blocked everything:\n" + trace.output);
        for (Long n : blocked) {
            assertFalse(delivered.contains(n), "inhibited message #" + n + " arrived");
        }
        // each inhibition follows a release that sent true (the 1st, 3rd, ...) by at most the 30 ms window
        List<Double> releases = new ArrayList<>();
        for (int i = 0; i < trace.lines.size(); i++) {
            String line = trace.lines.get(i);
            if (line.equals("release high/overseer.watch")) {
                releases.add(trace.times.get(i));
            } else if (line.startsWith("inhibit ")) {
                assertFalse(releases.isEmpty(), "inhibited before the overseer sent true: " + line);
                double since = trace.times.get(i) - releases.get(releases.size() - 1);
                assertTrue(releases.size() % 2 == 1 && since <= 30 + 2, "'" + line + "' " + since + " ms after the overseer's release "
                        + releases.size() + ", which sent " + (releases.size() % 2 == 1) + "\n" + trace.output);
            }
        }
    }

    @Test
    void suppressorReplacesTheInputWhileActive(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        new RsamlGenerator().generate(Tools.example("subsumption-brooks.rsaml"), Target.CPP, out, false);
        RunTrace trace = new RunTrace(Tools.ok(out, 60, Tools.cmakeBuild(out, "subsumption_mobile_robot").toString(), "--run-for-ms", "450"));

        // avoid's heading replaces what runAway sends to the motor (suppressor overrideRunAway, 1.5 s).
        List<Long> replacements = trace.received("avoid/motor.heading", "wander/avoid.heading", true);
        assertTrue(replacements.size() >= 2, "the suppressor delivered no replacement:\n" + trace.output);
        Pattern suppress = Pattern.compile("suppress avoid/motor.heading <- avoid/runAway.heading #(\\d+) by wander/avoid.overrideRunAway");
        List<Long> suppressed = trace.lines.stream().map(suppress::matcher).filter(Matcher::matches).map(m -> Long.parseLong(m.group(1))).toList();
        assertFalse(suppressed.isEmpty(), "runAway's heading was never suppressed:\n" + trace.output);
        List<Long> normal = trace.received("avoid/motor.heading", "avoid/runAway.heading", false);
        for (Long n : suppressed) {
            assertFalse(normal.contains(n), "suppressed message #" + n + " arrived");
        }
    }
}
