/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.PathBound;
import org.rsaml.analysis.internal.Latencies.Stage;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;

/**
 * The worst bound of a latency requirement's paths without following each path: a longest path by
 * dynamic programming over the states "data is in module m, having passed the first k {@code via}
 * elements" (each state once, each step out of it once: linear in the plan times the length of
 * {@code via}). One module can be several states (entered through its stage, or past an inhibitor onto
 * one of its ports; a sensor's reader at the start and again later), so a walk over the states can pass
 * a module twice, which a path of {@link PathSearch} never does. Only where the modules themselves, over
 * every state reached, form no cycle is every walk a path, and the worst bound, the number of paths with
 * a bound and whether a path passes a stage without one exact; elsewhere ({@link #cyclic()}) the walks
 * include some that are no path, and the results below are no verdict.
 */
final class LongestPaths {

    private final PathSearch search;
    private final Map<PlannedModule, Stage> stages;
    private final boolean age;
    private final List<EObject> via;
    private final Map<Key, Node> nodes = new HashMap<>();
    private final List<Node> roots = new ArrayList<>();
    private boolean cyclic;

    /** A state: module m entered through its stage (or, {@code only} set, past an inhibitor), k via elements passed. */
    private record Key(PlannedModule m, PlannedPort only, int k, Stage stage, long period) {
    }

    private static final class Node {
        final Key key;
        /** 0 not seen, 1 on the walk, 2 done. */
        int state;
        int nextStep;
        List<PathSearch.Step> steps;
        /** The worst reaction and data age after the node's own stage over suffixes with a bound, -1 when none. */
        long reaction = -1;
        long dataAge = -1;
        /** Suffixes with a bound, at most Long.MAX_VALUE. */
        long count;
        /** The worst suffix for the requirement's kind: -1 ends here, 2i+0 ends with step i, 2i+1 goes on through step i. */
        int choice = -2;
        Node(Key key) {
            this.key = key;
        }
    }

    LongestPaths(PathSearch search, Map<PlannedModule, Stage> stages, boolean age, List<EObject> via) {
        this.search = search;
        this.stages = stages;
        this.age = age;
        this.via = via;
    }

    /** A path entering m through stage st (a sensor's reader). */
    void enter(PlannedModule m, Stage st) {
        roots.add(solve(new Key(m, null, advance(0, m.module()), st, st.periodNs())));
    }

    /** A path starting where m's output port {@code only} sends. */
    void start(PlannedModule m, PlannedPort only) {
        roots.add(solve(new Key(m, only, advance(0, m.module()), null, stages.get(m).periodNs())));
    }

    /**
     * Whether a walk from a root can come back to a module it passed, through the same state or another
     * of that module: then the results below are not those of the paths.
     */
    boolean cyclic() {
        if (cyclic) {
            return true;
        }
        Reach reach = reach();
        Map<PlannedModule, Set<PlannedModule>> after = new HashMap<>();
        Map<PlannedModule, Integer> before = new HashMap<>();
        for (Key k : reach.order()) {
            before.putIfAbsent(k.m(), 0);
        }
        reach.callers().forEach((c, callers) -> {
            for (Key from : callers) {
                if (after.computeIfAbsent(from.m(), x -> new HashSet<>()).add(c.m())) {
                    before.merge(c.m(), 1, Integer::sum);
                }
            }
        });
        // modules with no module before them taken away one by one: what remains holds a cycle
        ArrayDeque<PlannedModule> free = new ArrayDeque<>();
        before.forEach((m, n) -> {
            if (n == 0) {
                free.add(m);
            }
        });
        int taken = 0;
        while (!free.isEmpty()) {
            PlannedModule m = free.pop();
            taken++;
            for (PlannedModule c : after.getOrDefault(m, Set.of())) {
                if (before.merge(c, -1, Integer::sum) == 0) {
                    free.add(c);
                }
            }
        }
        cyclic = taken < before.size();
        return cyclic;
    }

    /** The states reached from the roots in breadth-first order, the states each is stepped to from, and those a path can end at. */
    private record Reach(List<Key> order, Map<Key, List<Key>> callers, List<Key> finishing) {
    }

