/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cxx;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.generator.internal.NameScope;
import org.rsaml.model.support.RsamlNames;
import org.rsaml.model.support.RsamlPackages;
import org.rsaml.generator.internal.Names;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.LinkPlan;
import org.rsaml.analysis.plan.PlannedAction;
import org.rsaml.analysis.plan.PlannedFunction;
import org.rsaml.analysis.plan.PlannedLayer;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.analysis.plan.Release;
import org.rsaml.analysis.plan.ReleaseKind;

/**
 * The C++ names of a plan, for the targets that emit a class per module (C++ and ROS 2): project
 * and layer folders, module classes, and the members of each class (methods, ports, releases),
 * sanitised and collision-free, allocated in model order so the same model gives the same names.
 * Used from Xtend as an extension ({@code m.className}).
 */
public final class CxxNames {

    /**
     * Names the module base classes take from the runtime, from rclcpp::Node's public API
     * (rclcpp/node.hpp, Humble to Rolling, and std::enable_shared_from_this) and from the ROS 2 base
     * class itself: model names must not hide them.
     */
    private static final String[] CLASS_RESERVED = { "name", "system", "on_start", "publish_outputs", "run_action",
            "begin_reaction", "trace", "react", "due", "Module", "Node", "options", "publish",
            // the ROS 2 target's ScheduledNode
            "ScheduledNode", "rsaml_ros2", "rsaml_of", "rsaml_core", "rsaml_releases", "rsaml_add_release",
            "rsaml_add_timer", "rsaml_add_arrivals", "rsaml_run_job", "rsaml_run_arrival",
            // rclcpp::Node
            "get_name", "get_namespace", "get_fully_qualified_name", "get_logger", "create_callback_group",
            "get_callback_groups", "for_each_callback_group", "create_publisher", "create_subscription",
            "create_wall_timer", "create_timer", "create_client", "create_service", "create_generic_publisher",
            "create_generic_subscription", "create_generic_client", "create_generic_service", "declare_parameter",
            "declare_parameters", "undeclare_parameter", "has_parameter", "set_parameter", "set_parameters",
            "set_parameters_atomically", "get_parameter", "get_parameter_or", "get_parameters", "describe_parameter",
            "describe_parameters", "get_parameter_types", "list_parameters", "add_pre_set_parameters_callback",
            "add_on_set_parameters_callback", "add_post_set_parameters_callback", "remove_pre_set_parameters_callback",
            "remove_on_set_parameters_callback", "remove_post_set_parameters_callback", "get_node_names",
            "get_topic_names_and_types", "get_service_names_and_types", "get_service_names_and_types_by_node",
            "get_client_names_and_types_by_node", "get_publisher_names_and_types_by_node",
            "get_subscriber_names_and_types_by_node", "count_publishers", "count_subscribers", "count_clients",
            "count_services", "get_publishers_info_by_topic", "get_subscriptions_info_by_topic", "get_graph_event",
            "wait_for_graph_change", "get_clock", "now", "get_node_base_interface", "get_node_clock_interface",
            "get_node_graph_interface", "get_node_logging_interface", "get_node_timers_interface",
            "get_node_topics_interface", "get_node_services_interface", "get_node_waitables_interface",
            "get_node_parameters_interface", "get_node_time_source_interface", "get_node_type_descriptions_interface",
            "get_sub_namespace", "get_effective_namespace", "create_sub_node", "get_node_options", "SharedPtr",
            "WeakPtr", "ConstSharedPtr", "ConstWeakPtr", "UniquePtr", "OnSetParametersCallbackHandle",
            "PreSetParametersCallbackHandle", "PostSetParametersCallbackHandle", "OnParametersSetCallbackType",
            "PreSetParametersCallbackType", "PostSetParametersCallbackType", "shared_from_this", "weak_from_this",
            // the ROS 2 base class
            "positive", "active", "publisher_options", "subscription_options" };

    /** Folder names the generated projects use themselves. */
    /** Layer ids, node names and default topics, as the rule on ROS 2 topics (RSA-28) knows them. */
    private final RsamlNames.Ids ids;

    private final String project;
    private final Map<PlannedLayer, String> layerIds = new IdentityHashMap<>();
    private final Map<PlannedModule, ModuleNames> modules = new IdentityHashMap<>();
    private final Map<PlannedFunction, String> functionMethods = new IdentityHashMap<>();
    private final Map<PlannedFunction, String> lastRunMembers = new IdentityHashMap<>();
    private final Map<PlannedAction, String> actionMethods = new IdentityHashMap<>();
    private final Map<PlannedPort, String> portStems = new IdentityHashMap<>();
    private final Map<Release, String> releaseMethods = new IdentityHashMap<>();
    private final Map<LinkPlan, String> linkStems = new IdentityHashMap<>();

