/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import org.rsaml.analysis.plan.Flow;
import org.rsaml.analysis.plan.LinkPlan;
import org.rsaml.analysis.plan.PlannedAction;
import org.rsaml.analysis.plan.PlannedFunction;
import org.rsaml.analysis.plan.PlannedLayer;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.analysis.plan.Reaction;
import org.rsaml.analysis.plan.Release;
import org.rsaml.analysis.plan.ReleaseKind;
import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Suppressor;

/**
 * Builds an {@link ExecutionPlan} from an architecture (the execution model is described there):
 * layers and modules, each function and action's releases, reactions, flows, links and ranks. It
 * takes time linear in the model (ranks: n log n).
 */
final class Planner {

    private final ExecutionPlan plan;

    /** Whether the plan holds the ports, flows, links and message types (see {@link ExecutionPlan#releasesOf}). */
    private final boolean connected;

    private Planner(Architecture architecture, boolean connected) {
        this.connected = connected;
        int ports = 0;
        for (Layer layer : connected ? architecture.getLayers() : List.<Layer>of()) {
            for (Module module : layer.getModules()) {
                ports += module.getPorts().size();
            }
        }
        this.plan = new ExecutionPlan(architecture, ports, connected);
    }

    static ExecutionPlan plan(Architecture architecture, boolean connected) throws UnplannableException {
        Planner planner = new Planner(architecture, connected);
        planner.build(architecture);
        return planner.plan;
    }

    private void build(Architecture architecture) throws UnplannableException {
        Map<Layer, PlannedLayer> byLayer = new IdentityHashMap<>();
        for (Layer layer : architecture.getLayers()) {
            PlannedLayer pl = new PlannedLayer(layer);
            plan.layers.add(pl);
            byLayer.putIfAbsent(layer, pl);
        }
        List<Layer> ordered = new ArrayList<>(architecture.getLayers());
        ordered.sort(Comparator.comparingInt(Layer::getLevel)); // stable: model order within a level
        for (Layer layer : ordered) {
            PlannedLayer pl = byLayer.get(layer);
            for (Module module : layer.getModules()) {
                PlannedModule pm = new PlannedModule(plan, pl, module);
                pl.modules.add(pm);
                plan.modules.add(pm);
            }
        }
        Map<Module, PlannedModule> byModule = new IdentityHashMap<>(plan.modules.size());
        plan.modules.forEach(m -> byModule.put(m.module, m));
        for (Processor p : architecture.getProcessors()) {
            for (Module module : p.getModules()) {
                PlannedModule m = byModule.get(module);
                if (m != null && m.processor == null) {
                    m.processor = p; // a second processor naming the module is RSA-25's finding
                }
            }
        }
        for (PlannedModule m : connected ? plan.modules : List.<PlannedModule>of()) {
            for (Port p : m.module.getPorts()) {
                PlannedPort pp = new PlannedPort(plan, m, p);
                m.ports.add(pp);
                (pp.entry ? m.inputs : m.outputs).add(pp);
                plan.ports.put(p, pp);
            }
        }
        for (PlannedModule m : plan.modules) {
            analyse(m);
        }
        for (Connection c : connected ? architecture.getConnections() : List.<Connection>of()) {
            addFlow(c);
        }
        for (PlannedModule m : plan.modules) {
            for (Inhibitor i : m.module.getInhibitors()) {
                if (connected) {
                    addLink(m, i, i.getTarget());
                } else {
                    checkLink(byModule, m, i, i.getTarget());
                }
            }
            for (Suppressor s : m.module.getSuppressors()) {
                if (connected) {
                    addLink(m, s, s.getTarget());
                } else {
                    checkLink(byModule, m, s, s.getTarget());
                }
            }
        }
        assignRanks();
    }

