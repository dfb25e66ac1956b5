/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

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
import org.rsaml.model.OutputPort;
import org.rsaml.model.Port;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Suppressor;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlLabels;

/**
 * What the generators need to know about an architecture, decided once for both targets: the
 * sanitised, collision-free names of every generated thing, how each module is activated (timed
 * releases, data, start), the priority of each timed release, the data types, the topics, and the
 * model elements that cannot be generated (with a warning instead). Everything is in model order,
 * so the same model always gives the same output.
 *
 * <p>Execution model, shared by the targets:
 * <ul>
 * <li>a periodic function is released every period and runs its actions in order, each at its
 * start date within the period; a periodic action whose period differs from its function's (or
 * whose function is not periodic) is released on its own;</li>
 * <li>a periodic module with functions that are not periodic (or with no timed activity at all)
 * is released every module period and runs those functions;</li>
 * <li>a module that is not periodic reacts to data: each arrival runs its non-periodic functions
 * (sporadic ones at most once per period);</li>
 * <li>after each activation the module publishes its outputs.</li>
 * </ul>
 */
public final class ArchitectureView {

    /** Names the module base classes take from the runtime or rclcpp::Node: model names must not hide them. */
    private static final String[] CLASS_RESERVED = { "name", "system", "on_start", "publish_outputs", "run_action",
            "begin_reaction", "trace", "react", "due", "Module", "Node", "get_name", "get_namespace", "get_logger", "get_clock",
            "now", "create_publisher", "create_subscription", "create_wall_timer", "create_timer", "declare_parameter",
            "get_parameter", "set_parameter", "shared_from_this", "get_node_options", "publish", "options" };

    public final Architecture architecture;
    public final String name;
    public final String description;
    /** C++ namespace, CMake project, executable and ROS package name. */
    public final String project;
    public final String interfacesPackage;
    public final List<LayerView> layers = new ArrayList<>();
    /** Modules lowest layer first, then in model order: the order of the start steps. */
    public final List<ModuleView> modules = new ArrayList<>();
    public final List<ConnectionView> connections = new ArrayList<>();
    public final List<LinkView> links = new ArrayList<>();
    public final List<MessageTypeView> messageTypes = new ArrayList<>();
    public final List<ReleaseView> releases = new ArrayList<>();
    /** Model elements that could not be generated as modeled. */
    public final List<String> warnings = new ArrayList<>();

    private final Map<String, MessageTypeView> messageTypesByKey = new LinkedHashMap<>();
    private final Map<Port, PortView> ports = new HashMap<>();
    private final NameScope cppMessageScope = new NameScope(true);
    private final NameScope rosMessageScope = new NameScope(true);

    public ArchitectureView(Architecture architecture) {
        this.architecture = architecture;
        this.name = RsamlLabels.name(architecture);
        this.description = architecture.getDescription();
        this.project = Names.snake(architecture.getName());
        this.interfacesPackage = project + "_interfaces";

        NameScope layerScope = new NameScope(true, "rsaml", "msg", "gen", "src", "launch", "include", "build", "architecture",
                "messages", "main", "user");
        NameScope executables = new NameScope(true);
        NameScope members = new NameScope(false, "system_", "run");
        List<Layer> ordered = new ArrayList<>(architecture.getLayers());
        ordered.sort(Comparator.comparingInt(Layer::getLevel)); // stable: model order within a level
        for (Layer layer : architecture.getLayers()) {
            layers.add(new LayerView(layer, layerScope.allocate(Names.snake(layer.getName()))));
        }
        for (Layer layer : ordered) {
            LayerView lv = layerOf(layer);
            NameScope classes = new NameScope(true);
            NameScope nodes = new NameScope(false);
            for (Module module : layer.getModules()) {
                ModuleView mv = new ModuleView(this, lv, module, classes, nodes);
                mv.executable = executables.allocate(Names.stem(lv.id + "_" + mv.nodeName));
                mv.member = members.allocate(Names.stem(lv.id + "_" + mv.nodeName), "", "_");
                lv.modules.add(mv);
                modules.add(mv);
            }
        }
        for (ModuleView mv : modules) {
            mv.analysePorts();
        }
        for (ModuleView mv : modules) {
            mv.analyseActivation();
        }
        for (Connection c : architecture.getConnections()) {
            addConnection(c);
        }
        for (ModuleView mv : modules) {
            for (Inhibitor i : mv.module.getInhibitors()) {
                addLink(mv, i, i.getTarget(), members);
            }
            for (Suppressor s : mv.module.getSuppressors()) {
                addLink(mv, s, s.getTarget(), members);
            }
        }
        assignPriorities();
        assignTopics();
    }

