/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.PathBound;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TaskSource;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.Verdict;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Flow;
import org.rsaml.analysis.plan.LinkPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.analysis.plan.PlanTimes;
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
 * End-to-end latency along every path of connections, under the runtime's communication: a module
 * with timed releases samples the latest value at its next release (it waits up to one period, then
 * takes its worst-case response time); a sporadic reacting module starts on the arrival (it may skip
 * an arrival within its minimum interval, so it waits up to that interval); an aperiodic one has no
 * bound. Delivery between modules is a memory write in one process and counts as 0. The maximum data
 * age adds the period of the last stage, whose output stays in place until replaced.
 */
public final class Latencies {

    /** Paths examined per requirement before giving up (said so, never a silent pass). */
    static final int MAX_PATHS = 100_000;

    private Latencies() {
    }

    /** A stage: how long data can take through a module, or unbounded (hop null) and why. */
    private record Stage(Hop hop, long periodNs, String unbounded) {
    }

    public static List<LatencyResult> analyse(ExecutionPlan plan, List<LatencyRequirement> requirements, List<ProcessorTiming> processors) {
        if (requirements.isEmpty()) {
            return List.of();
        }
        Map<String, List<TaskResult>> byModule = new HashMap<>();
        Map<String, List<TaskSource>> sourcesByModule = new HashMap<>();
        for (ProcessorTiming p : processors) {
            for (int i = 0; i < p.sources().size(); i++) {
                TaskSource s = p.sources().get(i);
                byModule.computeIfAbsent(s.task().group(), k -> new ArrayList<>()).add(p.result().tasks().get(i));
                sourcesByModule.computeIfAbsent(s.task().group(), k -> new ArrayList<>()).add(s);
            }
        }
        Map<PlannedModule, Stage> stages = new HashMap<>();
        for (PlannedModule m : plan.modules()) {
            stages.put(m, stage(m, byModule.getOrDefault(m.qualifiedName(), List.of()),
                    sourcesByModule.getOrDefault(m.qualifiedName(), List.of())));
        }
        List<LatencyResult> results = new ArrayList<>();
        for (LatencyRequirement r : requirements) {
            results.add(new Search(plan, stages, r).run());
        }
        return results;
    }

    private static Stage stage(PlannedModule m, List<TaskResult> results, List<TaskSource> sources) {
        Stage best = null;
        for (int i = 0; i < results.size(); i++) {
            TaskResult t = results.get(i);
            boolean reaction = "reaction".equals(sources.get(i).kind());
            if (t.responseTime().isEmpty()) {
                return new Stage(null, 0, m.qualifiedName() + " has no bounded response time (" + t.explanation() + ")");
            }
            long r = t.responseTime().getAsLong();
            long wait = t.task().period();
            String how = reaction
                    ? "reacts to the arrival (may skip arrivals within its minimum interval of " + RsamlTimes.text(wait) + ")"
                    : "samples the latest value at its next release of " + t.task().name() + " (every " + RsamlTimes.text(wait) + ")";
            Stage s = new Stage(new Hop(m.qualifiedName(), m.module(), how, wait, r), t.task().period(), null);
            if (best == null || s.hop().totalNs() > best.hop().totalNs()) {
                best = s;
            }
        }
        if (m.reactive() && m.minIntervalNs() == 0) {
            return new Stage(null, 0, m.qualifiedName() + " reacts aperiodically: its response time has no bound");
        }
        if (best == null) {
            return new Stage(null, 0, m.qualifiedName() + " is never activated");
        }
        return best;
    }

    private static final class Search {
        final ExecutionPlan plan;
        final Map<PlannedModule, Stage> stages;
        final LatencyRequirement requirement;
        final Set<PlannedModule> visited = new HashSet<>();
        final List<Hop> hops = new ArrayList<>();
        /** The modules, ports and links the current path has passed, for {@code via}. */
        final List<EObject> trail = new ArrayList<>();
        /** The longest paths found so far (the shortest of them first, to be replaced). */
        final java.util.PriorityQueue<PathBound> listed;
        List<EObject> via = List.of();
        int paths;
        long worstReaction = -1;
        long worstAge = -1;
        List<Hop> worstPath = List.of();
        String unbounded;
        /** Why the current path has no bound (its first stage without one), or null. */
        String pathUnbounded;
        Actuator actuator;
        EntryPort entry;
        /** The modules from which the target can be reached: the search goes nowhere else. */
        Set<PlannedModule> reaching;

