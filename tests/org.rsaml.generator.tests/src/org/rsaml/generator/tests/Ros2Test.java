/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.Names;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.support.RsamlTopics;
import org.rsaml.validation.ModelLoader;

/**
 * What can be checked of the ROS 2 target here, for every example and for hostile names: each
 * package.xml is valid against the REP 149 format 3 schema and parses with catkin_pkg; every
 * package configures, builds and installs with the real ament_cmake and rosidl (see
 * {@link Ros2Build}) with modern CMake targets, warnings as errors; both launch files compile and,
 * run against stand-in launch modules, start one node per module (as components of one container,
 * or as processes), every node in the launch namespace; connected ports share a relative topic;
 * every periodic function has a timer on the node's clock whose period is a parameter with the
 * model's value; sensor streams use the sensor data QoS and everything else is reliable. rclcpp
 * itself is a stand-in: the nodes are compiled and linked, not run.
 */
class Ros2Test {

    /** The parameters every node gets in both launch files after its own from the parameters file. */
    static final String PARAMETERS = "{'use_sim_time': $(use_sim_time), 'rsaml.simulated_load': ParameterValue($(simulated_load), float)}]";

    static List<String> models() throws Exception {
        List<String> models = new ArrayList<>(Tools.cleanExamples());
        models.add("resources/names-hostile.rsaml");
        models.add("resources/ros2-node-api-names.rsaml");
        return models;
    }

    static Path model(String name) {
        return name.startsWith("resources/") ? Tools.resource(name.substring(10)) : Tools.example(name);
    }

    /** Runs a launch file against the stand-in launch modules and prints what it starts. */
    private static final String LAUNCH = """
            import importlib.util, sys
            sys.dont_write_bytecode = True
            sys.path.insert(0, sys.argv[2])
            spec = importlib.util.spec_from_file_location('l', sys.argv[1]); m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)
            class Context:
                launch_configurations = {}
                package_shares = {sys.argv[3]: sys.argv[4]}  # the package's source folder holds config/ as its share folder will
            entities = m.generate_launch_description().entities
            for e in entities:
                if type(e).__name__ == 'DeclareLaunchArgument':
                    Context.launch_configurations[e.name] = e.default_value
            for a in sys.argv[5:]:  # NAME:=VALUE, as on ros2 launch's command line
                Context.launch_configurations[a.split(':=', 1)[0]] = a.split(':=', 1)[1]
            started = []
            for e in entities:
                started += e.function(Context) if type(e).__name__ == 'OpaqueFunction' else [e]
            for e in started:
                kind = type(e).__name__
                if kind == 'DeclareLaunchArgument':
                    print('argument', e.name, repr(e.default_value))
                elif kind == 'ComposableNodeContainer':
                    print('container', e.package, e.executable, repr(e.namespace), e.name)
                    for c in e.composable_node_descriptions:
                        print('component', c.package, c.plugin, repr(c.namespace), c.name, repr(c.parameters))
                        print('extra', c.name, repr(c.extra_arguments))
                        for r in c.remappings or []:
                            print('remap', r[0], r[1])
                else:
                    print('node', e.package, e.executable, repr(e.namespace), e.name, repr(e.parameters))
                    for r in e.remappings or []:
                        print('remap', r[0], r[1])
                if kind != 'DeclareLaunchArgument' and e.other.get('prefix') is not None:
                    print('prefix', e.name, e.other['prefix'])
            """;

    @ParameterizedTest
    @MethodSource("models")
    void packagesBuildWithRosidlAndStartAsComponentsOrProcesses(String name, @TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model(name), Target.ROS2, out, false);
        Architecture arch = ModelLoader.load(model(name), name).architecture();
        String pkg = Names.snake(arch.getName());
        Path root = out.resolve(pkg);

