/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.EntryPort;
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
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlTimes;

/**
 * How an architecture executes, independent of any target language: what is released when, what
 * reacts to what, and what flows where. Every code generator renders this plan; a timing analysis
 * can take its task set from {@link #releases()} and {@link #reactions()}. All times are integral
 * nanoseconds; everything is in model order, so the same model gives the same plan.
 *
 * <p>The execution model:
 * <ul>
 * <li>a periodic function is a {@link Release} every period; it runs its actions in order, each at
 * its start date within the period ({@link PlannedAction#offsetNs()});</li>
 * <li>a periodic action whose period differs from its function's (or whose function is not
 * periodic) is a release of its own, first at its start date;</li>
 * <li>a periodic module with functions that are not periodic (or with no timed activity at all) is
 * released every module period and runs those functions ({@link PlannedModule#stepFunctions()});</li>
 * <li>a module that is not periodic reacts to arriving data ({@link Reaction}): each arrival runs
 * its step functions, a sporadic module at most once per period, a sporadic function at most once
 * per its period;</li>
 * <li>after each activation the module sends its outputs along its {@link Flow}s; an
 * {@link LinkPlan inhibitor} blocks an output while active, a suppressor replaces an input;</li>
 * <li>at start every module runs once, lowest layer first, and sends its initial outputs.</li>
 * </ul>
 *
 * <p>Priorities follow the scheduling policy of the released element's function: rate monotonic
 * by period, deadline monotonic by deadline (shorter is higher); every other policy runs
 * first-in first-out at the base priority ({@link Release#rank()} 1).
 *
 * <p>A model is planned only when every time it uses can be represented: finite, not negative, a
 * period of at least 1 ns once converted, and at most {@link #MAX_TIME_NS}. Otherwise
 * {@link #of(Architecture)} throws an {@link UnplannableException} naming the element.
 */
public final class ExecutionPlan {

    /**
     * The longest time a plan holds, 2^60 ns (about 36.5 years): generated code counts time in
     * signed 64-bit nanoseconds from the start of the run and must add a period and an offset to
     * it without overflow.
     */
    public static final long MAX_TIME_NS = RsamlTimes.MAX_NANOSECONDS.longValueExact();

    private final Architecture architecture;
    private final String name;
    private final List<PlannedLayer> layers = new ArrayList<>();
    private final List<PlannedModule> modules = new ArrayList<>();
    private final List<Flow> flows = new ArrayList<>();
    private final List<LinkPlan> links = new ArrayList<>();
    private final List<Release> releases = new ArrayList<>();
    private final List<Reaction> reactions = new ArrayList<>();
    private final List<String> messageTypes = new ArrayList<>();
    private final List<String> warnings = new ArrayList<>();
    private final Map<Port, PlannedPort> ports = new IdentityHashMap<>();

    private ExecutionPlan(Architecture architecture) throws UnplannableException {
        this.architecture = architecture;
        this.name = RsamlLabels.name(architecture);
        List<Layer> ordered = new ArrayList<>(architecture.getLayers());
        ordered.sort(Comparator.comparingInt(Layer::getLevel)); // stable: model order within a level
        for (Layer layer : architecture.getLayers()) {
            layers.add(new PlannedLayer(layer));
        }
        for (Layer layer : ordered) {
            PlannedLayer pl = layerOf(layer);
            for (Module module : layer.getModules()) {
                PlannedModule pm = new PlannedModule(this, pl, module);
                pl.modules.add(pm);
                modules.add(pm);
            }
        }
        Map<Module, PlannedModule> byModule = new IdentityHashMap<>();
        modules.forEach(m -> byModule.put(m.module, m));
        for (Processor p : architecture.getProcessors()) {
            for (Module module : p.getModules()) {
                PlannedModule m = byModule.get(module);
                if (m != null && m.processor == null) {
                    m.processor = p; // a second processor naming the module is RSA-25's finding
                }
            }
        }
        for (PlannedModule m : modules) {
            for (Port p : m.module.getPorts()) {
                PlannedPort pp = new PlannedPort(this, m, p);
                m.ports.add(pp);
                (pp.entry ? m.inputs : m.outputs).add(pp);
                ports.put(p, pp);
            }
        }
        for (PlannedModule m : modules) {
            m.analyse();
        }
        for (Connection c : architecture.getConnections()) {
            addFlow(c);
        }
        for (PlannedModule m : modules) {
            for (Inhibitor i : m.module.getInhibitors()) {
                addLink(m, i, i.getTarget());
            }
            for (Suppressor s : m.module.getSuppressors()) {
                addLink(m, s, s.getTarget());
            }
        }
        assignRanks();
    }

