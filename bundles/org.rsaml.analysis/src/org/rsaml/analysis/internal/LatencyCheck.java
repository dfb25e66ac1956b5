/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.internal.Latencies.Stage;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlanTimes;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.model.Actuator;
import org.rsaml.model.EntryPort;
import org.rsaml.model.LatencyKind;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Sensor;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlTimes;

/**
 * One latency requirement checked: what it names (a source the generated code sends from, a target it
 * receives at, {@code via} elements it runs, a bound it can count), the search of its paths from where
 * its source sends ({@link PathSearch}), and the verdict in words.
 */
final class LatencyCheck {

    private final ExecutionPlan plan;
    private final Map<PlannedModule, Stage> stages;
    private final LatencyRequirement requirement;

    LatencyCheck(ExecutionPlan plan, Map<PlannedModule, Stage> stages, LatencyRequirement requirement) {
        this.plan = plan;
        this.stages = stages;
        this.requirement = requirement;
    }

    LatencyResult run() {
        String name = RsamlLabels.name(requirement);
        String from = label(requirement.getSource());
        String to = label(requirement.getTarget());
        boolean age = requirement.getKind() == LatencyKind.DATA_AGE;
        TimeUnit unit = RsamlTimes.unit(requirement);
        double max = requirement.getMaxLatency();
        if (!Double.isFinite(max) || max <= 0 || !RsamlTimes.representable(max, requirement)) {
            return fail(name, from, to, 0, age, "maxLatency " + RsamlLabels.number(max) + " " + unit.getLiteral()
                    + " is not a positive time generated code can count: give the longest latency allowed");
        }
        long maxNs = PlanTimes.nanos(max, requirement);
        for (EObject e : requirement.getVia()) {
            boolean known = e instanceof Module || e instanceof org.rsaml.model.Port p && plan.port(p) != null
                    || e instanceof SubsumptionLink l && plan.links().stream().anyMatch(k -> k.link() == l);
            if (!known) {
                return fail(name, from, to, maxNs, age, "via names " + label(e) + ", which is not a module, a port of a module,"
                        + " an inhibitor or a suppressor that the generated code runs: name those the path passes through");
            }
        }
        List<EObject> via = List.copyOf(requirement.getVia());
        List<String> through = via.stream().map(this::label).toList();
        String pathWord = through.isEmpty() ? "path" : "path through " + String.join(", then ", through);
        if (!(requirement.getTarget() instanceof Actuator) && !(requirement.getTarget() instanceof EntryPort)) {
            return fail(name, from, to, maxNs, age, "the target " + to + " is neither an actuator nor an entry port: choose one");
        }
        PathSearch search = new PathSearch(plan, stages, age, via, requirement.getTarget() instanceof Actuator a ? a : null,
                requirement.getTarget() instanceof EntryPort e ? e : null);
        if (requirement.getSource() instanceof Sensor s) {
            for (PlannedModule m : plan.modules()) {
                if (m.module().getSensors().contains(s) && search.reaches(m)) {
                    Stage st = stages.get(m);
                    if (st.hop() != null && m.reactive() && m.releases().isEmpty()) {
                        st = new Stage(null, 0, m.qualifiedName() + " reacts to data only: reading sensor " + from
                                + " does not start it, so nothing bounds when it reads the sensor");
                    }
                    search.enter(m, st);
                }
            }
        } else if (requirement.getSource() instanceof OutputPort p && plan.port(p) != null) {
            PlannedPort port = plan.port(p);
            search.start(port.module(), port);
        } else {
            return fail(name, from, to, maxNs, age, "the source " + from + " is neither a sensor nor an output port of a module: choose one");
        }
        Verdict verdict;
        String explanation;
        int paths = search.paths();
        long bound = age ? search.worstAge() : search.worstReaction();
        String what = age ? "maximum data age" : "worst-case reaction time";
        if (paths > PathSearch.MAX_PATHS) {
            verdict = Verdict.NOT_ANALYSED;
            explanation = "not analysed: more than " + PathSearch.MAX_PATHS + " " + pathWord + "s from " + from + " to " + to;
        } else if (paths == 0) {
            verdict = Verdict.MISSES;
            explanation = through.isEmpty()
                    ? "no path of connections leads from " + from + " to " + to + ": the data never arrives"
                    : "no " + pathWord + " leads from " + from + " to " + to + ": the data never arrives that way";
        } else if (bound > maxNs) {
            verdict = Verdict.MISSES;
            explanation = "the " + what + " can reach " + RsamlTimes.text(bound) + ", more than " + RsamlTimes.text(maxNs);
        } else if (search.unbounded() != null) {
            verdict = Verdict.NOT_ANALYSED;
            explanation = "not analysed: " + search.unbounded();
        } else {
            verdict = Verdict.MEETS;
            explanation = "the " + what + " is at most " + RsamlTimes.text(bound) + " over " + paths + " "
                    + (through.isEmpty() ? "path" + (paths == 1 ? "" : "s")
                            : (paths == 1 ? "path" : "paths") + " through " + String.join(", then ", through))
                    + ", within " + RsamlTimes.text(maxNs);
        }
        return new LatencyResult(requirement, name, from, to, maxNs, age, verdict, search.worstReaction(), search.worstAge(),
                search.worstPath(), Math.min(paths, PathSearch.MAX_PATHS), explanation, through, search.longestFirst());
    }

    private LatencyResult fail(String name, String from, String to, long maxNs, boolean age, String why) {
        return new LatencyResult(requirement, name, from, to, maxNs, age, Verdict.NOT_ANALYSED, -1, -1, List.of(), 0,
                "not analysed: " + why);
    }

    private String label(Object element) {
        if (element instanceof Module m) {
            PlannedModule pm = plan.modules().stream().filter(x -> x.module() == m).findFirst().orElse(null);
            return pm == null ? "module '" + RsamlLabels.name(m) + "'" : pm.qualifiedName();
        }
        if (element instanceof SubsumptionLink l) {
            return plan.links().stream().filter(k -> k.link() == l).map(k -> (k.inhibitor() ? "inhibitor " : "suppressor ")
                    + k.qualifiedName()).findFirst().orElse(RsamlLabels.describe(l));
        }
        if (element instanceof Sensor s) {
            return "sensor '" + RsamlLabels.name(s) + "'";
        }
        if (element instanceof Actuator a) {
            return "actuator '" + RsamlLabels.name(a) + "'";
        }
        if (element instanceof org.rsaml.model.Port p && plan.port(p) != null) {
            return plan.port(p).qualifiedName();
        }
        return element == null ? "nothing" : RsamlLabels.describe((org.eclipse.emf.ecore.EObject) element);
    }
}
