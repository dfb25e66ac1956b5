/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import org.rsaml.model.Processor;
import org.rsaml.model.SchedulingPolicy;

/**
 * A timed release: a job every {@link #periodNs()} from the start of the run plus
 * {@link #offsetNs()}, due within {@link #deadlineNs()}, taking at most {@link #costNs()}
 * (0 when the model gives no execution duration), at {@link #rank()}.
 */
public final class Release {
    final PlannedModule module;
    final ReleaseKind kind;
    final PlannedFunction function;
    final PlannedAction action;
    final long periodNs;
    final long offsetNs;
    final long deadlineNs;
    final long costNs;
    final long priorityKey;
    final SchedulingPolicy policy;
    int rank;

    Release(PlannedModule module, ReleaseKind kind, PlannedFunction function, PlannedAction action, long periodNs,
            long offsetNs, long deadlineNs, long costNs, long priorityKey, SchedulingPolicy policy) {
        this.module = module;
        this.kind = kind;
        this.function = function;
        this.action = action;
        this.periodNs = Math.max(1, periodNs);
        this.offsetNs = offsetNs;
        this.deadlineNs = deadlineNs > 0 ? deadlineNs : this.periodNs;
        this.costNs = costNs;
        this.priorityKey = priorityKey;
        this.policy = policy == null ? SchedulingPolicy.FIFO : policy;
    }

    public PlannedModule module() {
        return module;
    }

    public ReleaseKind kind() {
        return kind;
    }

    /** The released function (FUNCTION), or the function of the released action (ACTION); else null. */
    public PlannedFunction function() {
        return function;
    }

    /** The released action (ACTION only). */
    public PlannedAction action() {
        return action;
    }

    public long periodNs() {
        return periodNs;
    }

    /** Time of the first release after the start of the run. */
    public long offsetNs() {
        return offsetNs;
    }

    /** Relative deadline: the element's delay, or its period when it gives none. */
    public long deadlineNs() {
        return deadlineNs;
    }

    /** Worst-case execution time as modeled (execDuration); 0 when not given. */
    public long costNs() {
        return costNs;
    }

    /**
     * Whether it runs on an EDF processor: scheduled by absolute deadline (the runtimes ask Linux
     * for SCHED_DEADLINE), not at its rank.
     */
    public boolean edf() {
        org.rsaml.model.Processor p = module.processor();
        return p != null && p.isSetSchedPolicy() && p.getSchedPolicy() == SchedulingPolicy.EDF;
    }

    /** The scheduling policy of the released element's function (FIFO for module releases). */
    public SchedulingPolicy policy() {
        return policy;
    }

    /**
     * Fixed priority, 1 the lowest: RM releases rank by period and DM ones by deadline (shorter
     * is higher, from 2 up); every other policy is 1.
     */
    public int rank() {
        return rank;
    }

    /** What traces call it: {@code layer/module.function[.action]} or {@code layer/module}. */
    public String label() {
        return switch (kind) {
            case FUNCTION -> function.label();
            case ACTION -> action.label();
            case MODULE -> module.qualifiedName;
        };
    }

    /** The model's name of the released element ({@code module} for a module release). */
    public String elementName() {
        return switch (kind) {
            case FUNCTION -> function.function.getName();
            case ACTION -> action.action.getName();
            case MODULE -> "module";
        };
    }

    /** Why the release has its priority, in words. */
    public String why() {
        return switch (policy) {
            case RM -> "rate monotonic: priority by period";
            case DM -> "deadline monotonic: priority by delay";
            case RR -> "round robin at the base priority (SCHED_RR)";
            default -> policy.getLiteral() + ": first in, first out at the base priority";
        };
    }
}