    /**
     * The plan of an architecture.
     *
     * @throws UnplannableException a time of the model cannot be represented (not finite, negative,
     *                              a period below 1 ns, or longer than {@link #MAX_TIME_NS})
     */
    public static ExecutionPlan of(Architecture architecture) throws UnplannableException {
        return new ExecutionPlan(architecture);
    }

    public Architecture architecture() {
        return architecture;
    }

    /** The architecture's name as the model spells it. */
    public String name() {
        return name;
    }

    public String description() {
        return architecture.getDescription();
    }

    /** Layers in model order. */
    public List<PlannedLayer> layers() {
        return Collections.unmodifiableList(layers);
    }

    /** Modules lowest layer first, then in model order: the order of the start steps. */
    public List<PlannedModule> modules() {
        return Collections.unmodifiableList(modules);
    }

    /** Every timed release of every module. */
    public List<Release> releases() {
        return Collections.unmodifiableList(releases);
    }

    /** Every module that reacts to arriving data. */
    public List<Reaction> reactions() {
        return Collections.unmodifiableList(reactions);
    }

    /** The connections that carry data (those that cannot are left out, with a warning). */
    public List<Flow> flows() {
        return Collections.unmodifiableList(flows);
    }

    /** Inhibitors and suppressors that can act (the others are left out, with a warning). */
    public List<LinkPlan> links() {
        return Collections.unmodifiableList(links);
    }

    /** Structured message type names as written on the ports, first use first. */
    public List<String> messageTypes() {
        return Collections.unmodifiableList(messageTypes);
    }

    /** Model elements that cannot execute as modeled. */
    public List<String> warnings() {
        return Collections.unmodifiableList(warnings);
    }

    /** The plan of a port, or null when the port is not in a module of a layer. */
    public PlannedPort port(Port port) {
        return port == null ? null : ports.get(port);
    }

    private PlannedLayer layerOf(Layer layer) {
        return layers.stream().filter(l -> l.layer == layer).findFirst().orElseThrow();
    }

    private void addFlow(Connection c) {
        PlannedPort source = port(c.getSource());
        PlannedPort target = port(c.getTarget());
        if (source == null || target == null) {
            warnings.add("connection " + RsamlLabels.name(c.getSource()) + " -> " + RsamlLabels.name(c.getTarget())
                    + " is not generated: it lacks a source or a target port in a layer");
            return;
        }
        if (!source.sameData(target)) {
            warnings.add("connection " + source.qualifiedName + " -> " + target.qualifiedName
                    + " is not generated: the ports carry different data (" + source.dataLabel() + " vs " + target.dataLabel() + ")");
            return;
        }
        Flow f = new Flow(c, source, target);
        flows.add(f);
        source.outgoing.add(f);
        target.incoming.add(f);
    }

    private void addLink(PlannedModule owner, SubsumptionLink link, Port targetPort) throws UnplannableException {
        boolean inhibitor = link instanceof Inhibitor;
        String kind = inhibitor ? "inhibitor" : "suppressor";
        String label = owner.qualifiedName + "." + RsamlLabels.name(link);
        PlannedPort trigger = port(link.getTrigger());
        PlannedPort target = port(targetPort);
        if (target == null) {
            warnings.add(kind + " " + label + " is not generated: it has no target port");
            return;
        }
        if (trigger == null) {
            warnings.add(kind + " " + label + " is not generated: it has no trigger port, so nothing can activate it");
            return;
        }
        LinkPlan lp = new LinkPlan(link, inhibitor, owner, label, trigger, target,
                time(link.getDuration(), link, "duration", label, false));
        if (!inhibitor && !lp.deliversData) {
            warnings.add("suppressor " + label + " blocks " + target.qualifiedName + " but cannot replace its data: its trigger "
                    + trigger.qualifiedName + " carries " + trigger.dataLabel() + ", the target " + target.dataLabel());
        }
        links.add(lp);
        trigger.triggers.add(lp);
        (inhibitor ? target.inhibitors : target.suppressors).add(lp);
    }