    private static final class ModuleNames {
        String className;
        String nodeName;
        NameScope scope;
        String reactMethod;
    }

    /** The setting under which a target keeps the project name in the output's manifest. */
    public static final String KEPT_PROJECT = "project";

    /**
     * The project name (C++ namespace, build project, package) for this output: the one it was
     * first generated with, so that renaming the architecture does not move the namespace the
     * architect's files are written in; with a warning saying so when the name differs.
     *
     * @param what the things named after the project, for the warning
     * @param ros2 whether the project names ROS 2 packages: then it is none of ROS 2's own packages, and neither
     *             are the interfaces and runtime packages named after it ({@link RsamlPackages#systemPackage})
     */
    public static String stableProject(ExecutionPlan plan, Map<String, String> kept, List<String> warnings, String what, boolean ros2) {
        String named = Names.snake(plan.architecture().getName());
        String fresh = ros2 ? RsamlPackages.systemPackage(named) : named;
        String old = kept.get(KEPT_PROJECT);
        if (old == null || old.equals(fresh) || !old.matches("[a-z][a-z0-9_]*") || old.contains("__") || Names.reserved(old)
                || (ros2 && !RsamlPackages.systemPackage(old).equals(old))) {
            if (!fresh.equals(named)) {
                List<String> own = java.util.stream.Stream.of(named, named + "_" + RsamlPackages.INTERFACES, named + "_" + RsamlPackages.RUNTIME)
                        .filter(RsamlPackages.ROS2_OWN::contains).toList();
                warnings.add(RsamlPackages.renamedFromOwn("architecture '" + plan.name() + "'", fresh, named, own, what + " are"));
            }
            return fresh;
        }
        warnings.add("architecture '" + plan.name() + "' would be named " + fresh + " in code, but this output was generated as "
                + old + ": " + what + " keep the name " + old + " so that your files keep building; to use " + fresh
                + ", generate into a new directory and move your code there");
        return old;
    }

    public CxxNames(ExecutionPlan plan, String project) {
        this.project = project;
        ids = new RsamlNames.Ids(plan.architecture());
        for (PlannedLayer l : plan.layers()) {
            layerIds.put(l, ids.layer(l.layer()));
        }
        Map<PlannedLayer, NameScope> classes = new HashMap<>();
        for (PlannedModule m : plan.modules()) {
            ModuleNames n = new ModuleNames();
            n.className = classes.computeIfAbsent(m.layer(), k -> new NameScope(true))
                    .allocate(Names.pascal(m.module().getName()), "", "", "", "Base", "", "Main");
            n.nodeName = ids.node(m.module());
            String[] reserved = java.util.Arrays.copyOf(CLASS_RESERVED, CLASS_RESERVED.length + 3);
            reserved[CLASS_RESERVED.length] = n.className;
            reserved[CLASS_RESERVED.length + 1] = n.className + "Base";
            reserved[CLASS_RESERVED.length + 2] = n.className + "Main";
            n.scope = new NameScope(false, reserved);
            for (PlannedFunction f : m.functions()) {
                functionMethods.put(f, n.scope.allocate(Names.identifier(f.function().getName())));
            }
            for (PlannedFunction f : m.functions()) {
                for (PlannedAction a : f.actions()) {
                    String preferred = Names.identifier(a.action().getName());
                    actionMethods.put(a, n.scope.isTaken(preferred)
                            ? n.scope.allocate(Names.identifier(f.function().getName() + "_" + a.action().getName()))
                            : n.scope.allocate(preferred));
                }
            }
            modules.put(m, n);
        }
        for (PlannedModule m : plan.modules()) {
            NameScope scope = modules.get(m).scope;
            for (PlannedPort p : m.ports()) {
                String id = Names.stem(p.port().getName());
                portStems.put(p, p.entry() ? scope.allocate(id, "in_", "", "on_", "", "receive_", "", "sub_", "")
                        : scope.allocate(id, "out_", "", "pub_", "", "send_", "", "sent_", ""));
            }
        }
        for (PlannedModule m : plan.modules()) {
            ModuleNames n = modules.get(m);
            for (PlannedFunction f : m.functions()) {
                if (f.minIntervalNs() > 0) {
                    lastRunMembers.put(f, n.scope.allocate("last_run_" + Names.stem(f.function().getName())));
                }
                for (Release r : m.releases()) {
                    if (r.function() == f) {
                        releaseMethods.put(r, n.scope.allocate("release_" + stem(r), "", "", "timer_", ""));
                    }
                }
            }
            for (Release r : m.releases()) {
                if (r.kind() == ReleaseKind.MODULE) {
                    releaseMethods.put(r, n.scope.allocate("release_" + stem(r), "", "", "timer_", ""));
                }
            }
            n.reactMethod = n.scope.allocate("react");
        }
        for (LinkPlan l : plan.links()) {
            linkStems.put(l, modules.get(l.target().module()).scope.allocate(Names.stem(l.link().getName()), "link_", "_until", "link_", "_sub"));
        }
    }

