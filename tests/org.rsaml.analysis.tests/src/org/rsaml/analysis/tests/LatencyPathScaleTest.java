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
import org.rsaml.analysis.PathBound;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingText;
import org.rsaml.analysis.Verdict;
import org.rsaml.validation.ModelLoader;

/**
 * Latency requirements over more paths than can be followed one by one: a ladder of 30 rungs (2^30 paths)
 * is bounded exactly, and dense clusters of reacting modules, whose paths mostly end before the target,
 * get a verdict instead of a search that never ends; up to 10,000 paths are listed each with its bound, the
 * longest first, and past that the result says which are listed.
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

    /** A ladder: e feeds a0 and b0, each of a_i and b_i feeds a_(i+1) and b_(i+1), the last two feed the actuator's module. */
    private static String ladder(int rungs) {
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
        return model(modules, connections);
    }

    @Test
    void aLadderOfThirtyRungsIsBoundedExactlyOverItsTwoToTheThirtyPaths(@TempDir Path tmp) throws Exception {
        int rungs = 30;
        ArchitectureTiming timing = analyse(tmp, "ladder.rsaml", ladder(rungs));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(Verdict.MEETS, l.verdict(), l.explanation());
        assertEquals(1 << rungs, l.paths(), "every path is counted: " + l.explanation());
        assertFalse(l.pathsAtLeast(), "2^30 paths is an exact count, not flagged as at least");
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

    /**
     * A ladder of 30 rungs, the requirement bounding the data age of the paths through b15 (2^29 of them, too many to
     * follow): the worst is found exactly by the longest-path computation, through b15 and every a elsewhere, its data
     * age its reaction time plus the last stage's period.
     */
    @Test
    void theDataAgeOfThePathsThroughANamedModuleIsBoundedExactlyPastTheSearch(@TempDir Path tmp) throws Exception {
        int rungs = 30;
        String text = ladder(rungs).replace("<latencyRequirements name=\"req\"", "<latencyRequirements name=\"req\" kind=\"dataAge\""
                + " via=\"//@layers[name='l']/@modules[name='b15']\"");
        LatencyResult l = analyse(tmp, "ladder-via.rsaml", text).latencies().get(0);
        assertEquals(Verdict.MEETS, l.verdict(), l.explanation());
        assertEquals(1L << (rungs - 1), (long) l.paths(), "every path through b15 is counted: " + l.explanation());
        List<String> expected = new ArrayList<>(List.of("l/e"));
        for (int i = 0; i < rungs; i++) {
            expected.add(i == 15 ? "l/b15" : "l/a" + i);
        }
        expected.add("l/act");
        assertEquals(expected, l.worstPath().stream().map(Hop::label).toList(), "the worst path through b15 waits for every other a");
        long reaction = l.worstPath().stream().mapToLong(Hop::totalNs).sum();
        assertEquals(reaction, l.reactionNs(), "the reaction time is the worst path's");
        assertEquals(reaction + 100_000_000L, l.dataAgeNs(), "the data age adds the period of the last stage, act's 100 ms");
        assertTrue(l.explanation().contains("maximum data age is at most") && l.explanation().contains("through l/b15"), l.explanation());
        assertEquals(l.dataAgeNs(), l.pathBounds().get(0).dataAgeNs(), "the worst path, found past the search, is listed first");
    }

    /**
     * A ladder of 30 rungs whose a29 also feeds a slow monitor that inhibits b29's output, and whose actuator's module is
     * on another host (5 ms of link): 2^30 paths straight on and 2^29 through the inhibitor, too many to follow. The
     * worst, found exactly past the search, passes the monitor, its inhibitor (at once, +0) and the link.
     */
    @Test
    void aPathThroughAnInhibitorAndAcrossHostsIsBoundedExactlyPastTheSearch(@TempDir Path tmp) throws Exception {
        String module = "//@layers[name='l']/@modules[name='%s']";
        String monitor = "<modules name=\"mon\" execDuration=\"0.01\" execType=\"sporadic\" period=\"5000.0\"><ports xsi:type=\"rsaml:EntryPort\""
                + " name=\"i\" dataType=\"numeric\"/><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/><inhibitors name=\"halt\""
                + " trigger=\"" + PORT.formatted("mon", "o") + "\" duration=\"15.0\" target=\"" + PORT.formatted("b29", "o") + "\"/></modules>\n";
        String text = ladder(30).replace("  </layers>\n", "    " + monitor + "  </layers>\n  <connections source=\"" + PORT.formatted("a29", "o")
                + "\" target=\"" + PORT.formatted("mon", "i") + "\"/>\n  <processors name=\"board\" core=\"0\" host=\"wheels\" linkLatency=\"5.0\""
                + " timeUnit=\"ms\" modules=\"" + module.formatted("act") + "\"/>\n");
        LatencyResult l = analyse(tmp, "ladder-inhibitor.rsaml", text).latencies().get(0);
        assertEquals(Verdict.MEETS, l.verdict(), l.explanation());
        assertEquals(3 << 29, l.paths(), "2^30 paths straight on and 2^29 through the inhibitor: " + l.explanation());
        List<String> expected = new ArrayList<>(List.of("l/e"));
        for (int i = 0; i < 30; i++) {
            expected.add("l/a" + i);
        }
        expected.addAll(List.of("l/mon", "l/mon.halt", "link main -> 'wheels'", "l/act"));
        assertEquals(expected, l.worstPath().stream().map(Hop::label).toList(), "the worst path waits for the monitor and crosses the link");
        assertEquals(5_000_000L, l.worstPath().get(expected.size() - 2).totalNs(), "the link adds its 5 ms");
        assertEquals(l.worstPath().stream().mapToLong(Hop::totalNs).sum(), l.reactionNs(), "the bound is the worst path's");
    }

    /** How many of a path's stages are a modules (the slower ones to wait for: a longer path has more). */
    private static long slowStages(PathBound b) {
        return b.hops().stream().filter(h -> h.label().matches("l/a\\d+")).count();
    }

    /**
     * 4,096 paths, fewer than the listing's limit: each is listed once with its bound, the longest first, while the text
     * shows the 10 longest and says how many there are and where all are listed.
     */
    @Test
    void everyPathOfATwelveRungLadderIsListedAndTheTextSaysWhereToFindThem(@TempDir Path tmp) throws Exception {
        ArchitectureTiming timing = analyse(tmp, "ladder12.rsaml", ladder(12));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(4096, l.paths(), "every path is counted: " + l.explanation());
        assertEquals(4096, l.pathBounds().size(), "every path is listed, none left out");
        assertEquals("", l.unlisted(), "nothing is said to be left out when all are listed");
        assertEquals(4096, l.pathBounds().stream().map(PathBound::text).distinct().count(), "each path is listed once");
        for (int i = 1; i < l.pathBounds().size(); i++) {
            assertTrue(l.pathBounds().get(i - 1).reactionNs() >= l.pathBounds().get(i).reactionNs(),
                    "the longest first, at " + i + ": " + l.pathBounds().get(i - 1) + " before " + l.pathBounds().get(i));
        }
        String text = TimingText.render("ladder12.rsaml", timing);
        assertTrue(text.contains("  the 10 longest of 4096 paths (rsaml analyze --format json lists all 4096):\n"), text);
        String list = text.substring(text.indexOf("longest of 4096 paths"));
        assertEquals(10, list.lines().filter(line -> line.startsWith("    l/e +")).count(), "the text shows 10 paths:\n" + list);
    }

    /**
     * 16,384 paths of 16 stages, more than the 100,000 stages listed hold: the 6,250 listed are the longest (every path
     * with 9 or more of the 14 slower stages, and 2,777 of the 3,003 with 8), and the result says the others are counted,
     * not listed.
     */
    @Test
    void pastTheListingLimitTheLongestPathsAreListedAndTheRestCounted(@TempDir Path tmp) throws Exception {
        ArchitectureTiming timing = analyse(tmp, "ladder14.rsaml", ladder(14));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(16384, l.paths(), "every path is counted: " + l.explanation());
        assertEquals(LatencyResult.MAX_LISTED_STAGES / 16, l.pathBounds().size(), "the listing stops at its stages");
        assertEquals("the 6250 longest of 16384 are listed (at most 10000 paths of 100000 stages in all)", l.unlisted(), "the result says what is left out");
        // paths with k slower stages: C(14, k); the 6,250 longest are those with k >= 9 (3,473) and 2,777 with k = 8
        long[] binomial = { 1, 14, 91, 364, 1001, 2002, 3003, 3432, 3003, 2002, 1001, 364, 91, 14, 1 };
        long[] listed = new long[15];
        l.pathBounds().forEach(b -> listed[(int) slowStages(b)]++);
        for (int k = 9; k <= 14; k++) {
            assertEquals(binomial[k], listed[k], "every path with " + k + " slower stages is among the longest listed");
        }
        assertEquals(2777, listed[8], "the rest of the 6,250 have 8 slower stages");
        for (int k = 0; k < 8; k++) {
            assertEquals(0, listed[k], "no shorter path with " + k + " slower stages is listed");
        }
        String text = TimingText.render("ladder14.rsaml", timing);
        assertTrue(text.contains("  the 10 longest paths listed (rsaml analyze --format json lists 6250; the 6250 longest of 16384"
                + " are listed (at most 10000 paths of 100000 stages in all)):\n"), text);
    }

    /**
     * A ladder of 200 rungs: its search stops after 1,000,000 steps, and the paths it followed, 202 stages each, are listed
     * within the 100,000 stages the list holds, the worst first; the result says so. The analysis for verdicts only (as
     * validation runs it) gives the same verdict and worst path, and lists none.
     */
    @Test
    void longPathsAreListedWithinTheStagesTheListHoldsAndACutSearchSaysWhichAreListed(@TempDir Path tmp) throws Exception {
        ArchitectureTiming timing = analyse(tmp, "ladder200.rsaml", ladder(200));
        LatencyResult l = timing.latencies().get(0);
        assertEquals(Verdict.MISSES, l.verdict(), "200 stages of up to 1 s exceed the 100 s allowed: " + l.explanation());
        assertTrue(l.reactionNs() > 200 * 1_000_000_000L, "the worst path waits for every a: " + l.reactionNs());
        long stages = l.pathBounds().stream().mapToLong(b -> b.hops().size()).sum();
        assertEquals(LatencyResult.MAX_LISTED_STAGES / 202, l.pathBounds().size(), "as many paths as fit the list's stages: " + stages);
        assertEquals(l.reactionNs(), l.pathBounds().get(0).reactionNs(), "the worst path, found past the search, is listed first");
        assertTrue(l.unlisted().startsWith("the paths were followed one by one for 1000000 steps, ")
                && l.unlisted().contains("listed are the longest of those followed, and the worst"), l.unlisted());
        assertEquals(Integer.MAX_VALUE, l.paths(), "2^200 paths: the count stops at its largest");
        assertTrue(l.pathsAtLeast(), "a count that stopped is flagged as at least that many");
        String text = TimingText.render("ladder200.rsaml", timing);
        assertTrue(text.contains("worst path (at least 2147483647 paths examined;"), "the text report says at least: " + text);
        LatencyResult verdict = TimingAnalysis.verdicts(ModelLoader.load(tmp.resolve("ladder200.rsaml"), "ladder200.rsaml").architecture())
                .latencies().get(0);
        assertEquals(l.verdict(), verdict.verdict(), "the verdict without the list is the same: " + verdict.explanation());
        assertEquals(l.explanation(), verdict.explanation(), "and said the same");
        assertEquals(l.worstPathText(), verdict.worstPathText(), "the worst path is kept without the list");
        assertTrue(verdict.pathBounds().isEmpty(), "for verdicts only, no path is listed: " + verdict.pathBounds().size());
        assertTrue(verdict.unlisted().contains("not listed"), "and the result says so: " + verdict.unlisted());
        assertTrue(l.unlisted().contains("counted (at least 2147483647 in all)"), "a count that stopped says at least: " + l.unlisted());
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
