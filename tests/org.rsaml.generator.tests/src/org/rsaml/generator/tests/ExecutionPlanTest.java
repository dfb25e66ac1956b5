/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.Release;
import org.rsaml.analysis.plan.ReleaseKind;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.validation.ModelLoader;

/** The target-neutral plan: what is released when, with which deadline, cost and priority, and what reacts. */
class ExecutionPlanTest {

    static ExecutionPlan plan(String example) throws Exception {
        return ExecutionPlan.of(ModelLoader.load(Tools.example(example), example).architecture());
    }

    @Test
    void exp3ReleasesTheMotionControllerAndTheInterpreterReacts() throws Exception {
        ExecutionPlan plan = plan("exp3-task-interpreter.rsaml");
        // Lowest layer first: the start order.
        assertEquals(List.of("motionControl/motionController", "interpretation/taskInterpreter"),
                plan.modules().stream().map(PlannedModule::qualifiedName).toList(), "modules start lowest layer first");
        assertEquals(1, plan.releases().size(), "exp3 has one periodic release: the motion controller's function");
        Release r = plan.releases().get(0);
        assertEquals(ReleaseKind.FUNCTION, r.kind(), "the release is a periodic function's");
        assertEquals("motionControl/motionController.executeInstructions", r.label(), "the release is labelled module.function");
        assertEquals(20_000_000L, r.periodNs(), "the release's period is the model's 20 ms");
        assertEquals(20_000_000L, r.deadlineNs(), "the release's deadline defaults to its period");
        assertEquals(6_000_000L, r.costNs(), "the release's cost is the six actions' 6 ms");
        assertEquals(SchedulingPolicy.RM, r.policy(), "the release is scheduled rate monotonic, as the model says");
        assertEquals(2, r.rank(), "the only rate-monotonic release ranks just above the base priority");
        // Its six actions run inline, each at its start date within the period.
        assertEquals(List.of(0L, 1_000_000L, 2_000_000L, 3_000_000L, 4_000_000L, 5_000_000L),
                r.function().inlineActions().stream().map(a -> a.offsetNs()).toList(), "the six actions run at their start dates, 1 ms apart");

        assertEquals(1, plan.reactions().size(), "exp3 has one reactive module");
        PlannedModule interpreter = plan.reactions().get(0).module();
        assertEquals("interpretation/taskInterpreter", interpreter.qualifiedName(), "the reactive module is the task interpreter");
        assertTrue(interpreter.reactive() && !interpreter.periodic(), "the interpreter reacts to inputs and is not periodic");
        assertNull(plan.modules().get(0).reaction(), "the periodic motion controller has no reaction");
        assertEquals(2, plan.flows().size(), "exp3's two connections become two flows");
        assertTrue(plan.reactiveCycles().isEmpty(), "exp3 has no reactive cycle");
        assertTrue(plan.warnings().isEmpty(), plan.warnings()::toString);
    }

    @Test
    void rateMonotonicRanksShorterPeriodsHigher() throws Exception {
        ExecutionPlan plan = plan("hierarchical-nasrem.rsaml");
        List<Release> rm = plan.releases().stream().filter(r -> r.policy() == SchedulingPolicy.RM).toList();
        assertTrue(rm.size() >= 2, "the example has rate-monotonic releases");
        for (Release a : rm) {
            for (Release b : rm) {
                if (a.periodNs() < b.periodNs()) {
                    assertTrue(a.rank() > b.rank(), a.label() + " (" + a.periodNs() + " ns) must outrank " + b.label());
                }
            }
        }
        plan.releases().stream().filter(r -> r.policy() != SchedulingPolicy.RM && r.policy() != SchedulingPolicy.DM)
                .forEach(r -> assertEquals(1, r.rank(), r.label()));
    }

    @Test
    void exp1HasAReactiveCycleThePlanNames() throws Exception {
        List<List<PlannedModule>> cycles = plan("exp1-hybrid.rsaml").reactiveCycles();
        assertEquals(1, cycles.size(), "exp1 has exactly one reactive cycle");
        assertEquals(List.of("functional/m01", "control/requestChecker", "control/resourceChecker", "decision/temporalExecutive"),
                cycles.get(0).stream().map(PlannedModule::qualifiedName).toList(), "the cycle names its modules in flow order");
        assertFalse(cycles.get(0).stream().anyMatch(PlannedModule::periodic), "the cycle has only reactive modules");
    }
}