        Search(ExecutionPlan plan, Map<PlannedModule, Stage> stages, LatencyRequirement requirement) {
            this.plan = plan;
            this.stages = stages;
            this.requirement = requirement;
            boolean age = requirement.getKind() == LatencyKind.DATA_AGE;
            this.longest = Comparator.comparingLong((PathBound b) -> b.bounded() ? (age ? b.dataAgeNs() : b.reactionNs()) : Long.MAX_VALUE);
            this.listed = new java.util.PriorityQueue<>(longest);
        }

        /** Paths by their bound for the requirement's kind; a path without a bound is the longest. */
        final Comparator<PathBound> longest;

        private void list(PathBound b) {
            listed.add(b);
            if (listed.size() > LatencyResult.MAX_LISTED_PATHS) {
                listed.poll();
            }
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
            via = List.copyOf(requirement.getVia());
            List<String> through = via.stream().map(this::label).toList();
            String pathWord = through.isEmpty() ? "path" : "path through " + String.join(", then ", through);
            if (requirement.getTarget() instanceof Actuator a) {
                actuator = a;
            } else if (requirement.getTarget() instanceof EntryPort e) {
                entry = e;
            } else {
                return fail(name, from, to, maxNs, age, "the target " + to + " is neither an actuator nor an entry port: choose one");
            }
            reaching = reaching();
            if (requirement.getSource() instanceof Sensor s) {
                for (PlannedModule m : plan.modules()) {
                    if (m.module().getSensors().contains(s) && reaching.contains(m)) {
                        Stage st = stages.get(m);
                        if (st.hop() != null && m.reactive() && m.releases().isEmpty()) {
                            st = new Stage(null, 0, m.qualifiedName() + " reacts to data only: reading sensor " + from
                                    + " does not start it, so nothing bounds when it reads the sensor");
                        }
                        enter(m, st);
                    }
                }
            } else if (requirement.getSource() instanceof OutputPort p && plan.port(p) != null) {
                PlannedPort port = plan.port(p);
                start(port.module(), port);
            } else {
                return fail(name, from, to, maxNs, age, "the source " + from + " is neither a sensor nor an output port of a module: choose one");
            }
            Verdict verdict;
            String explanation;
            long bound = age ? worstAge : worstReaction;
            String what = age ? "maximum data age" : "worst-case reaction time";
            if (this.paths > MAX_PATHS) {
                verdict = Verdict.NOT_ANALYSED;
                explanation = "not analysed: more than " + MAX_PATHS + " " + pathWord + "s from " + from + " to " + to;
            } else if (this.paths == 0) {
                verdict = Verdict.MISSES;
                explanation = through.isEmpty()
                        ? "no path of connections leads from " + from + " to " + to + ": the data never arrives"
                        : "no " + pathWord + " leads from " + from + " to " + to + ": the data never arrives that way";
            } else if (bound > maxNs) {
                verdict = Verdict.MISSES;
                explanation = "the " + what + " can reach " + RsamlTimes.text(bound) + ", more than " + RsamlTimes.text(maxNs);
            } else if (unbounded != null) {
                verdict = Verdict.NOT_ANALYSED;
                explanation = "not analysed: " + unbounded;
            } else {
                verdict = Verdict.MEETS;
                explanation = "the " + what + " is at most " + RsamlTimes.text(bound) + " over " + this.paths + " "
                        + (through.isEmpty() ? "path" + (this.paths == 1 ? "" : "s")
                                : (this.paths == 1 ? "path" : "paths") + " through " + String.join(", then ", through))
                        + ", within " + RsamlTimes.text(maxNs);
            }
            List<PathBound> longestFirst = new ArrayList<>(listed);
            longestFirst.sort(longest.reversed());
            return new LatencyResult(requirement, name, from, to, maxNs, age, verdict, worstReaction, worstAge, worstPath,
                    Math.min(this.paths, MAX_PATHS), explanation, through, longestFirst);
        }

        private LatencyResult fail(String name, String from, String to, long maxNs, boolean age, String why) {
            return new LatencyResult(requirement, name, from, to, maxNs, age, Verdict.NOT_ANALYSED, -1, -1, List.of(), 0,
                    "not analysed: " + why);
        }

        /**
         * One step out of a module: the trail elements it adds (the output port, the link, the entry
         * port), whether it arrives at the target entry port, and where the path goes on: into a
         * module's stage ({@code enter}), or past an inhibitor to the inhibited port ({@code inhibitor}).
         */
        private record Step(List<EObject> adds, boolean arrives, PlannedModule next, LinkPlan inhibitor) {
        }