    private void assignRanks() {
        TreeSet<Long> keys = new TreeSet<>(Comparator.reverseOrder());
        for (Release r : releases) {
            if (r.priorityKey > 0) {
                keys.add(r.priorityKey);
            }
        }
        List<Long> ordered = new ArrayList<>(keys);
        for (Release r : releases) {
            r.rank = r.priorityKey > 0 ? ordered.indexOf(r.priorityKey) + 2 : 1;
        }
    }

    private void addMessageType(String key) {
        if (!messageTypes.contains(key)) {
            messageTypes.add(key);
        }
    }

    /**
     * Modules that react to data (not timed) and to each other in a cycle, each cycle in module
     * order. Where data carries no wave (see {@link Reaction}), a message would go round for ever.
     */
    public List<List<PlannedModule>> reactiveCycles() {
        Map<PlannedModule, List<PlannedModule>> edges = new LinkedHashMap<>();
        for (Flow f : flows) {
            if (f.source.module.reactive && f.target.module.reactive) {
                edges.computeIfAbsent(f.source.module, k -> new ArrayList<>()).add(f.target.module);
            }
        }
        List<List<PlannedModule>> cycles = new ArrayList<>();
        new Object() {
            int index;
            final Map<PlannedModule, Integer> idx = new HashMap<>();
            final Map<PlannedModule, Integer> low = new HashMap<>();
            final Deque<PlannedModule> stack = new ArrayDeque<>();

            void run() {
                for (PlannedModule m : modules) {
                    if (!idx.containsKey(m)) {
                        visit(m);
                    }
                }
            }

            void visit(PlannedModule v) {
                idx.put(v, index);
                low.put(v, index++);
                stack.push(v);
                for (PlannedModule w : edges.getOrDefault(v, List.of())) {
                    if (!idx.containsKey(w)) {
                        visit(w);
                        low.put(v, Math.min(low.get(v), low.get(w)));
                    } else if (stack.contains(w)) {
                        low.put(v, Math.min(low.get(v), idx.get(w)));
                    }
                }
                if (low.get(v).equals(idx.get(v))) {
                    List<PlannedModule> scc = new ArrayList<>();
                    PlannedModule w;
                    do {
                        w = stack.pop();
                        scc.add(0, w);
                    } while (w != v);
                    if (scc.size() > 1 || edges.getOrDefault(v, List.of()).contains(v)) {
                        scc.sort(Comparator.comparingInt(modules::indexOf));
                        cycles.add(scc);
                    }
                }
            }
        }.run();
        return cycles;
    }

    /** A time attribute of an element in nanoseconds, refused when the generated code cannot represent it. */
    static long time(double value, TimeScaled owner, String attribute, String label, boolean period) throws UnplannableException {
        TimeUnit unit = owner.getTimeUnit() == null ? TimeUnit.MS : owner.getTimeUnit();
        String what = attribute + " " + format(value) + " " + unit.getLiteral() + " of " + label;
        if (!Double.isFinite(value)) {
            throw new UnplannableException((EObject) owner, what + " is not a finite number; give a number of " + unit.getLiteral());
        }
        if (value < 0) {
            throw new UnplannableException((EObject) owner, what + " is negative; give 0 or more");
        }
        // The same limits as validation (RSA-20), so that a model without errors is always planned.
        if (!RsamlTimes.representable(value, owner)) {
            throw new UnplannableException((EObject) owner, what + " is longer than generated code can count (at most 2^60 ns, "
                    + "about 36 years); give a shorter time");
        }
        long rounded = Math.round(value * unit.getValue());
        if (period && !RsamlTimes.representablePeriod(value, owner)) {
            throw new UnplannableException((EObject) owner, what + " is shorter than 1 ns, the resolution of generated code; "
                    + "give a longer period");
        }
        return rounded;
    }