    private Reach reach() {
        Map<Key, List<Key>> callers = new HashMap<>();
        List<Key> order = new ArrayList<>();
        List<Key> finishing = new ArrayList<>();
        Set<Key> seen = new HashSet<>();
        for (Node r : roots) {
            if (seen.add(r.key)) {
                order.add(r.key);
            }
        }
        for (int i = 0; i < order.size(); i++) {
            Key k = order.get(i);
            boolean ends = k.stage() != null && search.drives(k.m()) && k.k() == via.size();
            for (PathSearch.Step step : search.steps(k.m(), k.only())) {
                ends |= step.arrives() && advance(k.k(), step.adds()) == via.size();
                Key c = child(k, step);
                if (c != null) {
                    callers.computeIfAbsent(c, x -> new ArrayList<>()).add(k);
                    if (seen.add(c)) {
                        order.add(c);
                    }
                }
            }
            if (ends) {
                finishing.add(k);
            }
        }
        return new Reach(order, callers, finishing);
    }

    /** The worst reaction time (or, {@code dataAge}, data age) over the paths with a bound, -1 when none. */
    long worst(boolean dataAge) {
        Node r = worstRoot(dataAge);
        return r == null ? -1 : Math.addExact(own(r.key), dataAge ? r.dataAge : r.reaction);
    }

    /** The root whose paths with a bound hold the worst reaction time (or data age), the first of equals; null when none. */
    private Node worstRoot(boolean dataAge) {
        Node worst = null;
        long w = -1;
        for (Node r : roots) {
            long v = dataAge ? r.dataAge : r.reaction;
            if (v >= 0 && Math.addExact(own(r.key), v) > w) {
                w = Math.addExact(own(r.key), v);
                worst = r;
            }
        }
        return worst;
    }

    /** The paths with a bound (saturating). */
    long bounded() {
        long c = 0;
        for (Node r : roots) {
            c = sum(c, r.count);
        }
        return c;
    }

    /**
     * A stage without a bound on a walk from a root to the target (the first such stage in breadth-first order), or
     * null when none: each state and step once. Where the modules form no cycle ({@link #cyclic()}) every walk is a
     * path, so a path passes that stage.
     */
    String mayPassUnbounded() {
        Reach reach = reach();
        Map<Key, List<Key>> callers = reach.callers();
        List<Key> order = reach.order();
        ArrayDeque<Key> finishing = new ArrayDeque<>(reach.finishing());
        Set<Key> finishes = new HashSet<>(finishing);
        while (!finishing.isEmpty()) {
            for (Key c : callers.getOrDefault(finishing.pop(), List.of())) {
                if (finishes.add(c)) {
                    finishing.add(c);
                }
            }
        }
        for (Key k : order) {
            if (!bounded(k) && finishes.contains(k)) {
                return k.stage().unbounded();
            }
        }
        return null;
    }

    /** The worst path with a bound for the requirement's kind, or null when none. */
    PathBound worst() {
        Node best = worstRoot(age);
        if (best == null) {
            return null;
        }
        List<Hop> hops = new ArrayList<>();
        List<EObject> passes = new ArrayList<>(List.of(best.key.m().module()));
        if (best.key.stage() != null) {
            hops.add(best.key.stage().hop());
        }
        Node n = best;
        long period = n.key.period();
        while (n.choice >= 0) {
            PathSearch.Step step = n.steps.get(n.choice / 2);
            passes.addAll(step.adds());
            Hop crossing = step.next() == null ? null : PathSearch.crossing(n.key.m(), step.next());
            if (crossing != null) {
                hops.add(crossing);
            }
            if (n.choice % 2 == 0) {
                period = n.key.period();
                break;
            }
            Node child = nodes.get(child(n.key, step));
            hops.add(childHop(step, child.key));
            passes.add(child.key.m().module());
            n = child;
            period = n.key.period();
        }
        long reaction = 0;
        for (Hop h : hops) {
            reaction = Math.addExact(reaction, h.totalNs());
        }
        return new PathBound(hops, reaction, Math.addExact(reaction, period), null, passes);
    }

    private static long own(Key k) {
        return k.stage() == null || k.stage().hop() == null ? 0 : k.stage().hop().totalNs();
    }

    private int advance(int k, EObject e) {
        return k < via.size() && via.get(k) == e ? k + 1 : k;
    }

    private int advance(int k, List<EObject> adds) {
        for (EObject e : adds) {
            k = advance(k, e);
        }
        return k;
    }