    /**
     * Without the ports: the one check {@link #addLink} makes that can refuse the plan, of the link's duration where
     * addLink reads it (both its ports planned), so that a plan without connections is refused where the whole one is.
     */
    private static void checkLink(Map<Module, PlannedModule> planned, PlannedModule owner, SubsumptionLink link, Port targetPort)
            throws UnplannableException {
        if (plannedPort(planned, targetPort) && plannedPort(planned, link.getTrigger())) {
            duration(link, label(owner, link));
        }
    }

    /** A link's label, {@code layer/module.link}. */
    private static String label(PlannedModule owner, SubsumptionLink link) {
        return owner.qualifiedName + "." + org.rsaml.model.support.RsamlLabels.name(link);
    }

    /** A link's duration in nanoseconds, as the plan reads it (the one way a link refuses a plan). */
    private static long duration(SubsumptionLink link, String label) throws UnplannableException {
        return PlanTimes.checked(link.getDuration(), link, "duration", label, false);
    }

    /** Whether the whole plan holds the port: a port of a planned module (its container). */
    private static boolean plannedPort(Map<Module, PlannedModule> planned, Port port) {
        return port != null && port.getModule() != null && planned.containsKey(port.getModule());
    }

    private void analyse(PlannedModule m) throws UnplannableException {
        Module module = m.module;
        m.periodic = timed(module);
        long modulePeriod = PlanTimes.checked(module.getPeriod(), module, "period", m.qualifiedName, true);
        long moduleDelay = PlanTimes.checked(module.getDelay(), module, "delay", m.qualifiedName, false);
        long moduleCost = PlanTimes.checked(module.getExecDuration(), module, "execution duration", m.qualifiedName, false);
        boolean anyTimed = false;
        for (PlannedFunction f : m.functions) {
            analyse(f);
            SchedulingPolicy policy = f.function.getSchedPolicy();
            if (f.timed) {
                anyTimed = true;
                add(m, new Release(m, ReleaseKind.FUNCTION, f, null, f.periodNs, 0, f.deadlineNs, f.costNs,
                        priorityKey(policy, f.periodNs, f.deadlineNs), policy));
            } else {
                m.stepFunctions.add(f);
            }
            for (PlannedAction a : f.actions) {
                if (a.standalone) {
                    anyTimed = true;
                    add(m, new Release(m, ReleaseKind.ACTION, f, a, a.periodNs, a.startNs, a.deadlineNs, a.costNs,
                            priorityKey(policy, a.periodNs, a.deadlineNs), policy));
                }
            }
        }
        if (m.periodic && (!m.stepFunctions.isEmpty() || !anyTimed)) {
            add(m, new Release(m, ReleaseKind.MODULE, null, null, modulePeriod, 0, moduleDelay > 0 ? moduleDelay : modulePeriod,
                    moduleCost, 0, SchedulingPolicy.FIFO));
        }
        m.reactive = !m.periodic && (!m.stepFunctions.isEmpty() || m.functions.isEmpty());
        if (module.getExecType() == ExecutionType.SPORADIC && module.getPeriod() > 0) {
            m.minIntervalNs = modulePeriod;
        }
        if (m.reactive) {
            m.reaction = new Reaction(m);
            plan.reactions.add(m.reaction);
        }
        for (PlannedPort p : m.ports) {
            if (p.messageType != null) {
                plan.messageTypes.add(p.messageType);
            }
        }
    }

    private static void analyse(PlannedFunction f) throws UnplannableException {
        Function function = f.function;
        long period = PlanTimes.checked(function.getPeriod(), function, "period", f::label, true);
        long delay = PlanTimes.checked(function.getDelay(), function, "delay", f::label, false);
        f.costNs = PlanTimes.checked(function.getExecDuration(), function, "execution duration", f::label, false);
        f.timed = timed(function);
        f.periodNs = f.timed ? period : 0;
        f.deadlineNs = delay > 0 ? delay : period;
        if (function.getExecType() == ExecutionType.SPORADIC && function.getPeriod() > 0) {
            f.minIntervalNs = period;
        }
        for (PlannedAction a : f.actions) {
            analyse(a);
        }
    }

