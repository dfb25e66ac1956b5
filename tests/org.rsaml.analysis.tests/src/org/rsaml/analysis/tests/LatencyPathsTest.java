/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
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
 * Latency requirements that name their path (via), paths through inhibitors, and every path's bound:
 * the reactive chain (55 + 65 + 12 ms), the global planner's (1150 + 65 + 12 ms) and the safety chain
 * through the monitor's inhibitor (21 ms, the block at once, then the drive's 12 ms).
 */
class LatencyPathsTest {

    private static final long MS = 1_000_000L;

    private static LatencyResult requirement(ArchitectureTiming timing, String name) {
        return timing.latencies().stream().filter(l -> l.name().equals(name)).findFirst().orElseThrow();
    }

    private static List<String> stages(PathBound b) {
        return b.hops().stream().map(Hop::label).toList();
    }

    @Test
    void everyPathIsReportedWithItsOwnBoundTheLongestFirst() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(ArchitectureTimingTest.fixture("latency-named-paths.rsaml"));
        LatencyResult all = requirement(timing, "scanToWheels");
        assertEquals(Verdict.MEETS, all.verdict(), all.explanation());
        assertEquals(3, all.paths(), "the planner's, the reactive and the safety chain: " + all.pathBounds());
        assertEquals(List.of(1227 * MS, 132 * MS, 33 * MS), all.pathBounds().stream().map(PathBound::reactionNs).toList(),
                "each path's reaction time, the longest first");
        assertEquals(List.of("deliberative/planner", "reactive/avoid", "control/drive"), stages(all.pathBounds().get(0)), "the planner's path runs planner, avoid, drive");
        assertEquals(List.of("reactive/detector", "reactive/avoid", "control/drive"), stages(all.pathBounds().get(1)), "the reactive path runs detector, avoid, drive");
        assertEquals(List.of("deliberative/monitor", "deliberative/monitor.halt", "control/drive"), stages(all.pathBounds().get(2)),
                "the safety chain passes the inhibitor, which blocks avoid's command at once");
        assertEquals(1227 * MS, all.reactionNs(), "the requirement's bound is its worst path's");
        String text = TimingText.render("latency-named-paths.rsaml", timing);
        assertTrue(text.contains("deliberative/monitor +21 ms -> deliberative/monitor.halt +0 ns -> control/drive +12 ms: reaction time 33 ms"),
                text);
    }

    @Test
    void aRequirementThatNamesItsPathIsCheckedOnThatPathOnly() throws Exception {
        ArchitectureTiming timing = TimingAnalysis.analyse(ArchitectureTimingTest.fixture("latency-named-paths.rsaml"));
        LatencyResult reactive = requirement(timing, "reactiveChain");
        assertEquals(Verdict.MEETS, reactive.verdict(), reactive.explanation());
        assertEquals(1, reactive.paths(), reactive.explanation());
        assertEquals(132 * MS, reactive.reactionNs(), "not the planner's 1227 ms");
        assertEquals(List.of("reactive/detector"), reactive.via(), "the reactive requirement names the path it is checked on");
        assertTrue(reactive.explanation().contains("over 1 path through reactive/detector"), reactive.explanation());

        LatencyResult safety = requirement(timing, "safetyChain");
        assertEquals(Verdict.MEETS, safety.verdict(), safety.explanation());
        assertEquals(33 * MS, safety.reactionNs(), safety.explanation());
        assertEquals(List.of("deliberative/monitor", "inhibitor deliberative/monitor.halt"), safety.via(), "the safety requirement names the monitor and its inhibitor");

        LatencyResult none = requirement(timing, "noSuchPath");
        assertEquals(Verdict.MISSES, none.verdict(), none.explanation());
        assertEquals("no path through deliberative/planner, then reactive/detector leads from sensor 'laser' to actuator 'wheels':"
                + " the data never arrives that way", none.explanation(), "a requirement naming a path that does not exist says which path, from which sensor to which actuator");
    }

    /**
     * The drive on another host (a board reached through a 2 ms link): every path into it crosses the
     * link and takes 2 ms more, shown as a stage of its own; and its core 0 is not the main host's core
     * 0, so the two processors that claim core 0 share nothing.
     */
    @Test
    void aProcessorOnAnotherHostAddsItsLinkToEveryPathThatCrossesIt(@TempDir Path tmp) throws Exception {
        Path root = Path.of(System.getProperty("rsaml.root", "../.."));
        String text = Files.readString(root.resolve("tests/org.rsaml.analysis.tests/resources/latency-named-paths.rsaml"));
        String drive = "<processors name=\"core0\" core=\"0\"";
        String reactive = "<processors name=\"core1\" core=\"1\"";
        assertTrue(text.contains(drive) && text.contains(reactive), "the fixture has the two processors this test moves to other hosts");
        Path model = tmp.resolve("latency-on-two-hosts.rsaml");
        Files.writeString(model, text.replace(drive, "<processors name=\"board\" core=\"0\" host=\"base-board\" linkLatency=\"2000.0\" timeUnit=\"us\"")
                .replace(reactive, "<processors name=\"core1\" core=\"0\""));
        ArchitectureTiming timing = TimingAnalysis.analyse(ModelLoader.load(model, model.getFileName().toString()).architecture());
        assertTrue(timing.processors().stream().allMatch(p -> p.result().verdict() == Verdict.MEETS),
                "core 0 of host base-board and core 0 of the main host are different CPUs: " + timing.processors());
        LatencyResult all = requirement(timing, "scanToWheels");
        assertEquals(List.of(1229 * MS, 134 * MS, 35 * MS), all.pathBounds().stream().map(PathBound::reactionNs).toList(),
                "each path 2 ms longer: " + all.pathBounds());
        assertEquals(List.of("reactive/detector", "reactive/avoid", "link main -> 'base-board'", "control/drive"), stages(all.pathBounds().get(1)),
                "the link is a stage of its own, between the hosts");
        Hop link = all.pathBounds().get(1).hops().get(2);
        assertEquals(2 * MS, link.totalNs(), link.toString());
        assertTrue(link.activation().contains("the link latencies of processor core1 and processor board"), link.activation());
    }
}