    /** The state a step leads to (its next module reaching the target), or null. */
    private Key child(Key from, PathSearch.Step step) {
        PlannedModule next = step.next();
        if (next == null || !search.reaches(next)) {
            return null;
        }
        int k = advance(from.k(), step.adds());
        if (step.inhibitor() != null) {
            return new Key(next, step.inhibitor().target(), k, null, 0);
        }
        Stage st = stages.get(next);
        return new Key(next, null, advance(k, next.module()), st, st.periodNs());
    }

    private static Hop childHop(PathSearch.Step step, Key child) {
        if (step.inhibitor() != null) {
            return PathSearch.inhibits(step.inhibitor(), step.next());
        }
        return child.stage().hop();
    }

    private static long sum(long a, long b) {
        long s = a + b;
        return s < 0 ? Long.MAX_VALUE : s;
    }

    /** Depth first over the states from root, with a stack of its own; each state solved once. */
    private Node solve(Key root) {
        Node first = node(root);
        if (first.state == 2) {
            return first;
        }
        if (!bounded(root)) {
            close(first);
            return first;
        }
        ArrayDeque<Node> stack = new ArrayDeque<>();
        open(first);
        stack.push(first);
        while (!stack.isEmpty()) {
            Node n = stack.peek();
            if (n.nextStep < n.steps.size()) {
                PathSearch.Step step = n.steps.get(n.nextStep);
                Key ck = child(n.key, step);
                if (ck != null && bounded(ck)) {
                    Node c = node(ck);
                    if (c.state == 0) {
                        open(c);
                        stack.push(c);
                        continue;
                    }
                    if (c.state == 1) {
                        cyclic = true;
                    }
                }
                n.nextStep++;
                continue;
            }
            stack.pop();
            close(n);
            if (!stack.isEmpty()) {
                stack.peek().nextStep++;
            }
        }
        return first;
    }

    /** Whether a state's own stage has a bound: the search for bounds goes only through those. */
    private static boolean bounded(Key k) {
        return k.stage() == null || k.stage().hop() != null;
    }

    private Node node(Key k) {
        return nodes.computeIfAbsent(k, Node::new);
    }

    private void open(Node n) {
        n.state = 1;
        n.steps = search.steps(n.key.m(), n.key.only());
    }

    /**
     * The node's suffixes with a bound, from its steps' (all solved, or on the walk: a cycle, counted as
     * none and said by {@link #cyclic()}); a step into a stage without a bound is noted as such.
     */
    private void close(Node n) {
        n.state = 2;
        Key k = n.key;
        if (!bounded(k)) {
            return;
        }
        if (k.stage() != null && search.drives(k.m()) && k.k() == via.size()) {
            offer(n, 0, k.period(), -1);
        }
        for (int i = 0; i < n.steps.size(); i++) {
            PathSearch.Step step = n.steps.get(i);
            Hop crossing = step.next() == null ? null : PathSearch.crossing(k.m(), step.next());
            long c = crossing == null ? 0 : crossing.totalNs();
            if (step.arrives() && advance(k.k(), step.adds()) == via.size()) {
                offer(n, c, Math.addExact(c, k.period()), 2 * i);
            }
            Key ck = child(k, step);
            if (ck == null) {
                continue;
            }
            if (!bounded(ck)) {
                continue;
            }
            Node child = nodes.get(ck);
            if (child == null || child.state != 2) {
                continue;
            }
            if (child.reaction >= 0) {
                long hop = Math.addExact(c, childHop(step, ck).totalNs());
                n.count = sum(n.count, child.count);
                long r = Math.addExact(hop, child.reaction);
                long a = Math.addExact(hop, child.dataAge);
                if (age ? a > n.dataAge : r > n.reaction) {
                    n.choice = 2 * i + 1;
                }
                n.reaction = Math.max(n.reaction, r);
                n.dataAge = Math.max(n.dataAge, a);
            }
        }
    }

    /** A suffix ending at n's module (or its step {@code choice}) adding reaction r and data age a. */
    private void offer(Node n, long r, long a, int choice) {
        n.count = sum(n.count, 1);
        if (age ? a > n.dataAge : r > n.reaction) {
            n.choice = choice;
        }
        n.reaction = Math.max(n.reaction, r);
        n.dataAge = Math.max(n.dataAge, a);
    }
}
