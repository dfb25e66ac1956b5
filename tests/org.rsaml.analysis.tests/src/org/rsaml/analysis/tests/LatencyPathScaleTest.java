/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingText;
import org.rsaml.analysis.Verdict;
import org.rsaml.validation.ModelLoader;

/**
 * Latency requirements over more paths than can be followed one by one: a ladder of 30 rungs (2^30 paths)
 * is bounded exactly, and dense clusters of reacting modules, whose paths mostly end before the target,
 * get a verdict instead of a search that never ends.
 */
class LatencyPathScaleTest {

    private static final String PORT = "//@layers[name='l']/@modules[name='%s']/@ports[name='%s']";

    private static String model(List<String> modules, List<String[]> connections) {
        StringBuilder b = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
                + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
                + " xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"scale\" declaredLayers=\"1\">\n  <layers name=\"l\" level=\"0\" timeUnit=\"ms\">\n");
        modules.forEach(m -> b.append("    ").append(m).append('\n'));
        b.append("  </layers>\n");
        for (String[] c : connections) {
            b.append("  <connections source=\"").append(PORT.formatted(c[0], "o")).append("\" target=\"").append(PORT.formatted(c[1], "i"))
                    .append("\"/>\n");
        }
        b.append("  <sensors name=\"s\" timeUnit=\"ms\" period=\"100.0\"/>\n  <actuators name=\"t\" timeUnit=\"ms\" period=\"100.0\"/>\n");
        b.append("  <latencyRequirements name=\"req\" timeUnit=\"ms\" source=\"//@sensors[name='s']\" target=\"//@actuators[name='t']\""
                + " maxLatency=\"100000.0\"/>\n</rsaml:Architecture>\n");
        return b.toString();
    }

    private static String timed() {
        return "<modules name=\"e\" type=\"realTime\" period=\"100.0\" execDuration=\"1.0\" execType=\"periodic\""
                + " sensors=\"//@sensors[name='s']\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>";
    }

    /** A reacting module with an entry port i and an output port o: sporadic with that interval, or aperiodic (null). */
    private static String reacting(String name, String interval, boolean actuator) {
        return "<modules name=\"" + name + "\" execDuration=\"0.01\"" + (interval == null ? "" : " execType=\"sporadic\" period=\"" + interval + "\"")
                + (actuator ? " actuators=\"//@actuators[name='t']\"" : "") + "><ports xsi:type=\"rsaml:EntryPort\" name=\"i\""
                + " dataType=\"numeric\"/><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>";
    }

    private static ArchitectureTiming analyse(Path tmp, String name, String text) throws Exception {
        Path file = tmp.resolve(name);
        Files.writeString(file, text);
        return TimingAnalysis.analyse(ModelLoader.load(file, name).architecture());
    }

    @Test
    void aLadderOfThirtyRungsIsBoundedExactlyOverItsTwoToTheThirtyPaths(@TempDir Path tmp) throws Exception {
        int rungs = 30;
        List<String> modules = new ArrayList<>(List.of(timed()));
        List<String[]> connections = new ArrayList<>();
        List<String> before = List.of("e");
        for (int i = 0; i < rungs; i++) {
            // a (every 1000 ms at most) is slower to wait for than b (every 900 ms): the worst path takes every a
            modules.add(reacting("a" + i, "1000.0", false));
            modules.add(reacting("b" + i, "900.0", false));
            for (String from : before) {
                connections.add(new String[] { from, "a" + i });
                connections.add(new String[] { from, "b" + i });
            }
            before = List.of("a" + i, "b" + i);
        }
        modules.add(reacting("act", "100.0", true));
        before.forEach(from -> connections.add(new String[] { from, "act" }));
        ArchitectureTiming timing = analyse(tmp, "ladder.rsaml", model(modules, connections));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(Verdict.MEETS, l.verdict(), l.explanation());
        assertEquals(1 << rungs, l.paths(), "every path is counted: " + l.explanation());
        List<String> expected = new ArrayList<>(List.of("l/e"));
        for (int i = 0; i < rungs; i++) {
            expected.add("l/a" + i);
        }
        expected.add("l/act");
        assertEquals(expected, l.worstPath().stream().map(Hop::label).toList(), "the worst path waits for every a");
        assertEquals(l.worstPath().stream().mapToLong(Hop::totalNs).sum(), l.reactionNs(), "the bound is the worst path's");
        assertTrue(l.reactionNs() > rungs * 1_000_000_000L, "each a waits up to 1 s: " + l.reactionNs());
        assertEquals(l.reactionNs(), l.pathBounds().get(0).reactionNs(), "the worst path is listed first: " + l.pathBounds().get(0));
        assertTrue(l.explanation().contains("over " + (1 << rungs) + " paths"), l.explanation());
    }

    /** The timed module e feeds c0 of a clique of reacting modules (each feeds every other); only c1 feeds the actuator's. */
    private static String clique(int k, String interval) {
        List<String> modules = new ArrayList<>(List.of(timed()));
        List<String[]> connections = new ArrayList<>();
        connections.add(new String[] { "e", "c0" });
        for (int i = 0; i < k; i++) {
            modules.add(reacting("c" + i, interval, false));
            for (int j = 0; j < k; j++) {
                if (i != j) {
                    connections.add(new String[] { "c" + i, "c" + j });
                }
            }
        }
        modules.add(reacting("act", interval, true));
        connections.add(new String[] { "c1", "act" });
        return model(modules, connections);
    }

    @Test
    void aDenseClusterOfAperiodicReactionsIsNotAnalysedForItsUnboundedStageNotSearchedForever(@TempDir Path tmp) throws Exception {
        ArchitectureTiming timing = analyse(tmp, "clique.rsaml", clique(14, null));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(Verdict.NOT_ANALYSED, l.verdict(), l.explanation());
        assertTrue(l.explanation().startsWith("not analysed: l/c0 reacts aperiodically: its response time has no bound"),
                "the reason is the stage without a bound every path passes: " + l.explanation());
        assertTrue(l.pathBounds().stream().anyMatch(b -> !b.bounded()), "paths followed are listed: " + l.pathBounds());
        String text = TimingText.render("clique.rsaml", timing);
        assertFalse(text.contains("not analysed: not analysed"), "the verdict is said once:\n" + text);
    }

    @Test
    void aDenseClusterOfSporadicReactionsSaysWhereItStoppedFollowingPaths(@TempDir Path tmp) throws Exception {
        ArchitectureTiming timing = analyse(tmp, "sporadic-clique.rsaml", clique(14, "1000.0"));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(Verdict.NOT_ANALYSED, l.verdict(), l.explanation());
        assertTrue(l.explanation().contains("stopped after " + 1_000_000 + " steps") && l.explanation().contains("cycle of modules"),
                "the cut is said, with what would avoid it: " + l.explanation());
        assertTrue(l.paths() > 0 && !l.pathBounds().isEmpty(), "the paths followed are listed: " + l.pathBounds());
    }
}
