/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
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
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.validation.ModelLoader;

/**
 * What can be checked of the ROS 2 target here: package.xml is valid against the REP 149 format 3
 * schema and parses with catkin_pkg; every package configures, builds and installs with the real
 * ament_cmake and rosidl (see {@link Ros2Build}), warnings as errors; the launch file compiles and,
 * run against stand-in launch modules, starts one node per module in its layer's namespace;
 * connected ports share a topic; every periodic function has a timer. rclcpp itself is a stand-in:
 * the nodes are compiled and linked, not run.
 */
class Ros2Test {

    static List<String> models() throws Exception {
        List<String> models = new ArrayList<>(Tools.cleanExamples());
        models.add("resources/names-hostile.rsaml");
        return models;
    }

    static Path model(String name) {
        return name.startsWith("resources/") ? Tools.resource(name.substring(10)) : Tools.example(name);
    }

    @ParameterizedTest
    @MethodSource("models")
    void packagesAreWellFormedAndCompileAgainstRclcppDeclarations(String name, @TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model(name), Target.ROS2, out, false);
        Architecture arch = ModelLoader.load(model(name), name).architecture();
        String pkg = Names.snake(arch.getName());
        Path root = out.resolve(pkg);

        // package.xml (format 3), read by catkin_pkg as colcon would.
        List<Path> manifests;
        try (Stream<Path> s = Files.list(out)) {
            manifests = s.map(p -> p.resolve("package.xml")).filter(Files::exists).sorted().toList();
        }
        for (Path manifest : manifests) {
            Ros2Build.validateManifest(manifest);
            String parsed = Tools.ok(out, 60, "python3", "-c", "import sys\nfrom catkin_pkg.package import parse_package\n"
                    + "p = parse_package(sys.argv[1])\nprint(p.package_format, p.name, ' '.join(sorted(d.name for d in p.build_depends)))", manifest.toString());
            assertTrue(parsed.startsWith("3 " + manifest.getParent().getFileName()), parsed);
            if (manifest.getParent().equals(root)) {
                assertTrue(parsed.contains("rclcpp"), parsed);
            }
        }

