/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.PathBound;
import org.rsaml.analysis.internal.Latencies.Stage;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Flow;
import org.rsaml.analysis.plan.LinkPlan;
import org.rsaml.analysis.plan.PlanTimes;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.model.Actuator;
import org.rsaml.model.EntryPort;
import org.rsaml.model.support.RsamlLabels;

/**
 * Every path of one latency requirement, depth first with a stack of its own (a chain of any length,
 * no recursion), only through the modules from which its target can be reached: each path's bound is
 * the sum of its stages (and of the links it crosses between hosts), recorded when the path reaches the
 * target through the requirement's {@code via} elements; the worst, and the longest paths for the list.
 * The walk is bounded by the steps it takes ({@link PathSteps}), dead ends included: past them it stops
 * ({@link #cut()}) and the worst bound is taken from {@link LongestPaths} where that is exact.
 */
final class PathSearch {

    private final int maxSteps = PathSteps.limit();
    private final ExecutionPlan plan;
    private final Map<PlannedModule, Stage> stages;
    private final boolean age;
    private final List<EObject> via;
    private final Actuator actuator;
    private final EntryPort entry;
    /** Whether paths are listed (the reports) or only the worst kept (verdicts). */
    private final boolean listPaths;
    private final Set<PlannedModule> visited = new HashSet<>();
    private final HopStack hops = new HopStack();
    /** The modules, ports and links the current path has passed, for {@code via}. */
    private final List<EObject> trail = new ArrayList<>();
    /** Paths by their bound for the requirement's kind; a path without a bound is the longest. */
    private final Comparator<PathBound> longest;
    /** The longest paths found so far (the shortest of them first, to be replaced). */
    private final PriorityQueue<PathBound> listed;
    /**
     * The modules from which the target can be reached, each with the fewest steps it takes: the search goes
     * nowhere else, and tries the nearest first (so that a walk cut short has found paths to report).
     */
    private final Map<PlannedModule, Integer> reaching;
    private int paths;
    /** The stages of the paths listed, and whether a path was left off the list. */
    private long listedStages;
    private boolean listFull;
    private int work;
    private long worstReaction = -1;
    private long worstAge = -1;
    private List<Hop> worstPath = List.of();
    private String unbounded;
    /** Why the current path has no bound (its first stage without one), or null. */
    private String pathUnbounded;

    /**
     * @param age      whether the requirement bounds the data age (else the reaction time)
     * @param via      the elements its paths must pass, in order
     * @param actuator its target when an actuator, else null
     * @param entry    its target when an entry port, else null
     * @param listPaths whether to list the longest paths ({@link #longestFirst()}), or only keep the worst
     */
    PathSearch(ExecutionPlan plan, Map<PlannedModule, Stage> stages, boolean age, List<EObject> via, Actuator actuator,
            EntryPort entry, boolean listPaths) {
        this.listPaths = listPaths;
        this.plan = plan;
        this.stages = stages;
        this.age = age;
        this.via = via;
        this.actuator = actuator;
        this.entry = entry;
        this.longest = Comparator.comparingLong(this::key);
        this.listed = new PriorityQueue<>(longest);
        this.reaching = reaching();
    }

    /** Whether the target can be reached from module m. */
    boolean reaches(PlannedModule m) {
        return reaching.containsKey(m);
    }

    /** How many paths reached the target (all of them unless {@link #cut()}). */
    int paths() {
        return paths;
    }

    /** Whether the walk stopped after {@link #maxSteps()} steps, before following every path. */
    boolean cut() {
        return work > maxSteps;
    }

    /** The steps the walk takes before it stops. */
    int maxSteps() {
        return maxSteps;
    }

    /** Whether module m drives the requirement's actuator. */
    boolean drives(PlannedModule m) {
        return actuator != null && m.module().getActuators().contains(actuator);
    }

    long worstReaction() {
        return worstReaction;
    }

    long worstAge() {
        return worstAge;
    }

    List<Hop> worstPath() {
        return worstPath;
    }

    /** Why some path has no bound (the first found), or null. */
    String unbounded() {
        return unbounded;
    }