    private static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    static boolean timed(RealTimeElement e) {
        return e.getExecType() == ExecutionType.PERIODIC && e.getPeriod() > 0;
    }

    /** A layer and its modules. */
    public static final class PlannedLayer {
        final Layer layer;
        final String name;
        final List<PlannedModule> modules = new ArrayList<>();

        PlannedLayer(Layer layer) {
            this.layer = layer;
            this.name = RsamlLabels.name(layer);
        }

        public Layer layer() {
            return layer;
        }

        public String name() {
            return name;
        }

        /** Its modules in model order. */
        public List<PlannedModule> modules() {
            return Collections.unmodifiableList(modules);
        }
    }

    /** How a module is activated: its timed releases, its reaction to data, its functions and ports. */
    public static final class PlannedModule {
        final ExecutionPlan plan;
        final PlannedLayer layer;
        final Module module;
        final String name;
        final String qualifiedName;
        final List<PlannedFunction> functions = new ArrayList<>();
        final List<PlannedPort> ports = new ArrayList<>();
        final List<PlannedPort> inputs = new ArrayList<>();
        final List<PlannedPort> outputs = new ArrayList<>();
        final List<Release> releases = new ArrayList<>();
        final List<PlannedFunction> stepFunctions = new ArrayList<>();
        boolean periodic;
        boolean reactive;
        long minIntervalNs;
        Reaction reaction;
        Processor processor;

        PlannedModule(ExecutionPlan plan, PlannedLayer layer, Module module) {
            this.plan = plan;
            this.layer = layer;
            this.module = module;
            this.name = RsamlLabels.name(module);
            this.qualifiedName = layer.name + "/" + name;
            for (Function f : module.getFunctions()) {
                PlannedFunction pf = new PlannedFunction(this, f);
                functions.add(pf);
                for (Action a : f.getActions()) {
                    pf.actions.add(new PlannedAction(pf, a));
                }
            }
        }

        void analyse() throws UnplannableException {
            periodic = timed(module);
            long modulePeriod = time(module.getPeriod(), module, "period", qualifiedName, true);
            long moduleDelay = time(module.getDelay(), module, "delay", qualifiedName, false);
            long moduleCost = time(module.getExecDuration(), module, "execution duration", qualifiedName, false);
            boolean anyTimed = false;
            for (PlannedFunction f : functions) {
                f.analyse();
                if (f.timed) {
                    anyTimed = true;
                    add(new Release(this, ReleaseKind.FUNCTION, f, null, f.periodNs, 0, f.deadlineNs, f.costNs,
                            priorityKey(f.function.getSchedPolicy(), f.periodNs, f.deadlineNs), f.function.getSchedPolicy()));
                } else {
                    stepFunctions.add(f);
                }
                for (PlannedAction a : f.actions) {
                    if (a.standalone) {
                        anyTimed = true;
                        add(new Release(this, ReleaseKind.ACTION, f, a, a.periodNs, a.startNs, a.deadlineNs, a.costNs,
                                priorityKey(f.function.getSchedPolicy(), a.periodNs, a.deadlineNs), f.function.getSchedPolicy()));
                    }
                }
            }
            if (periodic && (!stepFunctions.isEmpty() || !anyTimed)) {
                add(new Release(this, ReleaseKind.MODULE, null, null, modulePeriod, 0, moduleDelay > 0 ? moduleDelay : modulePeriod,
                        moduleCost, 0, SchedulingPolicy.FIFO));
            }
            reactive = !periodic && (!stepFunctions.isEmpty() || functions.isEmpty());
            if (module.getExecType() == ExecutionType.SPORADIC && module.getPeriod() > 0) {
                minIntervalNs = modulePeriod;
            }
            if (reactive) {
                reaction = new Reaction(this);
                plan.reactions.add(reaction);
            }
            for (PlannedPort p : ports) {
                if (p.messageType != null) {
                    plan.addMessageType(p.messageType);
                }
            }
        }