    private LayerView layerOf(Layer layer) {
        return layers.stream().filter(l -> l.layer == layer).findFirst().orElseThrow();
    }

    PortView port(Port port) {
        return port == null ? null : ports.get(port);
    }

    private void addConnection(Connection c) {
        PortView source = port(c.getSource());
        PortView target = port(c.getTarget());
        String label = RsamlLabels.name(c.getSource()) + " -> " + RsamlLabels.name(c.getTarget());
        if (source == null || target == null) {
            warnings.add("connection " + label + " is not generated: it lacks a source or a target port in a layer");
            return;
        }
        if (!source.sameType(target)) {
            warnings.add("connection " + source.qualifiedName + " -> " + target.qualifiedName
                    + " is not generated: the ports carry different data (" + source.typeLabel() + " vs " + target.typeLabel() + ")");
            return;
        }
        ConnectionView cv = new ConnectionView(source, target);
        connections.add(cv);
        source.outgoing.add(cv);
        target.incoming.add(cv);
    }

    private void addLink(ModuleView owner, SubsumptionLink link, Port targetPort, NameScope members) {
        boolean inhibitor = link instanceof Inhibitor;
        String kind = inhibitor ? "inhibitor" : "suppressor";
        String label = owner.qualifiedName + "." + RsamlLabels.name(link);
        PortView trigger = port(link.getTrigger());
        PortView target = port(targetPort);
        if (target == null) {
            warnings.add(kind + " " + label + " is not generated: it has no target port");
            return;
        }
        if (trigger == null) {
            warnings.add(kind + " " + label + " is not generated: it has no trigger port, so nothing can activate it");
            return;
        }
        LinkView lv = new LinkView(link, inhibitor, owner, label, trigger, target, nanos(link.getDuration(), link));
        lv.member = members.allocate(Names.stem("link_" + owner.member + "_" + link.getName()), "", "_");
        lv.stem = target.module.scope.allocate(Names.stem(link.getName()), "link_", "_until", "link_", "_sub");
        lv.deliversData = !inhibitor && trigger.sameType(target);
        if (!inhibitor && !lv.deliversData) {
            warnings.add("suppressor " + label + " blocks " + target.qualifiedName + " but cannot replace its data: its trigger "
                    + trigger.qualifiedName + " carries " + trigger.typeLabel() + ", the target " + target.typeLabel());
        }
        links.add(lv);
        trigger.triggers.add(lv);
        if (inhibitor) {
            target.inhibitors.add(lv);
        } else {
            target.suppressors.add(lv);
        }
    }

    /**
     * Rate-monotonic releases rank by period and deadline-monotonic ones by delay (shorter is
     * higher); every other policy runs first-in first-out at the lowest real-time priority, as given.
     */
    private void assignPriorities() {
        TreeSet<Long> keys = new TreeSet<>(Comparator.reverseOrder());
        for (ReleaseView r : releases) {
            if (r.priorityKey > 0) {
                keys.add(r.priorityKey);
            }
        }
        List<Long> ordered = new ArrayList<>(keys);
        for (ReleaseView r : releases) {
            r.rank = r.priorityKey > 0 ? ordered.indexOf(r.priorityKey) + 2 : 1;
        }
    }