    private static void analyse(PlannedAction a) throws UnplannableException {
        Action action = a.action;
        PlannedFunction f = a.function;
        long period = PlanTimes.checked(action.getPeriod(), action, "period", a::label, true);
        long delay = PlanTimes.checked(action.getDelay(), action, "delay", a::label, false);
        a.costNs = PlanTimes.checked(action.getExecDuration(), action, "execution duration", a::label, false);
        a.startNs = PlanTimes.checked(action.getStartDate(), action, "start date", a::label, false);
        boolean ownTimer = timed(action);
        a.periodNs = ownTimer ? period : 0;
        a.deadlineNs = delay > 0 ? delay : period;
        a.standalone = ownTimer && !(f.timed && a.periodNs == f.periodNs);
        a.offsetNs = f.timed && !a.standalone && f.periodNs > 0 ? a.startNs % f.periodNs : 0;
    }

    private static boolean timed(RealTimeElement e) {
        return e.getExecType() == ExecutionType.PERIODIC && e.getPeriod() > 0;
    }

    private void add(PlannedModule m, Release r) {
        m.releases.add(r);
        plan.releases.add(r);
    }

    private static long priorityKey(SchedulingPolicy policy, long periodNs, long deadlineNs) {
        if (policy == SchedulingPolicy.RM) {
            return periodNs;
        }
        if (policy == SchedulingPolicy.DM) {
            return deadlineNs;
        }
        return 0;
    }

    private void addFlow(Connection c) {
        PlannedPort source = plan.port(c.getSource());
        PlannedPort target = plan.port(c.getTarget());
        if (source == null || target == null) {
            plan.warnings.add(PlanWarnings.connectionWithoutPort(c));
            return;
        }
        if (!source.sameData(target)) {
            plan.warnings.add(PlanWarnings.connectionOfDifferentData(source, target));
            return;
        }
        Flow f = new Flow(c, source, target);
        plan.flows.add(f);
        source.outgoing.add(f);
        target.incoming.add(f);
    }

    private void addLink(PlannedModule owner, SubsumptionLink link, Port targetPort) throws UnplannableException {
        boolean inhibitor = link instanceof Inhibitor;
        String kind = inhibitor ? "inhibitor" : "suppressor";
        String label = label(owner, link);
        PlannedPort trigger = plan.port(link.getTrigger());
        PlannedPort target = plan.port(targetPort);
        if (target == null) {
            plan.warnings.add(PlanWarnings.linkWithoutTarget(kind, label));
            return;
        }
        if (trigger == null) {
            plan.warnings.add(PlanWarnings.linkWithoutTrigger(kind, label));
            return;
        }
        LinkPlan lp = new LinkPlan(link, inhibitor, owner, label, trigger, target, duration(link, label));
        if (!inhibitor && !lp.deliversData) {
            plan.warnings.add(PlanWarnings.suppressorWithoutData(label, trigger, target));
        }
        plan.links.add(lp);
        trigger.triggers.add(lp);
        (inhibitor ? target.inhibitors : target.suppressors).add(lp);
    }

    /** Distinct priority keys, longest first, become ranks 2, 3, ... (the shortest ranks highest); no key (not RM/DM) is rank 1. */
    private void assignRanks() {
        TreeSet<Long> keys = new TreeSet<>(Comparator.reverseOrder());
        for (Release r : plan.releases) {
            if (r.priorityKey > 0) {
                keys.add(r.priorityKey);
            }
        }
        Map<Long, Integer> rank = new HashMap<>();
        int next = 2;
        for (Long key : keys) {
            rank.put(key, next++);
        }
        for (Release r : plan.releases) {
            r.rank = r.priorityKey > 0 ? rank.get(r.priorityKey) : 1;
        }
    }
}