        // package.xml: REP 149 format 3, read by catkin_pkg as colcon would.
        List<Path> manifests;
        try (Stream<Path> s = Files.list(out)) {
            manifests = s.map(p -> p.resolve("package.xml")).filter(Files::exists).sorted().toList();
        }
        for (Path manifest : manifests) {
            Ros2Build.validateManifest(manifest);
            String parsed = Tools.ok(out, 60, Ros2Build.python(), "-c", "import sys\nfrom catkin_pkg.package import parse_package\n"
                    + "p = parse_package(sys.argv[1])\nprint(p.package_format, p.name, ' '.join(sorted(d.name for d in p.build_depends)),"
                    + " '|', ' '.join(sorted(d.name for d in p.exec_depends)))", manifest.toString());
            assertTrue(parsed.startsWith("3 " + manifest.getParent().getFileName()), parsed);
            if (manifest.getParent().equals(root)) {
                assertTrue(parsed.contains(" rclcpp ") && parsed.contains(" rclcpp_components "), parsed);
                assertTrue(parsed.contains(" ros2launch"), "ros2 launch needs ros2launch at run time: " + parsed);
            }
        }

        // Modern CMake targets: ament_target_dependencies() is gone from Rolling.
        String cmake = Files.readString(root.resolve("CMakeLists.txt"));
        assertFalse(cmake.contains("ament_target_dependencies"), cmake);
        assertTrue(cmake.contains("target_link_libraries(${PROJECT_NAME} PUBLIC rclcpp::rclcpp Threads::Threads"), cmake);
        assertTrue(cmake.contains(" PRIVATE rclcpp_components::component)"), cmake);

        // Every package builds as colcon would: the real rosidl generates each .msg, the nodes
        // compile against those headers and the stand-in rclcpp, warnings as errors, and each
        // component's executable links only if the library registers the class it names.
        Ros2Build.buildAll(out, tmp.resolve("colcon"));

        // The launch files: one container with a component per module, or a process per module.
        int modules = arch.getLayers().stream().mapToInt(l -> l.getModules().size()).sum();
        // Every module's class is a registered component, and has an executable of its own whose
        // main() runs that class (the executable is named as the node).
        Map<String, String> plugins = new TreeMap<>();
        Matcher registered = Pattern.compile("rclcpp_components_register_nodes\\(\\$\\{PROJECT_NAME\\}\\s+((?:\"[\\w:]+\"\\s+)+)\\)").matcher(cmake);
        assertTrue(registered.find(), cmake);
        Matcher exe = Pattern.compile("add_executable\\((\\w+) (gen/\\w+/\\w+Main\\.cpp)\\)").matcher(cmake);
        while (exe.find()) {
            Matcher run = Pattern.compile("run_standalone<([\\w:]+)>").matcher(Files.readString(root.resolve(exe.group(2))));
            assertTrue(run.find(), exe.group(2));
            assertTrue(registered.group(1).contains("\"" + run.group(1) + "\""), run.group(1) + " is not registered: " + cmake);
            plugins.put(run.group(1), exe.group(1));
        }
        assertEquals(modules, plugins.size(), cmake);
        String composed = launch(out, root.resolve("launch/" + pkg + ".launch.py"));
        String processes = launch(out, root.resolve("launch/" + pkg + "_processes.launch.py"));
        for (String started : List.of(composed, processes)) {
            assertTrue(started.contains("argument namespace ''"), started);
            assertTrue(started.contains("argument use_sim_time 'false'"), started);
            assertTrue(started.contains("argument simulated_load '0.0'"), started);
        }
        assertTrue(composed.contains("container " + pkg + " " + pkg + "_component_container $(namespace)"), composed);
        assertTrue(cmake.contains("add_executable(" + pkg + "_component_container gen/rsaml/container.cpp)"), cmake);
        assertDeployed(arch, pkg, root, composed, processes);
        List<String> components = composed.lines().filter(l -> l.startsWith("component ")).toList();
        List<String> nodes = processes.lines().filter(l -> l.startsWith("node ")).toList();
        assertEquals(modules, components.size(), composed);
        assertEquals(modules, nodes.size(), processes);
        TreeSet<String> nodeNames = new TreeSet<>();
        // Each node gets its values from the parameters file (config/<pkg>.params.yaml), then those of the launch arguments.
        Map<String, String> nodeParameters = new TreeMap<>();
        for (String c : components) {
            String[] f = c.split(" ");
            assertEquals(pkg, f[1], "the component is in the model's package: " + c);
            assertTrue(plugins.containsKey(f[2]), "component " + f[2] + " is not registered in CMakeLists.txt");
            assertEquals("$(namespace)", f[3], c);
            String parameters = c.substring(c.indexOf(" [{") + 1);
            assertTrue(parameters.startsWith("[{") && parameters.endsWith(", " + PARAMETERS), c);
            nodeNames.add(f[4]);
            nodeParameters.put(f[4], parameters);
            assertTrue(nodes.stream().anyMatch(n -> n.equals("node " + pkg + " " + plugins.get(f[2]) + " $(namespace) " + f[4]
                    + " " + parameters)), "no process for " + c + " with the same parameters: " + nodes);
        }
        assertEquals(modules, nodeNames.size(), "node names are not unique: " + components);
        // The nodes of a container use intra-process communication (messages shared, not copied).
        for (String n : nodeNames) {
            assertTrue(composed.contains("extra " + n + " [{'use_intra_process_comms': True}]"), "component " + n
                    + " does not use intra-process communication: " + composed);
        }

