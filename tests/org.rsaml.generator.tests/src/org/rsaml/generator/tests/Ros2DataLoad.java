/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Flow;
import org.rsaml.analysis.plan.LinkPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.analysis.plan.Release;
import org.rsaml.generator.internal.cxx.CxxNames;
import org.rsaml.generator.internal.cxx.ReleaseBounds;
import org.rsaml.generator.internal.ros2.Ros2Names;

/**
 * What a model offers the data threads of each processor on ROS 2, derived from the model as the generated
 * nodes run it: whether a node's data thread (its input handlers, reactions, link triggers) can keep up with
 * the data it is sent. The timing analysis excludes an aperiodic reaction (its arrivals are not bounded by the
 * model) and says nothing of it; but where the data comes from timed releases, the rate is known: a timed
 * module sends after each release, a reacting module after each reaction, and a reaction runs on each arrival
 * at an entry port (or at a suppressor's target, from its trigger), at most once per its minimum interval
 * (sporadic, or a reactive cycle's bound: {@link Ros2Names#reactionIntervalNs}) and at most as often as its
 * modeled execution time lets it.
 *
 * <p>
 * A node is <em>saturated</em> when its reactions are offered a whole CPU or more: its data thread is always
 * ready, and takes only as many messages as it can react to. The data threads of a processor run at one of two
 * levels: priority 0 (the lowest real-time priority), or, for nodes whose reactions are aperiodic, the default
 * priority below every real-time thread ({@code rsaml_data_unbounded}). A level is <em>overloaded</em> when the
 * CPU its nodes' reactions are offered (each at most a whole CPU: one thread) is no less than what the levels
 * above it leave of the CPUs the processor may use (its core, or every CPU of this machine for a processor
 * without one, or whose core this machine does not have). Then its data threads cannot take every message: a
 * message waits behind reactions of other nodes, and the middleware keeps only the last few of a topic (its
 * QoS depth). A test expects an entry port to receive every message its publisher sends only where neither is
 * the case ({@link #takesEveryMessage}).
 */
final class Ros2DataLoad {

    /** One level of a processor's data threads: the CPU its reactions are offered, the CPU the levels above leave, and who offers what. */
    record Level(String processor, String priority, double demand, double left, Map<String, Double> reactions) {
        boolean overloaded() {
            return demand >= left;
        }

        @Override
        public String toString() {
            List<String> each = new ArrayList<>();
            reactions.forEach((m, d) -> each.add(m + " " + String.format(Locale.ROOT, "%.2f", d)));
            return String.format(Locale.ROOT, "processor %s at %s: its reactions are offered %.2f CPU, the threads above leave %.2f (%s)",
                    processor, priority, demand, left, String.join(", ", each));
        }
    }

    private final Ros2Names names;
    private final ReleaseBounds bounds;
    private final Map<PlannedModule, Double> offered = new HashMap<>();
    private final Set<PlannedModule> visiting = new HashSet<>();
    private final Map<String, Level> realtime = new LinkedHashMap<>();
    private final Map<String, Level> unbounded = new LinkedHashMap<>();

    private Ros2DataLoad(ExecutionPlan plan, int cpus) {
        this.names = new Ros2Names(plan, new CxxNames(plan, "load"));
        this.bounds = ReleaseBounds.of(plan);
        Map<String, Integer> usable = new LinkedHashMap<>();
        Map<String, Double> releases = new LinkedHashMap<>();
        Map<String, Map<String, Double>> rank0 = new LinkedHashMap<>();
        Map<String, Map<String, Double>> below = new LinkedHashMap<>();
        for (PlannedModule m : plan.modules()) {
            String processor = processor(m);
            releases.putIfAbsent(processor, 0.0);
            usable.put(processor, m.core() >= 0 && m.core() < cpus ? 1 : cpus);
            rank0.putIfAbsent(processor, new LinkedHashMap<>());
            below.putIfAbsent(processor, new LinkedHashMap<>());
            for (Release r : m.releases()) {
                releases.merge(processor, (double) r.costNs() / r.periodNs(), Double::sum);
            }
            if (m.reactive()) {
                (aperiodic(m) ? below : rank0).get(processor).put(m.qualifiedName(), Math.min(1.0, offeredReactions(m) * m.reaction().costNs() / 1e9));
            }
        }
        releases.forEach((p, u) -> {
            double left = Math.max(0.0, usable.get(p) - u);
            Level top = new Level(p, "priority 0", sum(rank0.get(p)), left, rank0.get(p));
            realtime.put(p, top);
            unbounded.put(p, new Level(p, "the default priority", sum(below.get(p)), Math.max(0.0, left - top.demand()), below.get(p)));
        });
    }