    /** The longest paths, the longest first ({@link LatencyResult#MAX_LISTED_PATHS} at most). */
    List<PathBound> longestFirst() {
        List<PathBound> out = new ArrayList<>(listed);
        out.sort(longest.reversed());
        return out;
    }

    /**
     * A path reaching the target, listed when it is among the longest so far: at most {@link LatencyResult#MAX_LISTED_PATHS},
     * and at most {@link LatencyResult#MAX_LISTED_STAGES} stages in all (long paths: fewer of them). A path that would be
     * dropped at once is not copied: a path costs its copy only when listed.
     */
    private void list(long key, long reaction, long dataAge, String why) {
        if (!listPaths) {
            return;
        }
        if (LatencyResult.overListed(listed.size() + 1, listedStages + hops.size())) {
            PathBound shortest = listed.peek();
            if (shortest == null || key <= key(shortest)) {
                listFull = true;
                return;
            }
        }
        PathBound b = new PathBound(hops.list(), reaction, dataAge, why, trail);
        listed.add(b);
        listedStages += b.hops().size();
        while (listed.size() > 1 && LatencyResult.overListed(listed.size(), listedStages)) {
            listedStages -= listed.poll().hops().size();
            listFull = true;
        }
    }

    /** A path's place in the list: its bound for the requirement's kind; a path without a bound is the longest. */
    private long key(PathBound b) {
        return b.bounded() ? (age ? b.dataAgeNs() : b.reactionNs()) : Long.MAX_VALUE;
    }

    /** Whether some path reaching the target was left off the list (or dropped from it). */
    boolean listFull() {
        return listFull;
    }

    /**
     * One step out of a module: the trail elements it adds (the output port, the link, the entry
     * port), whether it arrives at the target entry port, and where the path goes on: into a
     * module's stage ({@code enter}), or past an inhibitor to the inhibited port ({@code inhibitor}).
     */
    record Step(List<EObject> adds, boolean arrives, PlannedModule next, LinkPlan inhibitor) {
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

    private final ArrayDeque<Frame> stack = new ArrayDeque<>();

    /**
     * Data (or, through an inhibitor, control) reaches module m, which takes it through its stage
     * st; every path on from there is followed depth first, with a stack of its own (a chain of any
     * length, no recursion).
     */
    void enter(PlannedModule m, Stage st) {
        push(m, st, trail.size(), 0);
        search();
    }

    /** A path starting where module m's output port {@code only} sends. */
    void start(PlannedModule m, PlannedPort only) {
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
        if (cut() || !visited.add(m)) {
            trail.subList(trailBefore, trail.size()).clear();
            hops.pop(link);
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
            hops.push(st.hop());
        }
        if (drives(m)) {
            record(st.periodNs());
        }
        stack.push(new Frame(m, st.periodNs(), steps(m, null), trailBefore, before, link + (st.hop() != null ? 1 : 0), false));
    }