    /** Ports joined by connections form one topic, named after their first output port. */
    private void assignTopics() {
        List<PortView> all = new ArrayList<>();
        for (ModuleView m : modules) {
            all.addAll(m.ports);
        }
        Map<PortView, PortView> parent = new HashMap<>();
        for (PortView p : all) {
            parent.put(p, p);
        }
        for (ConnectionView c : connections) {
            PortView a = find(parent, c.source);
            PortView b = find(parent, c.target);
            if (a != b) {
                parent.put(b, a);
            }
        }
        Map<PortView, String> topicOfRoot = new HashMap<>();
        for (PortView p : all) {
            if (!p.entry) {
                topicOfRoot.putIfAbsent(find(parent, p), p.ownTopic());
            }
        }
        for (PortView p : all) {
            p.topic = topicOfRoot.getOrDefault(find(parent, p), p.ownTopic());
        }
    }

    private static PortView find(Map<PortView, PortView> parent, PortView p) {
        while (parent.get(p) != p) {
            p = parent.get(p);
        }
        return p;
    }

    MessageTypeView messageType(String raw) {
        String key = raw == null || raw.isBlank() ? "StructuredData" : raw.strip();
        return messageTypesByKey.computeIfAbsent(key, k -> {
            MessageTypeView t = new MessageTypeView(this, k, cppMessageScope, rosMessageScope);
            messageTypes.add(t);
            return t;
        });
    }