        private void add(Release r) {
            releases.add(r);
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

        public ExecutionPlan plan() {
            return plan;
        }

        public PlannedLayer layer() {
            return layer;
        }

        public Module module() {
            return module;
        }

        public String name() {
            return name;
        }

        /** {@code layer/module}, the model's names, as traces and messages show them. */
        public String qualifiedName() {
            return qualifiedName;
        }

        public String description() {
            return module.getDescription();
        }

        public List<PlannedFunction> functions() {
            return Collections.unmodifiableList(functions);
        }

        public List<PlannedPort> ports() {
            return Collections.unmodifiableList(ports);
        }

        public List<PlannedPort> inputs() {
            return Collections.unmodifiableList(inputs);
        }

        public List<PlannedPort> outputs() {
            return Collections.unmodifiableList(outputs);
        }

        /** Its timed releases. */
        public List<Release> releases() {
            return Collections.unmodifiableList(releases);
        }

        /** Functions run when data arrives or when the module itself is released. */
        public List<PlannedFunction> stepFunctions() {
            return Collections.unmodifiableList(stepFunctions);
        }

        /** Whether the module has a period of its own. */
        public boolean periodic() {
            return periodic;
        }

        /** The processor the module is allocated to, or null: then it runs on the default processor. */
        public Processor processor() {
            return processor;
        }

        /** The CPU core the module's threads are pinned to, or -1 to leave the choice to the operating system. */
        public int core() {
            return processor == null ? -1 : processor.getCore();
        }

        /** Whether the module reacts to arriving data. */
        public boolean reactive() {
            return reactive;
        }

        /** Its reaction to data, or null when it does not react. */
        public Reaction reaction() {
            return reaction;
        }

        /** For a sporadic module, the minimum time between two reactions (0: none). */
        public long minIntervalNs() {
            return minIntervalNs;
        }

        public List<PlannedAction> actions() {
            List<PlannedAction> all = new ArrayList<>();
            functions.forEach(f -> all.addAll(f.actions));
            return all;
        }

        /** The module's timing as the model states it, for documentation. */
        public String timing() {
            return RsamlLabels.timing(module);
        }
    }

    /** A function of a module: released on its own when periodic, otherwise run by its module. */
    public static final class PlannedFunction {
        final PlannedModule module;
        final Function function;
        final String name;
        final List<PlannedAction> actions = new ArrayList<>();
        boolean timed;
        long periodNs;
        long deadlineNs;
        long costNs;
        long minIntervalNs;

        PlannedFunction(PlannedModule module, Function function) {
            this.module = module;
            this.function = function;
            this.name = RsamlLabels.name(function);
        }

        void analyse() throws UnplannableException {
            long period = time(function.getPeriod(), function, "period", label(), true);
            long delay = time(function.getDelay(), function, "delay", label(), false);
            costNs = time(function.getExecDuration(), function, "execution duration", label(), false);
            timed = ExecutionPlan.timed(function);
            periodNs = timed ? period : 0;
            deadlineNs = delay > 0 ? delay : period;
            if (function.getExecType() == ExecutionType.SPORADIC && function.getPeriod() > 0) {
                minIntervalNs = period;
            }
            for (PlannedAction a : actions) {
                a.analyse();
            }
        }

        public PlannedModule module() {
            return module;
        }

        public Function function() {
            return function;
        }

        public String name() {
            return name;
        }

        public String description() {
            return function.getDescription();
        }

        public List<PlannedAction> actions() {
            return Collections.unmodifiableList(actions);
        }

        /** Whether the function is released every {@link #periodNs()}. */
        public boolean timed() {
            return timed;
        }

        public long periodNs() {
            return periodNs;
        }

        /** For a sporadic function run by reactions, the minimum time between two runs (0: none). */
        public long minIntervalNs() {
            return minIntervalNs;
        }

        /** The actions this function runs itself, in order (the others are released on their own). */
        public List<PlannedAction> inlineActions() {
            return actions.stream().filter(a -> !a.standalone).toList();
        }