        /** A module on the current path, with the steps out of it not taken yet. */
        private static final class Frame {
            final PlannedModule module;
            final long period;
            final List<Step> steps;
            final int trailBefore;
            final String unboundedBefore;
            /** How many hops the frame added to the path (its stage's, and a link's crossed to reach it). */
            final int hop;
            final boolean root;
            int next;

            Frame(PlannedModule module, long period, List<Step> steps, int trailBefore, String unboundedBefore, int hop, boolean root) {
                this.module = module;
                this.period = period;
                this.steps = steps;
                this.trailBefore = trailBefore;
                this.unboundedBefore = unboundedBefore;
                this.hop = hop;
                this.root = root;
            }
        }

        private final java.util.ArrayDeque<Frame> stack = new java.util.ArrayDeque<>();

        /**
         * Data (or, through an inhibitor, control) reaches module m, which takes it through its stage
         * st; every path on from there is followed depth first, with a stack of its own (a chain of any
         * length, no recursion).
         */
        private void enter(PlannedModule m, Stage st) {
            push(m, st, trail.size(), 0);
            search();
        }

        /** A path starting where module m's output port {@code only} sends. */
        private void start(PlannedModule m, PlannedPort only) {
            visited.add(m);
            int before = trail.size();
            trail.add(m.module());
            stack.push(new Frame(m, stages.get(m).periodNs(), steps(m, only), before, pathUnbounded, 0, true));
            search();
        }

        /**
         * Enters m (when the path may: not yet on it, not past the limit), recording when it drives the
         * actuator; link: the hops of the link crossed to reach m (0 or 1, already on the path).
         */
        private void push(PlannedModule m, Stage st, int trailBefore, int link) {
            if (paths > MAX_PATHS || !visited.add(m)) {
                trail.subList(trailBefore, trail.size()).clear();
                hops.subList(hops.size() - link, hops.size()).clear();
                return;
            }
            String before = pathUnbounded;
            trail.add(m.module());
            if (st.hop() == null) {
                // paths through here have no bound; they are still followed, to count those that reach the target
                if (pathUnbounded == null) {
                    pathUnbounded = st.unbounded();
                }
            } else {
                hops.add(st.hop());
            }
            if (actuator != null && m.module().getActuators().contains(actuator)) {
                record(st.periodNs());
            }
            stack.push(new Frame(m, st.periodNs(), steps(m, null), trailBefore, before, link + (st.hop() != null ? 1 : 0), false));
        }

        private void search() {
            while (!stack.isEmpty()) {
                Frame f = stack.peek();
                if (f.next == f.steps.size() || paths > MAX_PATHS) {
                    stack.pop();
                    hops.subList(hops.size() - f.hop, hops.size()).clear();
                    pathUnbounded = f.unboundedBefore;
                    visited.remove(f.module);
                    trail.subList(f.trailBefore, trail.size()).clear();
                    continue;
                }
                Step step = f.steps.get(f.next++);
                int before = trail.size();
                trail.addAll(step.adds());
                PlannedModule next = step.next();
                Hop crossing = next == null ? null : crossing(f.module, next);
                int link = crossing == null ? 0 : 1;
                if (crossing != null) {
                    hops.add(crossing);
                }
                if (step.arrives()) {
                    record(f.period);
                }
                if (next == null || visited.contains(next) || !reaching.contains(next)) {
                    trail.subList(before, trail.size()).clear();
                    hops.subList(hops.size() - link, hops.size()).clear();
                } else if (step.inhibitor() == null) {
                    push(next, stages.get(next), before, link);
                } else if (paths <= MAX_PATHS) {
                    LinkPlan inhibitor = step.inhibitor();
                    visited.add(next);
                    hops.add(new Hop(inhibitor.qualifiedName(), next.module(), "inhibits " + inhibitor.target().qualifiedName()
                            + " from the trigger's message on, at once", 0, 0));
                    stack.push(new Frame(next, 0, steps(next, inhibitor.target()), before, pathUnbounded, link + 1, false));
                } else {
                    trail.subList(before, trail.size()).clear();
                    hops.subList(hops.size() - link, hops.size()).clear();
                }
            }
        }

