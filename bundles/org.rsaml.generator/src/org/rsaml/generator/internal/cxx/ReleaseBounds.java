/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cxx;

import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Locale;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TaskSource;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingModelException;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Reaction;
import org.rsaml.analysis.plan.Release;
import org.rsaml.analysis.plan.UnplannableException;

/**
 * The timing analysis's bound on each timed release's and each reaction's response time, as the
 * generated programs measure their jobs against it: the worst-case response time where the analysis computes one, the
 * deadline where it proves the deadline met without one (EDF), none otherwise (with the reason).
 */
public final class ReleaseBounds {

    /** A release's bound in nanoseconds (negative: none) and what the analysis says of it. */
    public record Bound(long responseNs, String why) {
    }

    private final Map<EObject, Map<String, TaskResult>> results = new IdentityHashMap<>();
    private final String unanalysed;

    private ReleaseBounds(ArchitectureTiming timing, String unanalysed) {
        this.unanalysed = unanalysed;
        if (timing == null) {
            return;
        }
        for (ProcessorTiming p : timing.processors()) {
            Map<String, TaskResult> byName = new HashMap<>();
            for (TaskResult t : p.result().tasks()) {
                byName.put(t.task().name(), t);
            }
            for (TaskSource s : p.sources()) {
                TaskResult t = byName.get(s.task().name());
                if (t != null) {
                    results.computeIfAbsent(s.element(), e -> new HashMap<>()).put(s.kind(), t);
                }
            }
        }
    }

    /** The analysis of the plan's architecture; a model the analysis refuses gives no bounds, and says why. */
    public static ReleaseBounds of(ExecutionPlan plan) {
        try {
            return new ReleaseBounds(TimingAnalysis.verdicts(plan.architecture()), null);
        } catch (UnplannableException | TimingModelException e) {
            return new ReleaseBounds(null, "the timing analysis refuses the model: " + e.getMessage());
        }
    }

    public Bound of(Release r) {
        EObject element = switch (r.kind()) {
            case FUNCTION -> r.function().function();
            case ACTION -> r.action().action();
            case MODULE -> r.module().module();
        };
        return bound(results.getOrDefault(element, Map.of()).get(r.kind().name().toLowerCase(Locale.ROOT)));
    }

    /** The bound of a reacting module's reactions, from the arrival that starts one to its completion. */
    public Bound of(Reaction r) {
        return aperiodic(r) ? new Bound(-1, "aperiodic: the model bounds neither its arrivals nor its load") : analysed(r);
    }

    /**
     * Whether a module's reactions are aperiodic: not sporadic, without a bound from the analysis, which excludes
     * them (their arrivals and their load are not bounded by the model).
     */
    public boolean aperiodic(Reaction r) {
        return r.minIntervalNs() == 0 && analysed(r).responseNs() < 0;
    }

    private Bound analysed(Reaction r) {
        return bound(results.getOrDefault(r.module().module(), Map.of()).get("reaction"));
    }

    private Bound bound(TaskResult t) {
        if (t == null) {
            return new Bound(-1, unanalysed != null ? unanalysed : "the timing analysis has no task for it");
        }
        if (t.responseTime().isPresent()) {
            return new Bound(t.responseTime().getAsLong(), t.verdict().name().toLowerCase(Locale.ROOT).replace('_', ' '));
        }
        if (t.verdict() == Verdict.MEETS) {
            return new Bound(t.task().deadline(), "meets its deadline (no response time computed)");
        }
        return new Bound(-1, t.explanation());
    }
}
