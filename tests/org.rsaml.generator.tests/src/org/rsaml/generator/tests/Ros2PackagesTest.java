/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.GenerationException;
import org.rsaml.generator.GenerationRefusedException;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * The package layouts of the ROS 2 target (Architecture.packages), on the mobile base of
 * examples/mobile-base-latency.rsaml (layers navigation and control, processors core1 and core0, a
 * message type of its own used by the control layer's odometry): with {@code perLayer} or
 * {@code perProcessor} each package of nodes holds exactly its modules (their generated code, the
 * architect's classes, a CMakeLists.txt registering their components) and depends on what they use;
 * the runtime package holds the scheduling runtime, the container and the lifecycle manager; the
 * package named after the architecture the launch files and the parameters file, and the launch
 * files start each node from its package. Every manifest is REP 149 format 3, read by catkin_pkg.
 * Changing the layout of an output refuses to leave the architect's code behind and says what to
 * move. {@link Ros2LayoutLaunchTest} builds and runs the layouts on ROS 2.
 */
class Ros2PackagesTest {

    static final String MODEL = "mobile-base-latency.rsaml";
    static final String PKG = "mobile_base";

    /** The mobile base with the given layout (and the text replacements), written into dir. */
    static Path model(Path dir, String layout, String... replacements) throws Exception {
        String text = Files.readString(Tools.example(MODEL)).replace("declaredLayers=\"2\"", "declaredLayers=\"2\" packages=\"" + layout + "\"");
        for (int i = 0; i < replacements.length; i += 2) {
            assertTrue(text.contains(replacements[i]), "the example has no " + replacements[i]);
            text = text.replace(replacements[i], replacements[i + 1]);
        }
        Path model = dir.resolve("mobile-base-" + layout + ".rsaml");
        Files.writeString(model, text);
        return model;
    }

    /** Every package of an output, with its files (relative to the package). */
    private static Map<String, List<String>> packages(Path out) throws Exception {
        Map<String, List<String>> packages = new TreeMap<>();
        try (Stream<Path> s = Files.list(out)) {
            for (Path p : s.filter(Files::isDirectory).toList()) {
                try (Stream<Path> files = Files.walk(p)) {
                    packages.put(p.getFileName().toString(), files.filter(Files::isRegularFile).map(f -> p.relativize(f).toString()).sorted().toList());
                }
            }
        }
        return packages;
    }

    /** What catkin_pkg reads of a manifest: its name, then "depend NAME" and "exec NAME" lines, sorted. */
    private static String parsed(Path manifest) throws Exception {
        Ros2Build.validateManifest(manifest);
        return Tools.ok(manifest.getParent(), 60, Ros2Build.python(), "-c", "import sys\nfrom catkin_pkg.package import parse_package\n"
                + "p = parse_package(sys.argv[1])\nprint(p.name)\n"
                + "print('\\n'.join(sorted(['build ' + d.name for d in p.build_depends] + ['exec ' + d.name for d in p.exec_depends])))",
                manifest.toString()).strip();
    }

    private static void nodePackage(Map<String, List<String>> packages, Path out, String pkg, String layer, List<String> classes,
            List<String> messagePackages) throws Exception {
        List<String> files = packages.get(pkg);
        assertTrue(files != null, "no package " + pkg + " among " + packages.keySet());
        for (String c : classes) {
            for (String f : List.of("gen/" + layer + "/" + c + "Base.hpp", "gen/" + layer + "/" + c + "Component.cpp", "src/" + layer + "/" + c + ".hpp",
                    "src/" + layer + "/" + c + ".cpp")) {
                assertTrue(files.contains(f), pkg + " lacks " + f + ": " + files);
            }
        }
        assertEquals(classes.size(), files.stream().filter(f -> f.endsWith("Base.hpp")).count(), pkg + " holds other nodes than " + classes + ": " + files);
        assertFalse(files.stream().anyMatch(f -> f.startsWith("launch/") || f.startsWith("config/") || f.startsWith("gen/rsaml/")),
                pkg + " holds launch files, parameters or the runtime: " + files);
        String cmake = Files.readString(out.resolve(pkg + "/CMakeLists.txt"));
        assertTrue(cmake.contains("project(" + pkg + " LANGUAGES CXX)") && cmake.contains("find_package(" + PKG + "_runtime REQUIRED)")
                && cmake.contains("PUBLIC " + PKG + "_runtime::" + PKG + "_runtime"), pkg + " builds on the runtime package:\n" + cmake);
        for (String c : classes) {
            assertTrue(cmake.contains("\"" + PKG + "::" + layer + "::" + c + "\""), pkg + " registers the component of " + c + ":\n" + cmake);
        }
        String manifest = parsed(out.resolve(pkg + "/package.xml"));
        assertTrue(manifest.startsWith(pkg + "\n"), manifest);
        List<String> depends = manifest.lines().filter(l -> l.startsWith("build ")).map(l -> l.substring(6)).toList();
        List<String> expected = new java.util.ArrayList<>(List.of("rclcpp", "rclcpp_components", PKG + "_runtime"));
        expected.addAll(messagePackages);
        assertEquals(expected.stream().sorted().toList(), depends, pkg + " depends on what its nodes use and on no other package of nodes");
    }

    @Test
    void perLayerGivesEachLayerAPackageOfItsNodes(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model(tmp, "perLayer"), Target.ROS2, out, false);
        Map<String, List<String>> packages = packages(out);
        assertEquals(List.of(PKG, PKG + "_control", PKG + "_interfaces", PKG + "_navigation", PKG + "_runtime"), List.copyOf(packages.keySet()),
                "the packages: the launch files', one per layer, the messages', the runtime's");
        nodePackage(packages, out, PKG + "_navigation", "navigation", List.of("ObstacleDetector", "PathPlanner"), List.of("std_msgs"));
        nodePackage(packages, out, PKG + "_control", "control", List.of("VelocityController", "Odometry"), List.of(PKG + "_interfaces", "std_msgs"));
        assertEquals(List.of("CMakeLists.txt", "config/" + PKG + ".params.yaml", "launch/" + PKG + ".launch.py", "launch/" + PKG + "_processes.launch.py",
                "package.user.xml", "package.xml", "user.cmake"), packages.get(PKG).stream().filter(f -> !f.startsWith("test/")).toList(),
                "the package named after the architecture holds the launch files and the parameters file");
        String system = parsed(out.resolve(PKG + "/package.xml"));
        for (String p : List.of(PKG + "_control", PKG + "_navigation", PKG + "_runtime", "launch_ros", "ros2launch")) {
            assertTrue(system.contains("\nexec " + p + "\n") || system.endsWith("\nexec " + p), "the launch files need " + p + " at run time:\n" + system);
        }
        assertTrue(packages.get(PKG + "_runtime").containsAll(List.of("gen/rsaml/scheduling.cpp", "gen/rsaml/scheduling.hpp", "gen/rsaml/container.cpp",
                "gen/rsaml/realtime.hpp")), "the runtime package holds the scheduling runtime and the container: " + packages.get(PKG + "_runtime"));
        String runtime = Files.readString(out.resolve(PKG + "_runtime/CMakeLists.txt"));
        assertTrue(runtime.contains("ament_export_targets(export_${PROJECT_NAME} HAS_LIBRARY_TARGET)")
                && runtime.contains("add_executable(" + PKG + "_component_container gen/rsaml/container.cpp)"),
                "the runtime exports its library (one per process, shared by every package's nodes) and builds the container:\n" + runtime);
        assertTrue(parsed(out.resolve(PKG + "_runtime/package.xml")).startsWith(PKG + "_runtime\n"), "the runtime's manifest");
        String launch = Files.readString(out.resolve(PKG + "/launch/" + PKG + ".launch.py"));
        assertTrue(launch.matches("(?s).*package='" + PKG + "_runtime',\\s+executable='" + PKG + "_component_container'.*")
                && !launch.contains("package='" + PKG + "'"), "the containers are the runtime package's:\n" + launch);
        assertTrue(launch.contains("ComposableNode(package='" + PKG + "_navigation', plugin='" + PKG + "::navigation::ObstacleDetector'")
                && launch.contains("ComposableNode(package='" + PKG + "_control', plugin='" + PKG + "::control::Odometry'"),
                "each component is loaded from its package:\n" + launch);
        String processes = Files.readString(out.resolve(PKG + "/launch/" + PKG + "_processes.launch.py"));
        assertTrue(processes.contains("Node(package='" + PKG + "_navigation', executable='navigation_path_planner'")
                && processes.contains("Node(package='" + PKG + "_control', executable='control_velocity_controller'"),
                "each node's executable is started from its package:\n" + processes);
    }

    @Test
    void perProcessorGivesEachProcessorAPackageAndTheUnallocatedModulesOneOfTheirOwn(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        // the odometry allocated to no processor: it runs on the default processor, in the package ending _default
        Path model = model(tmp, "perProcessor", " //@layers[name='control']/@modules[name='odometry']\"/>", "\"/>");
        new RsamlGenerator().generate(model, Target.ROS2, out, false);
        Map<String, List<String>> packages = packages(out);
        assertEquals(List.of(PKG, PKG + "_core0", PKG + "_core1", PKG + "_default", PKG + "_interfaces", PKG + "_runtime"),
                List.copyOf(packages.keySet()), "a package per processor with modules, and one for the module no processor names");
        nodePackage(packages, out, PKG + "_core1", "navigation", List.of("ObstacleDetector", "PathPlanner"), List.of("std_msgs"));
        nodePackage(packages, out, PKG + "_core0", "control", List.of("VelocityController"), List.of("std_msgs"));
        nodePackage(packages, out, PKG + "_default", "control", List.of("Odometry"), List.of(PKG + "_interfaces"));
        String launch = Files.readString(out.resolve(PKG + "/launch/" + PKG + ".launch.py"));
        assertTrue(launch.contains("ComposableNode(package='" + PKG + "_default', plugin='" + PKG + "::control::Odometry'"),
                "the odometry is loaded from the default package:\n" + launch);
    }

    @Test
    void aProcessorWhosePackageWouldBeTheDefaultOneIsRefusedWithItsFinding(@TempDir Path tmp) throws Exception {
        Path model = model(tmp, "perProcessor", "<processors name=\"core0\"", "<processors name=\"Default\"");
        GenerationRefusedException e = assertThrows(GenerationRefusedException.class,
                () -> new RsamlGenerator().generate(model, Target.ROS2, tmp.resolve("ws"), false));
        assertEquals(List.of("RSA-29 mobileBase/Default"), e.errors().stream().map(f -> f.ruleId() + " " + f.qualifiedName()).toList(),
                "the processor named Default is found: " + e.errors());
        assertTrue(e.errors().get(0).message().contains("the package of the modules no processor names"), e.errors().get(0).message());
        assertFalse(Files.exists(tmp.resolve("ws")), "nothing is written");
    }

    /**
     * From one package to a package per layer: the architect's classes are in mobile_base/src/, where
     * the new layout does not look. Generating refuses, writes nothing and lists each move; once the
     * files are moved as it says, it generates, keeps them (still the architect's) and removes the
     * regenerated files of the old layout.
     */
    @Test
    void changingTheLayoutNeverLeavesTheArchitectsCodeBehind(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model(tmp, "single"), Target.ROS2, out, false);
        Path mine = out.resolve(PKG + "/src/navigation/ObstacleDetector.cpp");
        Files.writeString(mine, Files.readString(mine) + "\n// the detection of mine\n");
        Map<String, byte[]> before = Tools.snapshot(out);
        Path layered = model(tmp, "perLayer");
        GenerationException e = assertThrows(GenerationException.class, () -> new RsamlGenerator().generate(layered, Target.ROS2, out, false));
        String message = e.toString();
        for (String c : List.of("navigation/ObstacleDetector", "navigation/PathPlanner", "control/VelocityController", "control/Odometry")) {
            String layer = c.substring(0, c.indexOf('/'));
            for (String ext : List.of(".hpp", ".cpp")) {
                assertTrue(message.contains(PKG + "/src/" + c + ext + " -> " + PKG + "_" + layer + "/src/" + c + ext), "the move of " + c + ext
                        + " is said: " + message);
            }
        }
        assertTrue(message.contains("packages perLayer") && message.contains("set packages back to single"), message);
        assertTrue(Tools.sameFiles(before, Tools.snapshot(out)), "the refused generation changed the output");

        for (String move : message.substring(message.indexOf("): ") + 3).split(" \\(and what")[0].split(", ")) {
            Path from = out.resolve(move.split(" -> ")[0]);
            Path to = out.resolve(move.split(" -> ")[1]);
            Files.createDirectories(to.getParent());
            Files.move(from, to);
        }
        new RsamlGenerator().generate(layered, Target.ROS2, out, false);
        Path moved = out.resolve(PKG + "_navigation/src/navigation/ObstacleDetector.cpp");
        assertTrue(Files.readString(moved).endsWith("// the detection of mine\n"), "the architect's code is kept where it was moved");
        assertFalse(Files.exists(out.resolve(PKG + "/gen/navigation/ObstacleDetectorBase.hpp")), "the old layout's generated node is removed from " + PKG);
        assertFalse(Files.readString(out.resolve(PKG + "/CMakeLists.txt")).contains("add_library"), PKG + " builds no nodes any more");
        assertTrue(Files.exists(out.resolve(PKG + "_navigation/gen/navigation/ObstacleDetectorBase.hpp")), "the nodes are generated in their package");
    }
}