        /** {@code layer/module.function}. */
        public String label() {
            return module.qualifiedName + "." + name;
        }

        public String timing() {
            return RsamlLabels.timing(function);
        }
    }

    /** An action of a function: run by it in order, or released on its own. */
    public static final class PlannedAction {
        final PlannedFunction function;
        final Action action;
        final String name;
        boolean standalone;
        long periodNs;
        long startNs;
        long offsetNs;
        long deadlineNs;
        long costNs;

        PlannedAction(PlannedFunction function, Action action) {
            this.function = function;
            this.action = action;
            this.name = RsamlLabels.name(action);
        }

        void analyse() throws UnplannableException {
            long period = time(action.getPeriod(), action, "period", label(), true);
            long delay = time(action.getDelay(), action, "delay", label(), false);
            costNs = time(action.getExecDuration(), action, "execution duration", label(), false);
            startNs = time(action.getStartDate(), action, "start date", label(), false);
            boolean ownTimer = timed(action);
            periodNs = ownTimer ? period : 0;
            deadlineNs = delay > 0 ? delay : period;
            standalone = ownTimer && !(function.timed && periodNs == function.periodNs);
            offsetNs = function.timed && !standalone && function.periodNs > 0 ? startNs % function.periodNs : 0;
        }

        public PlannedFunction function() {
            return function;
        }

        public Action action() {
            return action;
        }

        public String name() {
            return name;
        }

        public String description() {
            return action.getDescription();
        }

        /** Whether it is released on its own rather than run by its function. */
        public boolean standalone() {
            return standalone;
        }

        /** Delay after its function's release before it runs (actions of timed functions only). */
        public long offsetNs() {
            return offsetNs;
        }

        /** {@code layer/module.function.action}. */
        public String label() {
            return function.label() + "." + name;
        }

        public String timing() {
            return RsamlLabels.timing(action);
        }
    }

    /** The kind of data a port carries. */
    public enum DataKind {
        NUMERIC, ALPHANUMERIC, BOOLEAN, STRUCTURED
    }

    /** An entry or output port and the flows and links that touch it. */
    public static final class PlannedPort {
        final PlannedModule module;
        final Port port;
        final boolean entry;
        final String name;
        final String qualifiedName;
        final DataKind kind;
        final String messageType;
        final List<Flow> outgoing = new ArrayList<>();
        final List<Flow> incoming = new ArrayList<>();
        final List<LinkPlan> triggers = new ArrayList<>();
        final List<LinkPlan> inhibitors = new ArrayList<>();
        final List<LinkPlan> suppressors = new ArrayList<>();

        PlannedPort(ExecutionPlan plan, PlannedModule module, Port port) {
            this.module = module;
            this.port = port;
            this.entry = port instanceof EntryPort;
            this.name = RsamlLabels.name(port);
            this.qualifiedName = module.qualifiedName + "." + name;
            DataType type = port.getDataType() == null ? DataType.NUMERIC : port.getDataType();
            this.kind = switch (type) {
                case ALPHANUMERIC -> DataKind.ALPHANUMERIC;
                case BOOLEAN -> DataKind.BOOLEAN;
                case STRUCTURED -> DataKind.STRUCTURED;
                default -> DataKind.NUMERIC;
            };
            // Read as the rules read it (RSA-02, RSA-18): trimmed, and blank is missing.
            String written = port.normalizedMessageType();
            this.messageType = kind == DataKind.STRUCTURED ? (written == null ? "StructuredData" : written) : null;
        }

        boolean sameData(PlannedPort other) {
            return kind == other.kind && java.util.Objects.equals(messageType, other.messageType);
        }

        public PlannedModule module() {
            return module;
        }

        public Port port() {
            return port;
        }

        /** Whether it is an entry port (else an output port). */
        public boolean entry() {
            return entry;
        }

        public String name() {
            return name;
        }

        /** {@code layer/module.port}. */
        public String qualifiedName() {
            return qualifiedName;
        }

        public String description() {
            return port.getDescription();
        }

        public DataKind kind() {
            return kind;
        }

