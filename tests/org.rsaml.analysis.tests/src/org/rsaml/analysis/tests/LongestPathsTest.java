/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.internal.PathSteps;
import org.rsaml.model.Architecture;
import org.rsaml.validation.ModelLoader;

/**
 * The longest-path computation that takes over from following each path past the step limit agrees with
 * following each path wherever it calls its result exact, and declines (not analysed, saying why) where a
 * walk over its states could pass a module twice: the same small models analysed with no limit and with a
 * limit of 0 steps.
 */
class LongestPathsTest {

    private static final String PORT = "//@layers[name='l']/@modules[name='%s']/@ports[name='%s']";
    private static final String CYCLE = "cycle of modules";

    private record Link(String from, String port, String to) {
    }

    /** One layer: e reads sensor s every 100 ms and feeds r0; sporadic modules r0.. with ports i, o, q; actuator t. */
    private static String model(List<String> modules, Set<Link> connections, String requirementAttributes) {
        StringBuilder b = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
                + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
                + " xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"walks\" declaredLayers=\"1\">\n  <layers name=\"l\" level=\"0\" timeUnit=\"ms\">\n"
                + "    <modules name=\"e\" type=\"realTime\" period=\"100.0\" execDuration=\"1.0\" execType=\"periodic\" sensors=\"//@sensors[name='s']\">"
                + "<ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>\n");
        modules.forEach(m -> b.append("    ").append(m).append('\n'));
        b.append("  </layers>\n");
        for (Link c : connections) {
            b.append("  <connections source=\"").append(PORT.formatted(c.from(), c.port())).append("\" target=\"")
                    .append(PORT.formatted(c.to(), "i")).append("\"/>\n");
        }
        b.append("  <sensors name=\"s\" timeUnit=\"ms\" period=\"100.0\"/>\n  <actuators name=\"t\" timeUnit=\"ms\" period=\"100.0\"/>\n");
        b.append("  <latencyRequirements name=\"req\" timeUnit=\"ms\" source=\"//@sensors[name='s']\" target=\"//@actuators[name='t']\" ")
                .append(requirementAttributes).append("/>\n</rsaml:Architecture>\n");
        return b.toString();
    }

    /** A sporadic module with entry port i and output ports o and q; inhibitors given as {trigger port, target module, target port}. */
    private static String module(String name, int intervalMs, String duration, boolean actuator, List<String[]> inhibitors) {
        StringBuilder b = new StringBuilder("<modules name=\"" + name + "\" execDuration=\"" + duration + "\" execType=\"sporadic\" period=\""
                + intervalMs + ".0\"" + (actuator ? " actuators=\"//@actuators[name='t']\"" : "") + ">"
                + "<ports xsi:type=\"rsaml:EntryPort\" name=\"i\" dataType=\"numeric\"/>"
                + "<ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/>"
                + "<ports xsi:type=\"rsaml:OutputPort\" name=\"q\" dataType=\"numeric\"/>");
        for (int k = 0; k < inhibitors.size(); k++) {
            String[] h = inhibitors.get(k);
            b.append("<inhibitors name=\"h").append(k).append("\" timeUnit=\"ms\" duration=\"10.0\" trigger=\"").append(PORT.formatted(name, h[0]))
                    .append("\" target=\"").append(PORT.formatted(h[1], h[2])).append("\"/>");
        }
        return b.append("</modules>").toString();
    }

    private static LatencyResult analyse(Path tmp, String name, String text, int steps) throws Exception {
        Path file = tmp.resolve(name);
        Files.writeString(file, text);
        Architecture a = ModelLoader.load(file, name).architecture();
        return PathSteps.withLimit(steps, () -> TimingAnalysis.analyse(a)).latencies().get(0);
    }

    /** A random model: forward connections (a third of the models any, so cycles too), some inhibitors, via and data age sometimes. */
    private static String random(Random r, boolean[] hasInhibitor) {
        int n = 3 + r.nextInt(8);
        boolean anyDirection = r.nextInt(3) == 0;
        List<String> modules = new ArrayList<>();
        Set<Link> connections = new LinkedHashSet<>();
        connections.add(new Link("e", "o", "r0"));
        for (int i = 0; i < n; i++) {
            List<String[]> inhibitors = new ArrayList<>();
            int j = r.nextInt(n);
            if (r.nextInt(3) == 0 && j != i) {
                inhibitors.add(new String[] { r.nextBoolean() ? "o" : "q", "r" + j, r.nextBoolean() ? "o" : "q" });
                hasInhibitor[0] = true;
            }
            modules.add(module("r" + i, 100 + r.nextInt(900), "0." + (1 + r.nextInt(9)), i >= n - 2 || r.nextInt(6) == 0, inhibitors));
            for (int k = 1 + r.nextInt(3); k > 0; k--) {
                int to = anyDirection ? r.nextInt(n) : i + 1 + r.nextInt(4);
                if (to < n && to != i) {
                    connections.add(new Link("r" + i, r.nextBoolean() ? "o" : "q", "r" + to));
                }
            }
        }
        String via = r.nextInt(3) == 0 ? "via=\"//@layers[name='l']/@modules[name='r" + (1 + r.nextInt(n - 1)) + "']\" " : "";
        String kind = r.nextBoolean() ? "kind=\"dataAge\" " : "";
        return model(modules, connections, via + kind + "maxLatency=\"" + (r.nextBoolean() ? "100000000.0" : "3000.0") + "\"");
    }

    @Test
    void theLongestPathComputationAgreesWithFollowingEachPathWhereverItCallsItselfExact(@TempDir Path tmp) throws Exception {
        int exact = 0;
        int exactWithInhibitors = 0;
        int declined = 0;
        for (int seed = 0; seed < 300; seed++) {
            boolean[] inhibitor = { false };
            String text = random(new Random(seed), inhibitor);
            LatencyResult walk = analyse(tmp, "walk" + seed + ".rsaml", text, Integer.MAX_VALUE);
            LatencyResult dp = analyse(tmp, "dp" + seed + ".rsaml", text, 0);
            String both = "model " + seed + ": every path followed: " + walk.explanation() + "; the longest-path computation: " + dp.explanation();
            assertFalse(walk.explanation().contains("stopped after"), "a small model is followed path by path to the end: " + both);
            if (dp.explanation().contains(CYCLE)) {
                declined++;
                assertEquals(Verdict.NOT_ANALYSED, dp.verdict(), "a model whose walks may pass a module twice is not analysed: " + both);
                continue;
            }
            exact++;
            exactWithInhibitors += inhibitor[0] ? 1 : 0;
            assertEquals(walk.verdict(), dp.verdict(), "the verdict: " + both);
            assertEquals(walk.paths(), dp.paths(), "the number of paths: " + both);
            assertEquals(walk.reactionNs(), dp.reactionNs(), "the worst reaction time: " + both);
            assertEquals(walk.dataAgeNs(), dp.dataAgeNs(), "the worst data age: " + both);
        }
        assertTrue(exact >= 100 && exactWithInhibitors >= 20 && declined >= 20, "the models compared cover both outcomes: " + exact
                + " exact (" + exactWithInhibitors + " with inhibitors), " + declined + " declined");
    }

    /**
     * e feeds r1, which sends on o to r2 and on q to the actuator's r3; r2 inhibits r1's q. The only path is
     * e, r1, r3: the walk e, r1, r2, inhibitor, r1.q, r3 enters r1 twice (through its stage, then past the
     * inhibitor), and its bound, higher, is no path's.
     */
    private static String reachedDirectlyAndThroughAnInhibitor(String maxLatency) {
        List<String> modules = List.of(module("r1", 100, "0.1", false, List.of()),
                module("r2", 900, "0.1", false, List.<String[]> of(new String[] { "q", "r1", "q" })),
                module("r3", 100, "0.1", true, List.of()));
        Set<Link> connections = new LinkedHashSet<>(List.of(new Link("e", "o", "r1"), new Link("r1", "o", "r2"), new Link("r1", "q", "r3")));
        return model(modules, connections, "maxLatency=\"" + maxLatency + "\"");
    }

    @Test
    void aModuleReachedDirectlyAndThroughAnInhibitorIsNeitherCountedTwiceNorAMiss(@TempDir Path tmp) throws Exception {
        LatencyResult walk = analyse(tmp, "direct.rsaml", reachedDirectlyAndThroughAnInhibitor("100000.0"), Integer.MAX_VALUE);
        assertEquals(Verdict.MEETS, walk.verdict(), walk.explanation());
        assertEquals(1, walk.paths(), "the one path e, r1, r3: " + walk.explanation());
        assertEquals(List.of("l/e", "l/r1", "l/r3"), walk.worstPath().stream().map(h -> h.label()).toList(), "the path followed");
        // a bound between the path's and the walk's through r1 twice: the path meets it
        long between = walk.reactionNs() + 500_000_000L;
        LatencyResult dp = analyse(tmp, "direct-dp.rsaml", reachedDirectlyAndThroughAnInhibitor(String.valueOf(between / 1e6)), 0);
        assertNotEquals(Verdict.MISSES, dp.verdict(), "the walk through r1 twice is no path, so no miss: " + dp.explanation());
        assertEquals(Verdict.NOT_ANALYSED, dp.verdict(), dp.explanation());
        assertTrue(dp.explanation().contains(CYCLE) && dp.explanation().contains("inhibitors leading back"),
                "the finding says why the paths were not bounded: " + dp.explanation());
        LatencyResult met = analyse(tmp, "direct-met.rsaml", reachedDirectlyAndThroughAnInhibitor(String.valueOf(between / 1e6)), Integer.MAX_VALUE);
        assertEquals(Verdict.MEETS, met.verdict(), "following each path, the bound is met: " + met.explanation());
    }
}