        // The launch file: compiles, and starts exactly the modules, each in its layer's namespace.
        Path launch = root.resolve("launch/" + pkg + ".launch.py");
        Tools.ok(out, 60, "python3", "-m", "py_compile", launch.toString());
        String nodes = Tools.ok(out, 60, "python3", "-c", "import importlib.util, sys\nsys.dont_write_bytecode = True\nsys.path.insert(0, sys.argv[2])\n"
                + "spec = importlib.util.spec_from_file_location('l', sys.argv[1]); m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n"
                + "for n in m.generate_launch_description().entities: print(n.package, n.executable, n.namespace, n.name)",
                launch.toString(), Tools.resource("ros2-stubs/python").toString());
        List<String> started = nodes.lines().toList();
        int modules = arch.getLayers().stream().mapToInt(l -> l.getModules().size()).sum();
        assertEquals(modules, started.size(), nodes);
        String cmake = Files.readString(root.resolve("CMakeLists.txt"));
        for (String node : started) {
            String[] f = node.split(" ");
            assertEquals(pkg, f[0]);
            assertTrue(cmake.contains("add_executable(" + f[1] + " "), "no executable " + f[1] + " in CMakeLists.txt");
        }
        // Each module has its node, and all modules of a layer share a namespace of their own.
        Map<String, String[]> nodesByModule = nodes(root);
        Map<String, String> namespaceOfLayer = new TreeMap<>();
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                String[] node = nodesByModule.get(layer.getName() + "/" + m.getName());
                assertTrue(node != null, "no node for module " + layer.getName() + "/" + m.getName());
                assertTrue(started.contains(pkg + " " + executable(cmake, node) + " " + node[0] + " " + node[1]),
                        "the launch file does not start " + node[0] + "/" + node[1] + ": " + started);
                String ns = namespaceOfLayer.putIfAbsent(layer.getName(), node[0]);
                assertTrue(ns == null || ns.equals(node[0]), "layer " + layer.getName() + " spans namespaces");
            }
        }
        assertEquals(arch.getLayers().size(), new TreeSet<>(namespaceOfLayer.values()).size(), "layers share a namespace");

        // Every package builds as colcon would: the real rosidl generates each .msg, and the nodes
        // compile against those headers and the stand-in rclcpp, warnings as errors.
        Ros2Build.buildAll(out, tmp.resolve("colcon"));

        // Connected ports share one topic: the source's publisher and the target's subscription.
        Map<String, String> topics = topics(root);
        for (Connection c : arch.getConnections()) {
            String pub = topics.get(key(c.getSource().getModule()) + "/pub_" + Names.stem(c.getSource().getName()));
            String sub = topics.get(key(c.getTarget().getModule()) + "/sub_" + Names.stem(c.getTarget().getName()));
            assertTrue(pub != null && pub.equals(sub), c.getSource().getName() + " publishes on " + pub + ", "
                    + c.getTarget().getName() + " listens on " + sub);
        }
        // A timer per periodic function, at its period.
        String all = allText(root.resolve("gen"));
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                for (Function f : m.getFunctions()) {
                    if (f.getExecType() == ExecutionType.PERIODIC && f.getPeriod() > 0) {
                        long ns = Math.round(f.getPeriod() * f.getTimeUnit().getValue());
                        assertTrue(all.contains("create_wall_timer(std::chrono::nanoseconds(" + ns + "), [this] { release_"
                                + Names.stem(f.getName())), "no timer for " + f.getName());
                    }
                }
            }
        }
    }

    private static String key(Module m) {
        return m.getLayer().getName() + "/" + m.getName();
    }

    private static final Pattern NODE = Pattern.compile("\\* Node (\\w+) in namespace /(\\w+): module (.+?)(?:: .*)?$", Pattern.MULTILINE);

    /** Namespace and node name of each module, as its generated base class says (the model's names). */
    private static Map<String, String[]> nodes(Path root) throws Exception {
        Map<String, String[]> nodes = new TreeMap<>();
        try (Stream<Path> s = Files.walk(root.resolve("gen"))) {
            for (Path p : s.filter(f -> f.toString().endsWith("Base.hpp")).toList()) {
                Matcher m = NODE.matcher(Files.readString(p));
                assertTrue(m.find(), p.toString());
                nodes.put(m.group(3), new String[] { m.group(2), m.group(1), p.getFileName().toString().replace("Base.hpp", "") });
            }
        }
        return nodes;
    }

    /** The executable whose main file is the node's. */
    private static String executable(String cmake, String[] node) {
        Matcher m = Pattern.compile("add_executable\\((\\w+) gen/\\w+/" + Pattern.quote(node[2]) + "Main\\.cpp").matcher(cmake);
        assertTrue(m.find(), "no executable for " + node[2]);
        return m.group(1);
    }

    /** Topic of each publisher and subscription member, by module (layer/module, the model's names). */
    private static Map<String, String> topics(Path root) throws Exception {
        Map<String, String> topics = new TreeMap<>();
        Pattern member = Pattern.compile("(\\w+)_ = this->create_(?:publisher|subscription)<[^>]+>\\(\\s*\"([^\"]+)\"");
        try (Stream<Path> s = Files.walk(root.resolve("gen"))) {
            for (Path p : s.filter(f -> f.toString().endsWith("Base.hpp")).toList()) {
                String text = Files.readString(p);
                Matcher c = NODE.matcher(text);
                assertTrue(c.find());
                Matcher m = member.matcher(text);
                while (m.find()) {
                    topics.put(c.group(3) + "/" + m.group(1), m.group(2));
                }
            }
        }
        return topics;
    }

    private static String allText(Path dir) throws Exception {
        StringBuilder sb = new StringBuilder();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.filter(f -> f.toString().endsWith(".hpp") || f.toString().endsWith(".cpp")).sorted().toList()) {
                sb.append(Files.readString(p)).append('\n');
            }
        }
        return sb.toString();
    }
}