    private static String stem(Release r) {
        return r.kind() == ReleaseKind.MODULE ? "module" : Names.stem(r.elementName());
    }

    /** C++ namespace, CMake project, executable and ROS package name. */
    public String project() {
        return project;
    }

    /** Folder and namespace of a layer. */
    /** The architecture's layer ids, node names and default ROS 2 topics. */
    public RsamlNames.Ids ids() {
        return ids;
    }

    public String layerId(PlannedLayer l) {
        return layerIds.get(l);
    }

    public String layerId(PlannedModule m) {
        return layerIds.get(m.layer());
    }

    /** The architect's class of a module. */
    public String className(PlannedModule m) {
        return modules.get(m).className;
    }

    /** The generated base class the architect's class derives from. */
    public String baseName(PlannedModule m) {
        return className(m) + "Base";
    }

    /** The class or file holding a module's entry point, where a target needs one. */
    public String mainName(PlannedModule m) {
        return className(m) + "Main";
    }

    /** The module's snake-case name, unique in its layer (ROS node name). */
    public String nodeName(PlannedModule m) {
        return modules.get(m).nodeName;
    }

    public String method(PlannedFunction f) {
        return functionMethods.get(f);
    }

    public String method(PlannedAction a) {
        return actionMethods.get(a);
    }

    /** The private method that runs a timed release. */
    public String method(Release r) {
        return releaseMethods.get(r);
    }

    public String timerMember(Release r) {
        return "timer_" + releaseMethods.get(r);
    }

    /** The private method that runs a reaction. */
    public String reactMethod(PlannedModule m) {
        return modules.get(m).reactMethod;
    }

    /** For a sporadic function run by reactions, the member that holds its last run. */
    public String lastRunMember(PlannedFunction f) {
        return lastRunMembers.get(f);
    }

    public String stem(PlannedPort p) {
        return portStems.get(p);
    }

    public String inName(PlannedPort p) {
        return "in_" + portStems.get(p);
    }

    public String onName(PlannedPort p) {
        return "on_" + portStems.get(p);
    }

    public String receiveName(PlannedPort p) {
        return "receive_" + portStems.get(p);
    }

    public String subName(PlannedPort p) {
        return "sub_" + portStems.get(p);
    }

    public String outName(PlannedPort p) {
        return "out_" + portStems.get(p);
    }

    public String pubName(PlannedPort p) {
        return "pub_" + portStems.get(p);
    }

    /** The method that publishes a message at an output port at once, handed over without a copy (ROS 2). */
    public String sendName(PlannedPort p) {
        return "send_" + portStems.get(p);
    }

    /** The member that says an output port's message was sent by its send method since the last publish of its outputs (ROS 2). */
    public String sentName(PlannedPort p) {
        return "sent_" + portStems.get(p);
    }

    /** Member stem of a link in its target module's class. */
    public String stem(LinkPlan l) {
        return linkStems.get(l);
    }

    /** The methods the module's own class is created with: its actions and input handlers. */
    public List<String> stubs(PlannedModule m) {
        List<String> stubs = new ArrayList<>();
        m.actions().forEach(a -> stubs.add(method(a)));
        m.inputs().forEach(p -> stubs.add(onName(p)));
        return stubs;
    }

    /** The methods the architect implements or overrides in the module's own class. */
    public List<String> hooks(PlannedModule m) {
        List<String> hooks = new ArrayList<>();
        m.functions().forEach(f -> hooks.add(method(f)));
        m.actions().forEach(a -> hooks.add(method(a)));
        m.inputs().forEach(p -> hooks.add(onName(p)));
        return hooks;
    }
}