        // Each module has its node, named as the launch files name it.
        Map<String, String> nodesByModule = nodes(root);
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                String node = nodesByModule.get(layer.getName() + "/" + m.getName());
                assertTrue(node != null && nodeNames.contains(node), "no node for module " + layer.getName() + "/" + m.getName());
            }
        }

        // Connected ports share one topic: the one the model names for them, else one of the
        // publisher's path; relative, unless the model names an absolute one, so that the launch
        // namespace applies. Each named topic has a launch argument that renames it in every node.
        Map<String, String> topics = topics(root);
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                for (Port p : m.getPorts()) {
                    String t = topics.get(key(m) + (p instanceof OutputPort ? "/pub_" : "/sub_") + Names.stem(p.getName()));
                    if (t == null) {
                        continue; // a member named apart from its port (hostile names): its connections are checked below
                    }
                    String named = RsamlTopics.sharedTopic(p);
                    assertEquals(named != null && named.startsWith("/"), t.startsWith("/"), "topic " + t + " of " + key(m) + "/" + p.getName());
                    if (named != null) {
                        assertEquals(named, t, "the topic " + key(m) + "/" + p.getName() + " names");
                        String argument = named.replaceFirst("^/", "").replace('/', '_') + "_topic";
                        for (String started : List.of(composed, processes)) {
                            assertTrue(started.contains("argument " + argument + " '" + named + "'"), started);
                            assertTrue(started.contains("remap " + named + " $(" + argument + ")"), started);
                        }
                    }
                }
            }
        }
        for (Connection c : arch.getConnections()) {
            String pub = topics.get(key(c.getSource().getModule()) + "/pub_" + Names.stem(c.getSource().getName()));
            String sub = topics.get(key(c.getTarget().getModule()) + "/sub_" + Names.stem(c.getTarget().getName()));
            assertTrue(pub != null && pub.equals(sub), c.getSource().getName() + " publishes on " + pub + ", "
                    + c.getTarget().getName() + " listens on " + sub);
        }

        // QoS: sensor streams best effort, the rest reliable, both overridable by parameters.
        Map<String, String> qos = qos(root);
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                boolean perception = !m.getSensors().isEmpty() && m.getActuators().isEmpty();
                for (Port p : m.getPorts()) {
                    if (p instanceof OutputPort) {
                        String q = qos.get(key(m) + "/pub_" + Names.stem(p.getName()));
                        assertEquals(perception ? "rclcpp::SensorDataQoS()" : "rclcpp::QoS(10).reliable()", q, p.getName());
                    }
                }
            }
        }

        // Messages by shared pointer, the package's launch test, the timers and their period parameters.
        Ros2NodeCode.assertMessagesByPointer(arch, root);
        Ros2NodeCode.assertLaunchTest(arch, pkg, root, cmake);
        Ros2NodeCode.assertTimers(arch, root, nodeParameters, nodesByModule);
    }

    private static final Pattern LINK = Pattern.compile("// (?:Inhibitor|Suppressor) (\\S+), triggered by [^\\n]*\\n\\s*link_(\\w+)_sub_ = "
            + "this->create_subscription<([\\w:]+)>\\((.*?)subscription_options\\);", Pattern.DOTALL);

    /**
     * A link's subscription to its trigger topic asserts the link as docs/timing.md says: on a
     * boolean trigger only a true message sets the link's time (a false one returns before it,
     * delivering nothing), on any other data kind every message does. Subsumption-brooks has both:
     * whenlook's boolean startLook and numeric headings. (It builds in the test above.)
     */
    @org.junit.jupiter.api.Test
    void linksAreAssertedOnlyByTrueOnBooleanTriggers(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(Tools.example("subsumption-brooks.rsaml"), Target.ROS2, out, false);
        String all = Ros2NodeCode.allText(out.resolve("subsumption_mobile_robot/gen"));
        Matcher link = LINK.matcher(all);
        Set<String> booleans = new TreeSet<>();
        Set<String> others = new TreeSet<>();
        while (link.find()) {
            String body = link.group(4);
            int set = body.indexOf("link_" + link.group(2) + "_until_ = ");
            assertTrue(set > 0, "the subscription of " + link.group(1) + " never sets the link's time:\n" + body);
            boolean guarded = Pattern.compile("if \\(!message->data\\) \\{\\s*return;").matcher(body.substring(0, set)).find();
            if (link.group(3).equals("std_msgs::msg::Bool")) {
                booleans.add(link.group(1));
                assertTrue(guarded, "a false message on the boolean trigger of " + link.group(1) + " must not assert it:\n" + body);
            } else {
                others.add(link.group(1));
                assertFalse(guarded || body.contains("message->data"), "every message on the " + link.group(3) + " trigger of "
                        + link.group(1) + " asserts it:\n" + body);
            }
        }
        assertEquals(Set.of("explore/whenlook.stopWandering"), booleans, "links with a boolean trigger");
        assertEquals(Set.of("explore/pathplan.overrideWander", "wander/avoid.overrideRunAway"), others, "links with another trigger");
    }

    /**
     * Every subscription of a node (entry ports, link triggers) is in the node's data group, which the
     * node creates in its constructor, so that the executor thread serving it at priority 0 of the
     * analysis exists before a managed node creates its subscriptions on configure; a node without
     * subscriptions has no data group (no idle real-time thread). Subsumption-brooks has entry ports
     * and link triggers, ros2-lifecycle managed nodes.
     */
    @org.junit.jupiter.api.Test
    void everySubscriptionIsInItsNodesDataGroup(@TempDir Path tmp) throws Exception {
        int nodes = 0;
        for (Path model : List.of(Tools.example("subsumption-brooks.rsaml"), Tools.resource("ros2-lifecycle.rsaml"))) {
            Path out = tmp.resolve(model.getFileName().toString());
            new RsamlGenerator().generate(model, Target.ROS2, out, false);
            List<Path> headers;
            try (Stream<Path> s = Files.walk(out)) {
                headers = s.filter(f -> f.toString().endsWith(".hpp") && f.toString().contains("/gen/") && !f.toString().contains("/gen/rsaml/"))
                        .sorted().toList();
            }
            assertFalse(headers.isEmpty(), "no node header generated in " + out);
            for (Path h : headers) {
                String text = Files.readString(h);
                int subscriptions = (int) Pattern.compile("create_subscription<").matcher(text).results().count();
                int inGroup = text.indexOf("subscription_options.callback_group = this->rsaml_data_group();");
                int created = text.indexOf("\n    this->rsaml_data_group();\n");
                if (subscriptions == 0) {
                    assertFalse(text.contains("rsaml_data_group"), h + ": a node without subscriptions has no data thread");
                    continue;
                }
                nodes++;
                assertEquals(subscriptions, Pattern.compile("\\s+subscription_options\\);").matcher(text).results().count(),
                        h + ": every subscription takes the subscription options");
                assertTrue(inGroup >= 0 && inGroup < text.indexOf("create_subscription<"),
                        h + ": the subscription options put the subscriptions in the node's data group:\n" + text);
                assertTrue(created >= 0 && created < text.indexOf(" protected:"),
                        h + ": the constructor creates the data group before the node is scheduled:\n" + text);
            }
        }
        assertTrue(nodes >= 3, "nodes with subscriptions checked: " + nodes);
    }

    /**
     * The model's deployment in the launch files: the nodes of the modules one processor runs share
     * a container of their own, the modules no processor names share the package's container, and
     * the processes of a processor with a core (its container, or its nodes' processes) start under
     * taskset on that core; where some processor claims a core, those of the modules without one (an EDF
     * processor's too) start under taskset on the CPUs no processor claims ({@link OneMachineCpus#claimed}, the
     * C++ program's rule); nothing else is confined.
     */
    private static void assertDeployed(Architecture arch, String pkg, Path root, String composed, String processes) throws Exception {
        Map<String, String> containerOf = new TreeMap<>();
        Map<String, String> prefixes = new TreeMap<>();
        String container = null;
        for (String line : (composed + "\n" + processes).lines().toList()) {
            String[] f = line.split(" ");
            if (line.startsWith("container ")) {
                container = f[4];
            } else if (line.startsWith("component ")) {
                assertNull(containerOf.put(f[4], container), "node " + f[4] + " in two containers: " + composed);
            } else if (line.startsWith("prefix ")) {
                assertNull(prefixes.put(f[1], line.substring(line.indexOf(' ', 7) + 1)), line);
            }
        }
        Map<String, String> nodesByModule = nodes(root);
        Map<Object, String> containerOfProcessor = new HashMap<>();
        Map<String, Object> processorOfContainer = new TreeMap<>();
        Set<String> pinned = new TreeSet<>();
        java.util.SortedSet<Integer> claimed = org.rsaml.generator.internal.cxx.OneMachineCpus.claimed(arch).get("");
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                String node = nodesByModule.get(key(m));
                Processor processor = arch.getProcessors().stream().filter(p -> p.getModules().contains(m)).findFirst().orElse(null);
                String c = containerOf.get(node);
                assertNotNull(c, "node " + node + " in no container: " + composed);
                Object domain = processor == null ? "default" : processor;
                String before = containerOfProcessor.putIfAbsent(domain, c);
                assertEquals(before == null ? c : before, c, "modules of one processor in different containers: " + composed);
                Object other = processorOfContainer.putIfAbsent(c, domain);
                assertEquals(other == null ? domain : other, domain, "modules of different processors in container " + c);
                if (processor == null) {
                    assertEquals(arch.getProcessors().isEmpty() ? pkg + "_container" : c, c,
                            "a node without a processor runs in the package's one container");
                }
                if (processor != null && processor.getCore() >= 0) {
                    for (String process : List.of(c, node)) {
                        assertNotNull(prefixes.get(process), "process " + process + " of processor " + processor.getName() + " is not pinned");
                        assertRunsOn(root, prefixes.get(process), processor.getCore());
                        pinned.add(process);
                    }
                }
                if ((processor == null || processor.getCore() < 0) && !claimed.isEmpty()) {
                    for (String process : List.of(c, node)) {
                        assertNotNull(prefixes.get(process), "process " + process + " of a module without a core is not kept off the claimed CPUs "
                                + claimed);
                        assertRunsOff(root, prefixes.get(process), claimed, process);
                        pinned.add(process);
                    }
                }
            }
        }
        assertEquals(pinned, prefixes.keySet(), "processes pinned that the model does not pin");
    }

    private static final String AFFINITY = "import os; print(sorted(os.sched_getaffinity(0)))";

    /**
     * Runs a command under a launch prefix as launch does (split as a shell would, the command
     * appended) and checks where it runs: on the core alone, or, on a machine without that core,
     * where it would have run anyway, with a line that says so.
     */
    private static void assertRunsOn(Path dir, String prefix, int core) throws Exception {
        String everywhere = Tools.ok(dir, 60, "python3", "-c", AFFINITY).strip();
        String ran = Tools.ok(dir, 60, "python3", "-c", "import shlex, subprocess, sys\n"
                + "sys.exit(subprocess.call(shlex.split(sys.argv[1]) + sys.argv[2:]))", prefix, "python3", "-c", AFFINITY).strip();
        List<String> lines = ran.lines().toList();
        String where = lines.get(lines.size() - 1);
        if (everywhere.matches(".*\\b" + core + "\\b.*")) {
            assertEquals("[" + core + "]", where, ran);
        } else {
            assertEquals(everywhere, where, ran);
            assertTrue(ran.contains("RsaML: CPU core " + core + " not available: python3 runs unpinned"), ran);
        }
    }

    /**
     * Runs a command under the launch prefix of process {@code process} of a processor without a core and checks where
     * it runs: on the CPUs this machine gives it that {@code claimed} leaves, saying so; where it leaves none, where it
     * would have run anyway, saying that.
     */
    private static void assertRunsOff(Path dir, String prefix, java.util.SortedSet<Integer> claimed, String process) throws Exception {
        String everywhere = Tools.ok(dir, 60, "python3", "-c", AFFINITY).strip();
        List<Integer> left = java.util.Arrays.stream(everywhere.replaceAll("[\\[\\] ]", "").split(",")).map(Integer::valueOf)
                .filter(c -> !claimed.contains(c)).toList();
        String ran = Tools.ok(dir, 60, "python3", "-c", "import shlex, subprocess, sys\n"
                + "sys.exit(subprocess.call(shlex.split(sys.argv[1]) + sys.argv[2:]))", prefix, "python3", "-c", AFFINITY).strip();
        List<String> lines = ran.lines().toList();
        String where = lines.get(lines.size() - 1);
        if (left.isEmpty()) {
            assertEquals(everywhere, where, ran);
            assertTrue(ran.contains("RsaML: cpu " + process + " no unclaimed core: default"), ran);
        } else {
            assertEquals(left.toString(), where, ran);
            assertTrue(ran.matches("(?s).*RsaML: cpu " + java.util.regex.Pattern.quote(process) + " cores [0-9,-]+ unclaimed\\b.*"), ran);
        }
    }

    /** What a launch file of the package in {@code root} starts, its parameters file read from root/config/. */
    private static String launch(Path dir, Path file) throws Exception {
        Tools.ok(dir, 60, Ros2Build.python(), "-m", "py_compile", file.toString());
        Tools.Result r = launch(file);
        assertEquals(0, r.exit(), () -> file + " failed:\n" + Tools.last(r.output(), 6000));
        return r.output();
    }

    /**
     * What a launch file of the package in {@code root} starts given the launch {@code arguments}
     * (NAME:=VALUE), its parameters file read from root/config/ unless params_file:= names another.
     */
    static Tools.Result launch(Path file, String... arguments) throws Exception {
        Path root = file.getParent().getParent();
        List<String> command = new ArrayList<>(List.of(Ros2Build.python(), "-c", LAUNCH, file.toString(), Tools.resource("ros2-stubs/python").toString(),
                root.getFileName().toString(), root.toString()));
        command.addAll(List.of(arguments));
        return Tools.run(root, 60, command.toArray(String[]::new));
    }

    static String key(Module m) {
        return m.getLayer().getName() + "/" + m.getName();
    }

    private static final Pattern NODE = Pattern.compile("\\* Node (\\w+): module (.+?)(?:: .*)?$", Pattern.MULTILINE);

    /** Node name of each module (layer/module, the model's names), as its generated base class says. */
    static Map<String, String> nodes(Path root) throws Exception {
        Map<String, String> nodes = new TreeMap<>();
        for (Path p : bases(root)) {
            Matcher m = NODE.matcher(Files.readString(p));
            assertTrue(m.find(), p.toString());
            nodes.put(m.group(2), m.group(1));
        }
        return nodes;
    }

    /** The generated base classes of the nodes under root: a package, or a workspace of packages (any package layout). */
    private static List<Path> bases(Path root) throws Exception {
        try (Stream<Path> s = Files.walk(root)) {
            return s.filter(f -> f.toString().endsWith("Base.hpp") && f.getParent().getParent().getFileName().toString().equals("gen"))
                    .sorted().toList();
        }
    }

    /** Topic of each publisher and subscription member, by module (layer/module, the model's names). */
    private static Map<String, String> topics(Path root) throws Exception {
        return members(root, 2);
    }

    /** QoS of each publisher and subscription member, by module. */
    private static Map<String, String> qos(Path root) throws Exception {
        return members(root, 3);
    }

    private static Map<String, String> members(Path root, int group) throws Exception {
        Map<String, String> found = new TreeMap<>();
        Pattern member = Pattern.compile("(\\w+)_ = this->create_(?:publisher|subscription)<[^>]+>\\(\\s*\"([^\"]+)\", (rclcpp::[^,]+),");
        for (Path p : bases(root)) {
            String text = Files.readString(p);
            Matcher c = NODE.matcher(text);
            assertTrue(c.find(), "the node class is declared in the header");
            Matcher m = member.matcher(text);
            while (m.find()) {
                found.put(c.group(2) + "/" + m.group(1), m.group(group));
            }
        }
        return found;
    }
}
