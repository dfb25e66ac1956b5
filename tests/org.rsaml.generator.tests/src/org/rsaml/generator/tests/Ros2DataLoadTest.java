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
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.validation.ModelLoader;

/**
 * Which processors' data threads a model sends more than they can react to on ROS 2 ({@link Ros2DataLoad}), as
 * {@link Ros2LaunchTest} derives it before it expects an entry port to receive every message its publisher
 * sends. Without ROS 2: from the models alone.
 */
class Ros2DataLoadTest {

    private static ExecutionPlan plan(String name) throws Exception {
        return ExecutionPlan.of(ModelLoader.load(Ros2Test.model(name), name).architecture());
    }

    private static PlannedModule module(ExecutionPlan plan, String qualifiedName) {
        return plan.modules().stream().filter(m -> m.qualifiedName().equals(qualifiedName)).findFirst().orElseThrow();
    }

    /**
     * subsumption-brooks: pathplan reacts for 200 ms to each robot pose (integrate, every 100 ms) and to each
     * startLook (whenlook sends one per pose it reacts to): 20 reactions a second offered, 5 possible. Its port
     * pose cannot receive the 10 poses a second that integrate sends.
     */
    @Test
    void aReactionOfferedMoreThanItCanRunOverloadsItsProcessor() throws Exception {
        ExecutionPlan plan = plan("subsumption-brooks.rsaml");
        Ros2DataLoad load = Ros2DataLoad.of(plan, 2);
        PlannedModule pathplan = module(plan, "explore/pathplan");
        assertEquals(10.0, load.sent(module(plan, "explore/integrate")), 1e-9, "integrate sends a pose every 100 ms");
        assertEquals(10.0, load.offeredReactions(module(plan, "explore/whenlook")), 1e-9, "whenlook reacts to each pose");
        assertEquals(20.0, load.offeredReactions(pathplan), 1e-9, "pathplan: each pose and each startLook");
        assertTrue(load.saturated(pathplan), "pathplan's reactions: 4 CPUs offered");
        assertEquals(1.0, load.level(pathplan).reactions().get("explore/pathplan"), 1e-9, "pathplan's thread: a whole CPU");
        assertFalse(load.takesEveryMessage(pathplan), load.whyNot(pathplan));
        // on one CPU the whole processor's aperiodic reactions are overloaded; on two, the others' threads still have room
        assertTrue(Ros2DataLoad.of(plan, 1).level(pathplan).overloaded(), Ros2DataLoad.of(plan, 1).level(pathplan).toString());
        assertFalse(Ros2DataLoad.of(plan, 2).level(pathplan).overloaded(), Ros2DataLoad.of(plan, 2).level(pathplan).toString());
        assertTrue(Ros2DataLoad.of(plan, 2).takesEveryMessage(module(plan, "avoid/collide")), "collide, sent a map every 100 ms");
    }

    /**
     * exp1-hybrid: the temporal executive (120 ms) reacts at most once per 10 ms (its reactive cycle's bound) and
     * is sent a resource report every 10 ms; the operator mission supervisor (50 ms) reacts to each report of
     * the robustness manager, which reacts to each status of m02 (every 20 ms). Both are aperiodic: their data
     * threads, always ready, run below every real-time thread, with the other aperiodic reactions of the
     * processor, which they overload; m02, which does not react, takes its data at priority 0, above them.
     */
    @Test
    void aperiodicReactionsOverloadOnlyTheirOwnLevel() throws Exception {
        ExecutionPlan plan = plan("exp1-hybrid.rsaml");
        Ros2DataLoad load = Ros2DataLoad.of(plan, 2);
        PlannedModule executive = module(plan, "decision/temporalExecutive");
        assertEquals(100.0, load.offeredReactions(executive), 1e-9, "at most once per 10 ms");
        assertEquals(50.0, load.offeredReactions(module(plan, "decision/operatorMissionSupervisor")), 1e-9, "each report of m02's status");
        assertTrue(load.aperiodic(executive) && load.saturated(executive), load.whyNot(executive));
        PlannedModule checker = module(plan, "control/requestChecker");
        assertTrue(load.aperiodic(checker) && !load.saturated(checker) && load.level(checker).overloaded(), load.level(checker).toString());
        PlannedModule m02 = module(plan, "functional/m02");
        assertFalse(load.aperiodic(m02), "m02 does not react");
        assertTrue(load.takesEveryMessage(m02), load.level(m02).toString());
    }

