/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.SubsumptionLink;
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
 *
 * <p>This class holds the plan and its types (nested, as targets name them); {@code Planner}
 * builds it, {@link PlanTimes} reads the model's times, {@code PlanWarnings} words what cannot
 * execute and {@code ReactiveCycles} finds the reactive cycles.
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
    final List<PlannedLayer> layers = new ArrayList<>();
    final List<PlannedModule> modules = new ArrayList<>();
    final List<Flow> flows = new ArrayList<>();
    final List<LinkPlan> links = new ArrayList<>();
    final List<Release> releases = new ArrayList<>();
    final List<Reaction> reactions = new ArrayList<>();
    final Set<String> messageTypes = new LinkedHashSet<>();
    final List<String> warnings = new ArrayList<>();
    final Map<Port, PlannedPort> ports = new IdentityHashMap<>();

    /** An empty plan, filled by the {@link Planner}. */
    ExecutionPlan(Architecture architecture) {
        this.architecture = architecture;
        this.name = RsamlLabels.name(architecture);
    }

    /**
     * The plan of an architecture.
     *
     * @throws UnplannableException a time of the model cannot be represented (not finite, negative,
     *                              a period below 1 ns, or longer than {@link #MAX_TIME_NS})
     */
    public static ExecutionPlan of(Architecture architecture) throws UnplannableException {
        return Planner.plan(architecture);
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
        return List.copyOf(messageTypes);
    }

    /** Model elements that cannot execute as modeled. */
    public List<String> warnings() {
        return Collections.unmodifiableList(warnings);
    }

    /** The plan of a port, or null when the port is not in a module of a layer. */
    public PlannedPort port(Port port) {
        return port == null ? null : ports.get(port);
    }

    /**
     * Modules that react to data (not timed) and to each other in a cycle, each cycle in module
     * order. Where data carries no wave (see {@link Reaction}), a message would go round for ever.
     */
    public List<List<PlannedModule>> reactiveCycles() {
        return ReactiveCycles.of(this);
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

        /**
         * Relative deadline of a reaction, from the arrival that starts it: the module's delay, else
         * its minimum interval; 0 (none) for an aperiodic module without a delay.
         */
        public long deadlineNs() {
            long delay = PlanTimes.nanos(module.module.getDelay(), module.module);
            return delay > 0 ? delay : module.minIntervalNs;
        }

        /** Modeled execution time of a reaction: the module's execDuration, else the sum of its step functions'. */
        public long costNs() {
            long cost = PlanTimes.nanos(module.module.getExecDuration(), module.module);
            if (cost == 0) {
                for (PlannedFunction f : module.stepFunctions()) {
                    cost = Math.addExact(cost, PlanTimes.nanos(f.function.getExecDuration(), f.function));
                }
            }
            return cost;
        }

        /** Whether the module gives no execution duration of its own, so that {@link #costNs()} sums its functions'. */
        public boolean costFromFunctions() {
            return PlanTimes.nanos(module.module.getExecDuration(), module.module) == 0;
        }

        /** What traces call it: {@code layer/module (reaction)}, as the analysis names its task. */
        public String label() {
            return module.qualifiedName + " (reaction)";
        }
    }
}