        /**
         * What m sends (from {@code only}, or from every output port): along its flows; a suppressor's
         * trigger message to the suppressed entry port (as data when the two carry the same data, else
         * as control: the target's input is blocked, which its module acts on at its next activation);
         * an inhibitor's, at once to the inhibited output port, whose module then sends nothing more
         * there, while what it sent before still travels on.
         */
        private List<Step> steps(PlannedModule m, PlannedPort only) {
            List<Step> steps = new ArrayList<>();
            for (PlannedPort out : m.outputs()) {
                if (only != null && out != only) {
                    continue;
                }
                for (Flow f : out.outgoing()) {
                    steps.add(new Step(List.of(out.port(), f.target().port()), entry != null && f.target().port() == entry,
                            f.target().module(), null));
                }
                for (LinkPlan link : out.triggers()) {
                    List<EObject> adds = List.of(out.port(), link.link(), link.target().port());
                    if (link.inhibitor()) {
                        steps.add(new Step(adds, false, link.target().module(), link));
                    } else {
                        steps.add(new Step(adds, entry != null && link.target().port() == entry, link.target().module(), null));
                    }
                }
            }
            return steps;
        }

        /**
         * The link a message from module a to module b crosses when their processors are on different
         * hosts: the link latencies of both processors (0 each when not given), as a hop of its own;
         * null on one host or when neither processor gives a latency.
         */
        private static Hop crossing(PlannedModule a, PlannedModule b) {
            String from = TimingAnalysis.host(a.processor());
            String to = TimingAnalysis.host(b.processor());
            if (from.equals(to)) {
                return null;
            }
            long ns = Math.addExact(linkNs(a.processor()), linkNs(b.processor()));
            if (ns == 0) {
                return null;
            }
            return new Hop("link " + hostName(from) + " -> " + hostName(to), b.module(), "crosses the links between host "
                    + hostName(from) + " and host " + hostName(to) + " (the link latencies of " + processorName(a.processor())
                    + " and " + processorName(b.processor()) + ")", ns, 0);
        }

        private static long linkNs(org.rsaml.model.Processor p) {
            return p == null ? 0 : PlanTimes.nanos(p.getLinkLatency(), p);
        }

        private static String hostName(String host) {
            return host.isEmpty() ? "main" : "'" + host + "'";
        }

        private static String processorName(org.rsaml.model.Processor p) {
            return p == null ? "the default processor" : "processor " + RsamlLabels.name(p);
        }

        /** The modules with a path of flows to the target (the target's own module included). */
        private Set<PlannedModule> reaching() {
            Map<PlannedModule, List<PlannedModule>> upstream = new HashMap<>();
            List<PlannedModule> todo = new ArrayList<>();
            for (Flow f : plan.flows()) {
                upstream.computeIfAbsent(f.target().module(), k -> new ArrayList<>()).add(f.source().module());
                if (entry != null && f.target().port() == entry) {
                    todo.add(f.source().module());
                }
            }
            for (LinkPlan l : plan.links()) {
                upstream.computeIfAbsent(l.target().module(), k -> new ArrayList<>()).add(l.trigger().module());
                if (entry != null && !l.inhibitor() && l.target().port() == entry) {
                    todo.add(l.trigger().module());
                }
            }
            if (actuator != null) {
                for (PlannedModule m : plan.modules()) {
                    if (m.module().getActuators().contains(actuator)) {
                        todo.add(m);
                    }
                }
            }
            Set<PlannedModule> seen = new HashSet<>();
            while (!todo.isEmpty()) {
                PlannedModule m = todo.remove(todo.size() - 1);
                if (seen.add(m)) {
                    todo.addAll(upstream.getOrDefault(m, List.of()));
                }
            }
            return seen;
        }

        private void record(long lastPeriod) {
            if (!throughVia()) {
                return;
            }
            paths++;
            if (pathUnbounded != null) {
                if (unbounded == null) {
                    unbounded = pathUnbounded;
                }
                list(new PathBound(hops, -1, -1, pathUnbounded));
                return;
            }
            long reaction = 0;
            for (Hop h : hops) {
                reaction = Math.addExact(reaction, h.totalNs());
            }
            long age = Math.addExact(reaction, lastPeriod);
            list(new PathBound(hops, reaction, age, null));
            if (reaction > worstReaction || age > worstAge) {
                boolean ageKind = requirement.getKind() == LatencyKind.DATA_AGE;
                if ((ageKind ? age > worstAge : reaction > worstReaction)) {
                    worstPath = List.copyOf(hops);
                }
                worstReaction = Math.max(worstReaction, reaction);
                worstAge = Math.max(worstAge, age);
            }
        }

        /** Whether the current path passes the requirement's {@code via} elements in their order. */
        private boolean throughVia() {
            int next = 0;
            for (int i = 0; i < trail.size() && next < via.size(); i++) {
                if (trail.get(i) == via.get(next)) {
                    next++;
                }
            }
            return next == via.size();
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
}