    private static double sum(Map<String, Double> demands) {
        return demands.values().stream().mapToDouble(Double::doubleValue).sum();
    }

    /** Whether the module's reactions are aperiodic, so that its node's data thread runs at the default priority. */
    boolean aperiodic(PlannedModule m) {
        return m.reactive() && bounds.aperiodic(m.reaction());
    }

    /** The processor a module runs on, by name ({@code default} when it has none). */
    static String processor(PlannedModule m) {
        return m.processor() == null ? "default" : m.processor().getName();
    }

    /** The level of the module's node's data thread on its processor. */
    Level level(PlannedModule m) {
        return (aperiodic(m) ? unbounded : realtime).get(processor(m));
    }

    /** On this machine's CPUs. */
    static Ros2DataLoad of(ExecutionPlan plan) {
        return of(plan, Runtime.getRuntime().availableProcessors());
    }

    /** On a machine with {@code cpus} CPUs. */
    static Ros2DataLoad of(ExecutionPlan plan, int cpus) {
        return new Ros2DataLoad(plan, cpus);
    }

    /** Whether a node's reactions are offered a whole CPU or more. */
    boolean saturated(PlannedModule m) {
        return m.reactive() && offeredReactions(m) * m.reaction().costNs() / 1e9 >= 1.0;
    }

    /** Whether the node can take every message sent to it: neither saturated nor on an overloaded processor. */
    boolean takesEveryMessage(PlannedModule m) {
        return !saturated(m) && !level(m).overloaded();
    }

    /** Why a node cannot take every message, or null. */
    String whyNot(PlannedModule m) {
        if (saturated(m)) {
            return String.format(Locale.ROOT, "%s is offered %.1f reactions a second of %s each", m.qualifiedName(), offeredReactions(m),
                    org.rsaml.model.support.RsamlTimes.milliseconds(m.reaction().costNs()));
        }
        return level(m).overloaded() ? level(m).toString() : null;
    }

    /**
     * How many reactions a second a reacting module is offered: one per message at its entry ports and per
     * message of a suppressor that delivers its data to one of them, at most one per its minimum interval.
     */
    double offeredReactions(PlannedModule m) {
        Double known = offered.get(m);
        if (known != null) {
            return known;
        }
        long interval = names.reactionIntervalNs(m);
        double cap = interval > 0 ? 1e9 / interval : Double.POSITIVE_INFINITY;
        if (!visiting.add(m)) {
            return interval > 0 ? cap : 0; // round a reactive cycle: at most its bound
        }
        double rate = 0;
        for (PlannedPort p : m.inputs()) {
            for (Flow f : p.incoming()) {
                rate += sent(f.source().module());
            }
            for (LinkPlan l : p.suppressors()) {
                // a boolean trigger asserts its link with true only, which no generated node sends
                if (l.deliversData() && !names.assertsOnlyWhenTrue(l.trigger())) {
                    rate += sent(l.trigger().module());
                }
            }
        }
        visiting.remove(m);
        double result = Math.min(rate, cap);
        offered.put(m, result);
        return result;
    }

    /** How many messages a second a module sends at each output port: after each release and each reaction it runs. */
    double sent(PlannedModule m) {
        double rate = 0;
        for (Release r : m.releases()) {
            rate += 1e9 / r.periodNs();
        }
        if (m.reactive()) {
            long cost = m.reaction().costNs();
            rate += cost > 0 ? Math.min(offeredReactions(m), 1e9 / cost) : offeredReactions(m);
        }
        return rate;
    }
}