    /** Modules that are not timed and react to each other in a cycle: every message would go round for ever. */
    public List<List<ModuleView>> reactiveCycles() {
        Map<ModuleView, List<ModuleView>> edges = new LinkedHashMap<>();
        for (ConnectionView c : connections) {
            if (c.source.module.reactive && c.target.module.reactive) {
                edges.computeIfAbsent(c.source.module, k -> new ArrayList<>()).add(c.target.module);
            }
        }
        List<List<ModuleView>> cycles = new ArrayList<>();
        new Object() {
            int index;
            final Map<ModuleView, Integer> idx = new HashMap<>();
            final Map<ModuleView, Integer> low = new HashMap<>();
            final java.util.Deque<ModuleView> stack = new java.util.ArrayDeque<>();

            void run() {
                for (ModuleView m : modules) {
                    if (!idx.containsKey(m)) {
                        visit(m);
                    }
                }
            }

            void visit(ModuleView v) {
                idx.put(v, index);
                low.put(v, index++);
                stack.push(v);
                for (ModuleView w : edges.getOrDefault(v, List.of())) {
                    if (!idx.containsKey(w)) {
                        visit(w);
                        low.put(v, Math.min(low.get(v), low.get(w)));
                    } else if (stack.contains(w)) {
                        low.put(v, Math.min(low.get(v), idx.get(w)));
                    }
                }
                if (low.get(v).equals(idx.get(v))) {
                    List<ModuleView> scc = new ArrayList<>();
                    ModuleView w;
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

    /** A time value of the element in nanoseconds. */
    static long nanos(double value, TimeScaled owner) {
        TimeUnit unit = owner.getTimeUnit() == null ? TimeUnit.MS : owner.getTimeUnit();
        return Math.max(0, Math.round(value * unit.getValue()));
    }

    static boolean timed(RealTimeElement e) {
        return e.getExecType() == ExecutionType.PERIODIC && e.getPeriod() > 0;
    }

    public static final class LayerView {
        public final Layer layer;
        public final String name;
        /** Namespace, folder and ROS namespace. */
        public final String id;
        public final List<ModuleView> modules = new ArrayList<>();

        LayerView(Layer layer, String id) {
            this.layer = layer;
            this.name = RsamlLabels.name(layer);
            this.id = id;
        }
    }

    public static final class ModuleView {
        public final ArchitectureView architecture;
        public final LayerView layer;
        public final Module module;
        public final String name;
        /** {@code layer/module}, the model's names, as the run's trace shows them. */
        public final String qualifiedName;
        public final String description;
        public final String className;
        public final String baseName;
        public final String mainName;
        public final String nodeName;
        public String executable;
        /** The module's member in the generated architecture class. */
        public String member;
        public final NameScope scope;
        public final List<FunctionView> functions = new ArrayList<>();
        public final List<PortView> ports = new ArrayList<>();
        public final List<PortView> inputs = new ArrayList<>();
        public final List<PortView> outputs = new ArrayList<>();
        public final List<ReleaseView> releases = new ArrayList<>();
        /** Functions run when data arrives or when the module itself is released. */
        public final List<FunctionView> stepFunctions = new ArrayList<>();
        public boolean periodic;
        public boolean reactive;
        /** For a sporadic module, the minimum time between two reactions. */
        public long minIntervalNs;
        public String reactMethod = "react";
        private final NameScope topicScope = new NameScope(false);

        ModuleView(ArchitectureView architecture, LayerView layer, Module module, NameScope classes, NameScope nodes) {
            this.architecture = architecture;
            this.layer = layer;
            this.module = module;
            this.name = RsamlLabels.name(module);
            this.qualifiedName = layer.name + "/" + name;
            this.description = module.getDescription();
            this.className = classes.allocate(Names.pascal(module.getName()), "", "", "", "Base", "", "Main");
            this.baseName = className + "Base";
            this.mainName = className + "Main";
            this.nodeName = nodes.allocate(Names.snake(module.getName()));
            String[] reserved = java.util.Arrays.copyOf(CLASS_RESERVED, CLASS_RESERVED.length + 3);
            reserved[CLASS_RESERVED.length] = className;
            reserved[CLASS_RESERVED.length + 1] = baseName;
            reserved[CLASS_RESERVED.length + 2] = mainName;
            this.scope = new NameScope(false, reserved);
            for (Function f : module.getFunctions()) {
                functions.add(new FunctionView(this, f, scope.allocate(Names.identifier(f.getName()))));
            }
            for (FunctionView f : functions) {
                for (Action a : f.function.getActions()) {
                    String preferred = Names.identifier(a.getName());
                    String method = scope.isTaken(preferred) ? scope.allocate(Names.identifier(f.function.getName() + "_" + a.getName()))
                            : scope.allocate(preferred);
                    f.actions.add(new ActionView(f, a, method));
                }
            }
        }

        void analysePorts() {
            for (Port p : module.getPorts()) {
                PortView pv = new PortView(this, p);
                ports.add(pv);
                (pv.entry ? inputs : outputs).add(pv);
                architecture.ports.put(p, pv);
            }
        }

        void analyseActivation() {
            periodic = timed(module);
            boolean anyTimed = false;
            for (FunctionView f : functions) {
                f.analyse();
                if (f.timed) {
                    anyTimed = true;
                    add(new ReleaseView(this, ReleaseKind.FUNCTION, f, null, f.periodNs, 0,
                            policyKey(f.function.getSchedPolicy(), f.function), f.function.getSchedPolicy()));
                } else {
                    stepFunctions.add(f);
                }
                for (ActionView a : f.actions) {
                    if (a.standalone) {
                        anyTimed = true;
                        add(new ReleaseView(this, ReleaseKind.ACTION, f, a, a.periodNs, a.startNs,
                                policyKey(f.function.getSchedPolicy(), a.action), f.function.getSchedPolicy()));
                    }
                }
            }
            if (periodic && (!stepFunctions.isEmpty() || !anyTimed)) {
                add(new ReleaseView(this, ReleaseKind.MODULE, null, null, nanos(module.getPeriod(), module), 0, 0, SchedulingPolicy.FIFO));
            }
            reactive = !periodic && (!stepFunctions.isEmpty() || functions.isEmpty());
            if (module.getExecType() == ExecutionType.SPORADIC && module.getPeriod() > 0) {
                minIntervalNs = nanos(module.getPeriod(), module);
            }
            reactMethod = scope.allocate("react");
        }

        private void add(ReleaseView r) {
            r.method = scope.allocate("release_" + r.stem, "", "", "timer_", "");
            r.timerMember = "timer_" + r.method;
            releases.add(r);
            architecture.releases.add(r);
        }

        private static long policyKey(SchedulingPolicy policy, RealTimeElement e) {
            if (policy == SchedulingPolicy.RM) {
                return nanos(e.getPeriod(), e);
            }
            if (policy == SchedulingPolicy.DM) {
                return e.getDelay() > 0 ? nanos(e.getDelay(), e) : nanos(e.getPeriod(), e);
            }
            return 0;
        }

        public List<ActionView> actions() {
            List<ActionView> all = new ArrayList<>();
            functions.forEach(f -> all.addAll(f.actions));
            return all;
        }

        /** The methods the module's own class is created with: its actions and input handlers. */
        public List<String> stubs() {
            List<String> stubs = new ArrayList<>();
            actions().forEach(a -> stubs.add(a.method));
            inputs.forEach(p -> stubs.add(p.onName));
            return stubs;
        }

        /** The methods the architect implements or overrides in the module's own class. */
        public List<String> hooks() {
            List<String> hooks = new ArrayList<>();
            functions.forEach(f -> hooks.add(f.method));
            actions().forEach(a -> hooks.add(a.method));
            inputs.forEach(p -> hooks.add(p.onName));
            return hooks;
        }

        public String timing() {
            return RsamlLabels.timing(module);
        }

        String topicSegment(String portName) {
            return topicScope.allocate(Names.snake(portName));
        }
    }

    public static final class FunctionView {
        public final ModuleView module;
        public final Function function;
        public final String name;
        public final String method;
        public final String description;
        public final List<ActionView> actions = new ArrayList<>();
        public boolean timed;
        public long periodNs;
        /** For a sporadic function run by reactions, the minimum time between two runs (0: none). */
        public long minIntervalNs;
        public String lastRunMember;

        FunctionView(ModuleView module, Function function, String method) {
            this.module = module;
            this.function = function;
            this.name = RsamlLabels.name(function);
            this.method = method;
            this.description = function.getDescription();
        }

        void analyse() {
            timed = timed(function);
            periodNs = timed ? nanos(function.getPeriod(), function) : 0;
            if (function.getExecType() == ExecutionType.SPORADIC && function.getPeriod() > 0) {
                minIntervalNs = nanos(function.getPeriod(), function);
                lastRunMember = module.scope.allocate("last_run_" + Names.stem(function.getName()));
            }
            for (ActionView a : actions) {
                a.analyse();
            }
        }

        /** The actions this function runs itself, in order (the others are released on their own). */
        public List<ActionView> inlineActions() {
            return actions.stream().filter(a -> !a.standalone).toList();
        }

        public String label() {
            return module.qualifiedName + "." + name;
        }

        public String timing() {
            return RsamlLabels.timing(function);
        }
    }

    public static final class ActionView {
        public final FunctionView function;
        public final Action action;
        public final String name;
        public final String method;
        public final String description;
        public boolean standalone;
        public long periodNs;
        public long startNs;
        /** Delay after the function's release before this action runs (timed functions only). */
        public long offsetNs;

        ActionView(FunctionView function, Action action, String method) {
            this.function = function;
            this.action = action;
            this.name = RsamlLabels.name(action);
            this.method = method;
            this.description = action.getDescription();
        }

        void analyse() {
            boolean ownTimer = timed(action);
            periodNs = ownTimer ? nanos(action.getPeriod(), action) : 0;
            startNs = nanos(action.getStartDate(), action);
            standalone = ownTimer && !(function.timed && periodNs == function.periodNs);
            offsetNs = function.timed && !standalone && function.periodNs > 0 ? startNs % function.periodNs : 0;
        }

        public String label() {
            return function.label() + "." + name;
        }

        public String timing() {
            return RsamlLabels.timing(action);
        }
    }

    public enum DataKind {
        NUMERIC, ALPHANUMERIC, BOOLEAN, STRUCTURED
    }

    public static final class PortView {
        public final ModuleView module;
        public final Port port;
        public final boolean entry;
        public final String name;
        public final String qualifiedName;
        public final String description;
        public final DataKind kind;
        public final MessageTypeView messageType;
        public final String stem;
        public final String inName;
        public final String onName;
        public final String receiveName;
        public final String subName;
        public final String outName;
        public final String pubName;
        public final String topicSegment;
        public String topic;
        public final List<ConnectionView> outgoing = new ArrayList<>();
        public final List<ConnectionView> incoming = new ArrayList<>();
        public final List<LinkView> triggers = new ArrayList<>();
        public final List<LinkView> inhibitors = new ArrayList<>();
        public final List<LinkView> suppressors = new ArrayList<>();

        PortView(ModuleView module, Port port) {
            this.module = module;
            this.port = port;
            this.entry = port instanceof EntryPort;
            this.name = RsamlLabels.name(port);
            this.qualifiedName = module.qualifiedName + "." + name;
            this.description = port.getDescription();
            DataType type = port.getDataType() == null ? DataType.NUMERIC : port.getDataType();
            this.kind = switch (type) {
                case ALPHANUMERIC -> DataKind.ALPHANUMERIC;
                case BOOLEAN -> DataKind.BOOLEAN;
                case STRUCTURED -> DataKind.STRUCTURED;
                default -> DataKind.NUMERIC;
            };
            this.messageType = kind == DataKind.STRUCTURED ? module.architecture.messageType(port.getMessageType()) : null;
            String id = Names.stem(port.getName());
            if (entry) {
                stem = module.scope.allocate(id, "in_", "", "on_", "", "receive_", "", "sub_", "");
                inName = "in_" + stem;
                onName = "on_" + stem;
                receiveName = "receive_" + stem;
                subName = "sub_" + stem;
                outName = null;
                pubName = null;
            } else {
                stem = module.scope.allocate(id, "out_", "", "pub_", "");
                outName = "out_" + stem;
                pubName = "pub_" + stem;
                inName = null;
                onName = null;
                receiveName = null;
                subName = null;
            }
            this.topicSegment = module.topicSegment(port.getName());
        }

        boolean sameType(PortView other) {
            return kind == other.kind && messageType == other.messageType;
        }

        public String typeLabel() {
            return kind == DataKind.STRUCTURED ? "structured data '" + messageType.key + "'" : kind.name().toLowerCase(java.util.Locale.ROOT) + " data";
        }

        public String cppType() {
            return switch (kind) {
                case NUMERIC -> "double";
                case ALPHANUMERIC -> "std::string";
                case BOOLEAN -> "bool";
                case STRUCTURED -> messageType.cppName;
            };
        }

        public String rosType() {
            return switch (kind) {
                case NUMERIC -> "std_msgs::msg::Float64";
                case ALPHANUMERIC -> "std_msgs::msg::String";
                case BOOLEAN -> "std_msgs::msg::Bool";
                case STRUCTURED -> messageType.rosCppName;
            };
        }

        public String rosHeader() {
            return switch (kind) {
                case NUMERIC -> "std_msgs/msg/float64.hpp";
                case ALPHANUMERIC -> "std_msgs/msg/string.hpp";
                case BOOLEAN -> "std_msgs/msg/bool.hpp";
                case STRUCTURED -> messageType.rosHeader;
            };
        }

        public String rosPackage() {
            return kind == DataKind.STRUCTURED ? messageType.rosPackage : "std_msgs";
        }

        String ownTopic() {
            return "/" + module.layer.id + "/" + module.nodeName + "/" + topicSegment;
        }
    }

    public static final class ConnectionView {
        public final PortView source;
        public final PortView target;

        ConnectionView(PortView source, PortView target) {
            this.source = source;
            this.target = target;
        }
    }

    public static final class LinkView {
        public final SubsumptionLink link;
        public final boolean inhibitor;
        public final ModuleView owner;
        public final String name;
        /** {@code layer/module.link}. */
        public final String qualifiedName;
        public final PortView trigger;
        public final PortView target;
        public final long durationNs;
        public boolean deliversData;
        public String member;
        /** Member stem in the target module's class (ROS 2). */
        public String stem;

        LinkView(SubsumptionLink link, boolean inhibitor, ModuleView owner, String qualifiedName, PortView trigger,
                PortView target, long durationNs) {
            this.link = link;
            this.inhibitor = inhibitor;
            this.owner = owner;
            this.name = RsamlLabels.name(link);
            this.qualifiedName = qualifiedName;
            this.trigger = trigger;
            this.target = target;
            this.durationNs = durationNs;
        }

        public String description() {
            return link.getDescription();
        }
    }

    public enum ReleaseKind {
        FUNCTION, ACTION, MODULE
    }

    public static final class ReleaseView {
        public final ModuleView module;
        public final ReleaseKind kind;
        public final FunctionView function;
        public final ActionView action;
        public final long periodNs;
        public final long offsetNs;
        final long priorityKey;
        public final SchedulingPolicy policy;
        /** 1 is the lowest real-time priority; higher ranks preempt lower ones. */
        public int rank;
        public String method;
        public String timerMember;
        final String stem;

        ReleaseView(ModuleView module, ReleaseKind kind, FunctionView function, ActionView action, long periodNs,
                long offsetNs, long priorityKey, SchedulingPolicy policy) {
            this.module = module;
            this.kind = kind;
            this.function = function;
            this.action = action;
            this.periodNs = Math.max(1, periodNs);
            this.offsetNs = offsetNs;
            this.priorityKey = priorityKey;
            this.policy = policy == null ? SchedulingPolicy.FIFO : policy;
            this.stem = switch (kind) {
                case FUNCTION -> Names.stem(function.function.getName());
                case ACTION -> Names.stem(action.action.getName());
                case MODULE -> "module";
            };
        }

        /** What the trace calls this release: {@code layer/module.function[.action]} or {@code layer/module}. */
        public String label() {
            return switch (kind) {
                case FUNCTION -> function.label();
                case ACTION -> action.label();
                case MODULE -> module.qualifiedName;
            };
        }

        /** The POSIX policy: round robin for RR, first-in first-out for every other policy. */
        public String posixPolicy() {
            return policy == SchedulingPolicy.RR ? "RoundRobin" : "Fifo";
        }

        public String why() {
            return switch (policy) {
                case RM -> "rate monotonic: priority by period";
                case DM -> "deadline monotonic: priority by delay";
                case RR -> "round robin";
                default -> policy.getLiteral() + ": first in, first out at the base priority";
            };
        }
    }

    public static final class MessageTypeView {
        private static final Pattern ROS_NAME = Pattern.compile("([a-z][a-z0-9_]*)/(?:msg/)?([A-Z][A-Za-z0-9]*)");
        public final String key;
        /** C++ target: the user's struct. */
        public final String cppName;
        public final String cppHeader;
        public final List<String> cppNamespaces = new ArrayList<>();
        public final String cppStruct;
        /** ROS 2 target. */
        public final String rosPackage;
        public final String rosName;
        public final String rosCppName;
        public final String rosHeader;
        /** Whether the ROS 2 type is defined in the generated interfaces package. */
        public final boolean rosGenerated;

        MessageTypeView(ArchitectureView arch, String key, NameScope cppScope, NameScope rosScope) {
            this.key = key;
            String[] segments = key.split("/|::|\\.");
            List<String> path = new ArrayList<>();
            for (int i = 0; i < segments.length - 1; i++) {
                if (!segments[i].isBlank()) {
                    path.add(Names.identifier(segments[i]));
                }
            }
            String struct = Names.pascal(segments.length == 0 ? key : segments[segments.length - 1]);
            String prefix = path.isEmpty() ? "" : String.join("/", path) + "/";
            struct = cppScope.allocate(prefix + struct).substring(prefix.length());
            cppNamespaces.addAll(path);
            cppStruct = struct;
            cppName = "::" + arch.project + "::msg::" + (path.isEmpty() ? "" : String.join("::", path) + "::") + struct;
            cppHeader = "msg/" + prefix + struct + ".hpp";

            Matcher m = ROS_NAME.matcher(key);
            if (m.matches()) {
                rosGenerated = false;
                rosPackage = m.group(1);
                rosName = m.group(2);
            } else {
                rosGenerated = true;
                rosPackage = arch.interfacesPackage;
                String base = String.join("", Names.words(key.replace("/", "_")).stream()
                        .map(w -> Character.toUpperCase(w.charAt(0)) + w.substring(1)).toList());
                if (base.isEmpty() || !Character.isLetter(base.charAt(0))) {
                    base = "Msg" + base;
                }
                rosName = rosScope.allocate(base).replace("_", "");
            }
            rosCppName = rosPackage + "::msg::" + rosName;
            rosHeader = rosPackage + "/msg/" + Names.rosidlHeaderStem(rosName) + ".hpp";
        }
    }
}