        /** The structured message type's name as written on the port (trimmed), or null. */
        public String messageType() {
            return messageType;
        }

        public List<Flow> outgoing() {
            return Collections.unmodifiableList(outgoing);
        }

        public List<Flow> incoming() {
            return Collections.unmodifiableList(incoming);
        }

        /** Links this port's messages trigger. */
        public List<LinkPlan> triggers() {
            return Collections.unmodifiableList(triggers);
        }

        /** Inhibitors that block this (output) port. */
        public List<LinkPlan> inhibitors() {
            return Collections.unmodifiableList(inhibitors);
        }

        /** Suppressors that replace what this (entry) port receives. */
        public List<LinkPlan> suppressors() {
            return Collections.unmodifiableList(suppressors);
        }

        /** {@code numeric data}, {@code structured data 'Pose'}, ... for messages. */
        public String dataLabel() {
            return kind == DataKind.STRUCTURED ? "structured data '" + messageType + "'"
                    : kind.name().toLowerCase(java.util.Locale.ROOT) + " data";
        }
    }

    /** Data flowing along a connection from an output port to an entry port. */
    public static final class Flow {
        final Connection connection;
        final PlannedPort source;
        final PlannedPort target;

        Flow(Connection connection, PlannedPort source, PlannedPort target) {
            this.connection = connection;
            this.source = source;
            this.target = target;
        }

        public Connection connection() {
            return connection;
        }

        public PlannedPort source() {
            return source;
        }

        public PlannedPort target() {
            return target;
        }
    }

    /** An inhibitor or a suppressor: active for its duration after each message on its trigger. */
    public static final class LinkPlan {
        final SubsumptionLink link;
        final boolean inhibitor;
        final PlannedModule owner;
        final String name;
        final String qualifiedName;
        final PlannedPort trigger;
        final PlannedPort target;
        final long durationNs;
        final boolean deliversData;

        LinkPlan(SubsumptionLink link, boolean inhibitor, PlannedModule owner, String qualifiedName, PlannedPort trigger,
                PlannedPort target, long durationNs) {
            this.link = link;
            this.inhibitor = inhibitor;
            this.owner = owner;
            this.name = RsamlLabels.name(link);
            this.qualifiedName = qualifiedName;
            this.trigger = trigger;
            this.target = target;
            this.durationNs = durationNs;
            this.deliversData = !inhibitor && trigger.sameData(target);
        }

        public SubsumptionLink link() {
            return link;
        }

        public boolean inhibitor() {
            return inhibitor;
        }

        public PlannedModule owner() {
            return owner;
        }

        public String name() {
            return name;
        }

        /** {@code layer/module.link}. */
        public String qualifiedName() {
            return qualifiedName;
        }

        public PlannedPort trigger() {
            return trigger;
        }

        public PlannedPort target() {
            return target;
        }

        public long durationNs() {
            return durationNs;
        }

        /** For a suppressor, whether the trigger's messages replace the target's input (same data). */
        public boolean deliversData() {
            return deliversData;
        }

        public String description() {
            return link.getDescription();
        }
    }

    /** What a release runs. */
    public enum ReleaseKind {
        /** A periodic function and its inline actions. */
        FUNCTION,
        /** A periodic action released on its own. */
        ACTION,
        /** A periodic module's step functions. */
        MODULE
    }

    /**
     * A timed release: a job every {@link #periodNs()} from the start of the run plus
     * {@link #offsetNs()}, due within {@link #deadlineNs()}, taking at most {@link #costNs()}
     * (0 when the model gives no execution duration), at {@link #rank()}.
     */
    public static final class Release {
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

    /**
     * A module reacting to data: every arrival at one of its {@link #inputs()} runs its step
     * functions and sends its outputs, not sooner than {@link #minIntervalNs()} after the previous
     * reaction. Data sent by an activation belongs to that activation's wave (a timed release or
     * the start begins one); a module reacts at most once per wave, so modules that react to each
     * other in a cycle ({@link ExecutionPlan#reactiveCycles()}) stop when the wave has gone round.
     */
    public static final class Reaction {
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
    }
}
