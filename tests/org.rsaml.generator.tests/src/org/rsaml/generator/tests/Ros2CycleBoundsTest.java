/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.generator.internal.cxx.CxxNames;
import org.rsaml.generator.internal.ros2.Ros2Names;
import org.rsaml.validation.ModelLoader;

/**
 * ROS 2 messages carry no wave, so a module in a reactive cycle reacts at most once per the shortest period
 * of the releases whose data reaches it: found for rings of any size (each module and connection once).
 */
class Ros2CycleBoundsTest {

    private static final String PORT = "//@layers[name='l']/@modules[name='%s']/@ports[name='%s']";
    private static final long MS = 1_000_000L;

    private static void ring(StringBuilder modules, StringBuilder connections, String prefix, int n) {
        for (int i = 0; i < n; i++) {
            modules.append("    <modules name=\"").append(prefix).append(i).append("\" execDuration=\"0.001\"><ports xsi:type=\"rsaml:EntryPort\"")
                    .append(" name=\"i\" dataType=\"numeric\"/><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>\n");
            connect(connections, prefix + i, prefix + ((i + 1) % n));
        }
    }

    private static void connect(StringBuilder connections, String from, String to) {
        connections.append("  <connections source=\"").append(PORT.formatted(from, "o")).append("\" target=\"").append(PORT.formatted(to, "i"))
                .append("\"/>\n");
    }

    @Test
    void eachModuleOfALargeRingReactsAtMostOncePerTheShortestPeriodThatReachesIt(@TempDir Path tmp) throws Exception {
        int n = 20_000;
        StringBuilder modules = new StringBuilder();
        StringBuilder connections = new StringBuilder();
        for (String[] timed : new String[][] { { "slow", "100.0" }, { "fast", "50.0" }, { "lone", "200.0" } }) {
            modules.append("    <modules name=\"").append(timed[0]).append("\" execType=\"periodic\" period=\"").append(timed[1])
                    .append("\" execDuration=\"0.001\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>\n");
        }
        ring(modules, connections, "big", n);
        ring(modules, connections, "small", 10);
        connect(connections, "slow", "big0");
        connect(connections, "fast", "big" + n / 2);
        connect(connections, "slow", "small3");
        connect(connections, "small5", "big7");
        Path file = tmp.resolve("rings.rsaml");
        Files.writeString(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
                + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
                + " xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"rings\" declaredLayers=\"1\">\n  <layers name=\"l\" level=\"0\" timeUnit=\"ms\">\n"
                + modules + "  </layers>\n" + connections + "</rsaml:Architecture>\n");
        ExecutionPlan plan = ExecutionPlan.of(ModelLoader.load(file, "rings.rsaml").architecture());
        Ros2Names names = new Ros2Names(plan, new CxxNames(plan, "rings"));
        Map<String, Integer> byBound = new TreeMap<>();
        for (PlannedModule m : plan.modules()) {
            String ring = m.module().getName().replaceAll("[0-9]+$", "");
            byBound.merge(ring + " " + names.cycleBoundNs(m) / MS + " ms", 1, Integer::sum);
        }
        assertEquals(Map.of("big 50 ms", n, "small 100 ms", 10, "slow 0 ms", 1, "fast 0 ms", 1, "lone 0 ms", 1), byBound,
                "the big ring is reached by the 50 ms release (and the 100 ms one), the small one by the 100 ms release only;"
                        + " timed modules are in no cycle");
    }
}
