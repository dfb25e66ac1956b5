/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.PathBound;
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
    /** Whether the paths are listed with their bounds (the reports), or only the worst kept (verdicts). */
    private final boolean listPaths;

    LatencyCheck(ExecutionPlan plan, Map<PlannedModule, Stage> stages, LatencyRequirement requirement, boolean listPaths) {
        this.plan = plan;
        this.stages = stages;
        this.requirement = requirement;
        this.listPaths = listPaths;
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
                requirement.getTarget() instanceof EntryPort e ? e : null, listPaths);
        LongestPaths dp = new LongestPaths(search, stages, age, via);
        List<Runnable> roots = new ArrayList<>();
        if (requirement.getSource() instanceof Sensor s) {
            for (PlannedModule m : plan.modules()) {
                if (m.module().getSensors().contains(s) && search.reaches(m)) {
                    Stage st0 = stages.get(m);
                    Stage st = st0.hop() != null && m.reactive() && m.releases().isEmpty()
                            ? new Stage(null, 0, m.qualifiedName() + " reacts to data only: reading sensor " + from
                                    + " does not start it, so nothing bounds when it reads the sensor")
                            : st0;
                    search.enter(m, st);
                    roots.add(() -> dp.enter(m, st));
                }
            }
        } else if (requirement.getSource() instanceof OutputPort p && plan.port(p) != null) {
            PlannedPort port = plan.port(p);
            search.start(port.module(), port);
            roots.add(() -> dp.start(port.module(), port));
        } else {
            return fail(name, from, to, maxNs, age, "the source " + from + " is neither a sensor nor an output port of a module: choose one");
        }
        int paths = search.paths();
        long worstReaction = search.worstReaction();
        long worstAge = search.worstAge();
        List<Hop> worstPath = search.worstPath();
        List<PathBound> listed = search.longestFirst();
        boolean cut = search.cut();
        boolean exact = true;
        String mayBeUnbounded = null;
        if (cut) {
            // too many paths to follow each: the worst bound by dynamic programming, exact only where the modules form no
            // cycle (else its walks include some through a module twice, which are no path): otherwise what the search proved
            roots.forEach(Runnable::run);
            exact = !dp.cyclic();
            if (exact) {
                worstReaction = dp.worst(false);
                worstAge = dp.worst(true);
                PathBound worst = dp.worst();
                worstPath = worst == null ? List.of() : worst.hops();
                if (listPaths && worst != null && !listed.contains(worst)) {
                    List<PathBound> more = new ArrayList<>(listed);
                    more.add(0, worst);
                    long stages = more.stream().mapToLong(b -> b.hops().size()).sum();
                    while (more.size() > 1 && LatencyResult.overListed(more.size(), stages)) {
                        stages -= more.remove(more.size() - 1).hops().size();
                    }
                    listed = more;
                }
                paths = (int) Math.min(Integer.MAX_VALUE, Math.max(paths, dp.bounded()));
                mayBeUnbounded = dp.mayPassUnbounded();
            }
        }
        Verdict verdict;
        String explanation;
        long bound = age ? worstAge : worstReaction;
        String what = age ? "maximum data age" : "worst-case reaction time";
        String stopped = "following each " + pathWord + " from " + from + " to " + to + " stopped after " + search.maxSteps()
                + " steps (" + search.paths() + " reached the target)";
        if (bound > maxNs) {
            verdict = Verdict.MISSES;
            explanation = "the " + what + " can reach " + RsamlTimes.text(bound) + ", more than " + RsamlTimes.text(maxNs);
        } else if (search.unbounded() != null) {
            verdict = Verdict.NOT_ANALYSED;
            explanation = "not analysed: " + search.unbounded();
        } else if (!exact) {
            verdict = Verdict.NOT_ANALYSED;
            explanation = "not analysed: " + stopped + ", and the paths pass a cycle of modules (connections or inhibitors leading back"
                    + " to a module passed), where the longest is only found by following each: break the cycle, or name the path with via";
        } else if (mayBeUnbounded != null) {
            verdict = Verdict.NOT_ANALYSED;
            explanation = "not analysed: " + mayBeUnbounded + ", and paths from " + from + " to " + to + " may pass it; " + stopped;
        } else if (paths == 0 || bound < 0) {
            verdict = Verdict.MISSES;
            explanation = through.isEmpty()
                    ? "no path of connections leads from " + from + " to " + to + ": the data never arrives"
                    : "no " + pathWord + " leads from " + from + " to " + to + ": the data never arrives that way";
        } else {
            verdict = Verdict.MEETS;
            explanation = "the " + what + " is at most " + RsamlTimes.text(bound) + " over " + count(paths) + " "
                    + (through.isEmpty() ? "path" + (paths == 1 ? "" : "s")
                            : (paths == 1 ? "path" : "paths") + " through " + String.join(", then ", through))
                    + ", within " + RsamlTimes.text(maxNs);
        }
        String unlisted = "";
        if (!listPaths) {
            unlisted = "the paths are not listed: the analysis was run for its verdicts (rsaml analyze lists them)";
        } else if (cut) {
            unlisted = "the paths were followed one by one for " + search.maxSteps() + " steps, " + search.paths() + " of them to the target;"
                    + (exact ? " the others were counted (" + count(paths) + " in all) and the worst found by a longest-path computation, which"
                            + " does not list them: listed are the longest of those followed, and the worst"
                            : " the others were not followed: listed are the longest of those followed");
        } else if (paths > listed.size()) {
            unlisted = "the " + listed.size() + " longest of " + paths + " are listed (at most " + LatencyResult.MAX_LISTED_PATHS
                    + " paths of " + LatencyResult.MAX_LISTED_STAGES + " stages in all)";
        }
        return new LatencyResult(requirement, name, from, to, maxNs, age, verdict, worstReaction, worstAge,
                worstPath, paths, explanation, through, listed, unlisted);
    }

    /** A number of paths as counted: at most Integer.MAX_VALUE, which then stands for at least that many. */
    private static String count(int paths) {
        return paths == Integer.MAX_VALUE ? "at least " + paths : String.valueOf(paths);
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
