/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
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

    @Test
    void inhibitorBlocksTheOutputWhileActive(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        new RsamlGenerator().generate(Tools.resource("inhibitor-window.rsaml"), Target.CPP, out, false);
        RunTrace trace = new RunTrace(Tools.ok(out, 60, Tools.cmakeBuild(out, "inhibitor_window").toString(), "--run-for-ms", "450"));

        Pattern inhibit = Pattern.compile("inhibit mid/producer.value #(\\d+) by high/overseer.silence");
        List<Long> blocked = trace.lines.stream().map(inhibit::matcher).filter(Matcher::matches).map(m -> Long.parseLong(m.group(1))).toList();
        List<Long> delivered = trace.received("low/sink.in", "mid/producer.value", false);
        assertFalse(blocked.isEmpty(), "the inhibitor never blocked:\n" + trace.output);
        assertFalse(delivered.isEmpty(), "the inhibitor blocked everything:\n" + trace.output);
        for (Long n : blocked) {
            assertFalse(delivered.contains(n), "inhibited message #" + n + " arrived");
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