    private void search() {
        while (!stack.isEmpty()) {
            Frame f = stack.peek();
            if (f.next == f.steps.size() || ++work > maxSteps) {
                stack.pop();
                hops.pop(f.hop);
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
                hops.push(crossing);
            }
            if (step.arrives()) {
                record(f.period);
            }
            if (next == null || visited.contains(next) || !reaching.containsKey(next)) {
                trail.subList(before, trail.size()).clear();
                hops.pop(link);
            } else if (step.inhibitor() == null) {
                push(next, stages.get(next), before, link);
            } else if (!cut()) {
                LinkPlan inhibitor = step.inhibitor();
                visited.add(next);
                hops.push(inhibits(inhibitor, next));
                stack.push(new Frame(next, 0, steps(next, inhibitor.target()), before, pathUnbounded, link + 1, false));
            } else {
                trail.subList(before, trail.size()).clear();
                hops.pop(link);
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
    List<Step> steps(PlannedModule m, PlannedPort only) {
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
        steps.sort(Comparator.comparingInt((Step s) -> s.arrives() ? -1 : reaching.getOrDefault(s.next(), Integer.MAX_VALUE)));
        return steps;
    }

    /**
     * The link a message from module a to module b crosses when their processors are on different
     * hosts: the link latencies of both processors (0 each when not given), as a hop of its own;
     * null on one host or when neither processor gives a latency.
     */
    static Hop crossing(PlannedModule a, PlannedModule b) {
        String from = RsamlLabels.host(a.processor());
        String to = RsamlLabels.host(b.processor());
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

    /** The hop of an inhibitor whose trigger's message blocks its target at once. */
    static Hop inhibits(LinkPlan inhibitor, PlannedModule target) {
        return new Hop(inhibitor.qualifiedName(), target.module(), "inhibits " + inhibitor.target().qualifiedName()
                + " from the trigger's message on, at once", 0, 0);
    }

    private static long linkNs(org.rsaml.model.Processor p) {
        return p == null ? 0 : PlanTimes.nanos(p.getLinkLatency(), p);
    }

    private static String hostName(String host) {
        return host.isEmpty() ? RsamlLabels.MAIN_HOST : "'" + host + "'";
    }

    private static String processorName(org.rsaml.model.Processor p) {
        return p == null ? "the default processor" : "processor " + RsamlLabels.name(p);
    }

    /** The modules with a path of flows to the target (the target's own module included), with its fewest steps. */
    private Map<PlannedModule, Integer> reaching() {
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
        Map<PlannedModule, Integer> distance = new HashMap<>();
        ArrayDeque<PlannedModule> queue = new ArrayDeque<>();
        for (PlannedModule m : todo) {
            if (distance.putIfAbsent(m, 0) == null) {
                queue.add(m);
            }
        }
        while (!queue.isEmpty()) {
            PlannedModule m = queue.poll();
            for (PlannedModule u : upstream.getOrDefault(m, List.of())) {
                if (distance.putIfAbsent(u, distance.get(m) + 1) == null) {
                    queue.add(u);
                }
            }
        }
        return distance;
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
            list(Long.MAX_VALUE, -1, -1, pathUnbounded);
            return;
        }
        long reaction = hops.total();
        long dataAge = Math.addExact(reaction, lastPeriod);
        list(age ? dataAge : reaction, reaction, dataAge, null);
        if (reaction > worstReaction || dataAge > worstAge) {
            if (age ? dataAge > worstAge : reaction > worstReaction) {
                worstPath = hops.list();
            }
            worstReaction = Math.max(worstReaction, reaction);
            worstAge = Math.max(worstAge, dataAge);
        }
    }

    /**
     * The hops of the current path, a stack (pushed at the end, popped back to a shorter size), with the total of each
     * prefix kept as hops are pushed: a path's reaction time costs O(1) when it reaches the target, not its length (a
     * long path found again and again, changing near its end, would cost its length each time). Only push and popTo
     * change it, so the totals always match the hops.
     */
    private static final class HopStack {
        /** A prefix whose total does not fit a long. */
        private static final long OVERFLOW = Long.MIN_VALUE;
        private Hop[] hops = new Hop[16];
        /** totals[i]: the total of the first i hops. */
        private long[] totals = new long[17];
        private int size;

        int size() {
            return size;
        }

        void push(Hop h) {
            if (size == hops.length) {
                hops = Arrays.copyOf(hops, size * 2);
                totals = Arrays.copyOf(totals, size * 2 + 1);
            }
            long before = totals[size];
            long total;
            try {
                total = before == OVERFLOW ? OVERFLOW : Math.addExact(before, h.totalNs());
            } catch (ArithmeticException e) {
                total = OVERFLOW;
            }
            hops[size++] = h;
            totals[size] = total;
        }

        /** Takes the hops above the first {@code n} off. */
        void popTo(int n) {
            if (n < 0 || n > size) {
                throw new IllegalArgumentException("popTo " + n + " on a stack of " + size + " hops");
            }
            Arrays.fill(hops, n, size, null);
            size = n;
        }

        /** Takes the last {@code n} hops off. */
        void pop(int n) {
            popTo(size - n);
        }

        /** The total of the hops, as summing them with Math.addExact gives it (an ArithmeticException when it does not fit). */
        long total() {
            long total = totals[size];
            if (total == OVERFLOW) {
                throw new ArithmeticException("long overflow");
            }
            return total;
        }

        /** The hops, a copy. */
        List<Hop> list() {
            return List.of(Arrays.copyOf(hops, size));
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
}