    /**
     * A node whose reactions are aperiodic serves its data at the default priority, below every real-time thread
     * (subsumption-brooks's pathplan, sent more than it can react to, would otherwise hold a CPU at priority 0 and
     * use up the real-time time Linux gives every CPU); sporadic reactions, which the analysis bounds, and the data
     * of a node that does not react stay at priority 0 (ros2-reaction.rsaml's filter and logger; exp1-hybrid's m02).
     */
    @Test
    void aperiodicReactionsAreServedBelowEveryRealtimeThread(@TempDir Path tmp) throws Exception {
        Map<String, Boolean> below = new TreeMap<>();
        for (String name : List.of("subsumption-brooks.rsaml", "resources/ros2-reaction.rsaml", "exp1-hybrid.rsaml")) {
            Path out = tmp.resolve(name.replace('/', '_'));
            new RsamlGenerator().generate(Ros2Test.model(name), Target.ROS2, out, true);
            try (Stream<Path> files = Files.walk(out)) {
                for (Path h : files.filter(f -> f.toString().endsWith("Base.hpp") && f.toString().contains("/gen/")).toList()) {
                    String text = Files.readString(h);
                    int calls = (int) Pattern.compile("\n    this->rsaml_data_unbounded();\n", Pattern.LITERAL).matcher(text).results().count();
                    assertTrue(calls <= 1 && (calls == 0 || text.indexOf("this->rsaml_data_group();") < text.indexOf("this->rsaml_data_unbounded();")),
                            h + ": at most once, in the constructor, after the data group:\n" + text);
                    below.put(h.getFileName().toString().replace("Base.hpp", ""), calls == 1);
                }
            }
        }
        for (String node : List.of("Pathplan", "Whenlook", "Collide", "TemporalExecutive", "RequestChecker", "M01")) {
            assertEquals(Boolean.TRUE, below.get(node), node + ": aperiodic reactions: " + below);
        }
        for (String node : List.of("Motor", "Filter", "Logger", "M02")) {
            assertEquals(Boolean.FALSE, below.get(node), node + ": at priority 0: " + below);
        }
    }

    /**
     * The models Ros2LaunchTest runs by default, and exp3-task-interpreter, leave their data threads room: every entry
     * port's rate is expected there, on a machine of two CPUs (exp3-task-interpreter's would not on one: its task
     * interpreter's reactions are offered 0.75 CPU, and its releases leave 0.70 of one). hierarchical-nasrem's
     * elementary-move sensory processing reacts for 30 ms to each of the 50 features a second primitive's sends it.
     */
    @Test
    void theDefaultLaunchModelsDoNotOverloadTheirDataThreads() throws Exception {
        for (String name : List.of("mobile-base-latency.rsaml", "resources/ros2-preemption.rsaml", "resources/inhibitor-window.rsaml",
                "resources/ros2-edf.rsaml", "resources/ros2-reaction.rsaml", "exp3-task-interpreter.rsaml")) {
            ExecutionPlan plan = plan(name);
            Ros2DataLoad load = Ros2DataLoad.of(plan, 2);
            for (PlannedModule m : plan.modules()) {
                assertTrue(load.takesEveryMessage(m), name + ": " + load.whyNot(m));
            }
        }
        ExecutionPlan nasrem = plan("hierarchical-nasrem.rsaml");
        PlannedModule eMoveSP = module(nasrem, "elementaryMove/eMoveSP");
        assertEquals(50.0, Ros2DataLoad.of(nasrem, 2).offeredReactions(eMoveSP), 1e-9, "a feature of primitiveSP every 20 ms");
        assertTrue(Ros2DataLoad.of(nasrem, 2).saturated(eMoveSP), "1.5 CPUs offered");
    }
}
