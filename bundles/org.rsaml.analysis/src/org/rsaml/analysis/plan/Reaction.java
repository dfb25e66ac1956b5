/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.List;

/**
 * A module reacting to data: every arrival at one of its {@link #inputs()} runs its step
 * functions and sends its outputs, not sooner than {@link #minIntervalNs()} after the previous
 * reaction. Data sent by an activation belongs to that activation's wave (a timed release or
 * the start begins one); a module reacts at most once per wave, so modules that react to each
 * other in a cycle ({@link ExecutionPlan#reactiveCycles()}) stop when the wave has gone round.
 */
public final class Reaction {
    final PlannedModule module;

    Reaction(PlannedModule module) {
        this.module = module;
    }

    public PlannedModule module() {
        return module;
    }

    public List<PlannedPort> inputs() {
        return module.inputs();
    }

    public List<PlannedFunction> functions() {
        return module.stepFunctions();
    }

    public long minIntervalNs() {
        return module.minIntervalNs;
    }

    /**
     * Relative deadline of a reaction, from the arrival that starts it: the module's delay, else
     * its minimum interval; 0 (none) for an aperiodic module without a delay.
     */
    public long deadlineNs() {
        long delay = PlanTimes.nanos(module.module.getDelay(), module.module);
        return delay > 0 ? delay : module.minIntervalNs;
    }

    /** Modeled execution time of a reaction: the module's execDuration, else the sum of its step functions'. */
    public long costNs() {
        long cost = PlanTimes.nanos(module.module.getExecDuration(), module.module);
        if (cost == 0) {
            for (PlannedFunction f : module.stepFunctions()) {
                cost = Math.addExact(cost, PlanTimes.nanos(f.function.getExecDuration(), f.function));
            }
        }
        return cost;
    }

    /** Whether the module gives no execution duration of its own, so that {@link #costNs()} sums its functions'. */
    public boolean costFromFunctions() {
        return PlanTimes.nanos(module.module.getExecDuration(), module.module) == 0;
    }

    /** What traces call it: {@code layer/module (reaction)}, as the analysis names its task. */
    public String label() {
        return module.qualifiedName + " (reaction)";
    }
}
