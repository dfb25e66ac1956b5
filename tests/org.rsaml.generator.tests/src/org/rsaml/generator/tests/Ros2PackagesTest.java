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
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.ros2.Ros2Shutdown;

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
        assertEquals(List.of("CMakeLists.txt", "config/" + PKG + ".params.yaml", "gen/" + PKG + ".params.yaml", "launch/" + PKG + ".launch.py", "launch/" + PKG + "_processes.launch.py",
                "package.user.xml", "package.xml", "user.cmake"), packages.get(PKG).stream().filter(f -> !f.startsWith("test/")).toList(),
                "the package named after the architecture holds the launch files and the parameters file");
        String system = parsed(out.resolve(PKG + "/package.xml"));
        for (String p : List.of(PKG + "_control", PKG + "_navigation", PKG + "_runtime", "launch_ros", "ros2launch")) {
            assertTrue(system.contains("\nexec " + p + "\n") || system.endsWith("\nexec " + p), "the launch files need " + p + " at run time:\n" + system);
        }
        assertTrue(packages.get(PKG + "_runtime").containsAll(List.of("gen/rsaml/scheduling.cpp", "gen/rsaml/scheduling.hpp", "gen/rsaml/container.cpp",
                "gen/rsaml/realtime.hpp", "gen/rsaml/jobs.hpp")), "the runtime package holds the scheduling runtime and the container: " + packages.get(PKG + "_runtime"));
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

    /**
     * With a package per layer or per processor, each package of nodes has a launch test of its own
     * (test/test_<package>_launch.py, valid Python, run by colcon test under BUILD_TESTING): it starts
     * that package's executables alone and waits for a message of a timed node of the package on its
     * topic, with its type (managed nodes brought to active by the runtime package's lifecycle manager); a package none
     * of whose timed nodes publishes says so in the test's docstring.
     */
    @Test
    void eachPackageOfNodesHasALaunchTestOfItsOwnNodesAndOneOfTheirMessages(@TempDir Path tmp) throws Exception {
        String pose = "<ports xsi:type=\"rsaml:OutputPort\" name=\"pose\" description=\"The base's pose.\" dataType=\"structured\""
                + " messageType=\"Pose2D\"/>";
        for (String layout : List.of("perLayer", "perProcessor")) {
            // perLayer: odometry without its pose, so that no timed node of control publishes; perProcessor: managed nodes.
            Path model = layout.equals("perLayer") ? model(tmp, layout, pose, "")
                    : model(tmp, layout, "declaredLayers=\"2\"", "declaredLayers=\"2\" lifecycle=\"managed\"");
            Path out = tmp.resolve("ws-" + layout);
            new RsamlGenerator().generate(model, Target.ROS2, out, false);
            String navigation = PKG + (layout.equals("perLayer") ? "_navigation" : "_core1");
            String control = PKG + (layout.equals("perLayer") ? "_control" : "_core0");
            Map<String, String> tests = new TreeMap<>();
            for (String np : List.of(navigation, control)) {
                String path = "test/test_" + np + "_launch.py";
                Path test = out.resolve(np).resolve(path);
                assertTrue(Files.isRegularFile(test), layout + ": package " + np + " has its launch test " + path);
                Tools.Result compiled = Tools.run(tmp, 60, "/usr/bin/python3", "-m", "py_compile", test.toString());
                assertEquals(0, compiled.exit(), () -> layout + ": " + path + " is not valid Python:\n" + compiled.output());
                String cmake = Files.readString(out.resolve(np + "/CMakeLists.txt"));
                assertTrue(cmake.contains("add_launch_test(" + path + " TIMEOUT 120)"), layout + ": colcon test runs it:\n" + cmake);
                Ros2Build.validateManifest(out.resolve(np + "/package.xml"));
                String manifest = Files.readString(out.resolve(np + "/package.xml"));
                assertTrue(List.of("launch_testing", "launch_testing_ament_cmake", "launch_ros", "rclpy").stream()
                        .allMatch(d -> manifest.contains("<test_depend>" + d + "</test_depend>")),
                        layout + ": the package's manifest names what the test needs:\n" + manifest);
                tests.put(np, Files.readString(test));
            }
            String nav = tests.get(navigation);
            assertTrue(nav.contains("Node(package='" + navigation + "', executable='navigation_obstacle_detector', name='navigation_obstacle_detector'")
                    && nav.contains("Node(package='" + navigation + "', executable='navigation_path_planner', name='navigation_path_planner'")
                    && !nav.contains("executable='control_"), layout + ": the navigation package's test starts its two nodes, and only those:\n" + nav);
            assertTrue(nav.contains("from std_msgs.msg import Float64") && nav.contains("TOPIC = 'speed_limit'")
                    && nav.contains("create_subscription(Float64, TOPIC,"), layout + ": and waits for the obstacle detector's speed limit (the"
                    + " first output of a timed node), a std_msgs/msg/Float64 on the topic the model names:\n" + nav);
            String ctl = tests.get(control);
            assertTrue(ctl.contains("executable='control_velocity_controller'") && ctl.contains("executable='control_odometry'")
                    && !ctl.contains("executable='navigation_"), layout + ": the control package's test starts its two nodes, and only those:\n" + ctl);
            if (layout.equals("perLayer")) {
                assertTrue(ctl.contains("No node of this package publishes on its own") && !ctl.contains("TOPIC"),
                        "a package whose timed nodes publish nothing says so, and waits for no message:\n" + ctl);
            } else {
                assertTrue(ctl.contains("from " + PKG + "_interfaces.msg import Pose2D") && ctl.contains("TOPIC = 'control/odometry/pose'"),
                        "the odometry's pose, a message of the interfaces package, on its default topic:\n" + ctl);
                String grace = "arguments=['" + Ros2Shutdown.GRACE_OPTION + "=" + Ros2Shutdown.graceMs(2) + "'], sigterm_timeout='"
                        + Ros2Shutdown.sigtermTimeoutS(2) + "'";
                assertTrue(ctl.contains("Node(package='" + PKG + "_runtime', executable='" + PKG + "_lifecycle_manager'")
                        && ctl.contains("'node_names': ['control_velocity_controller', 'control_odometry']")
                        && ctl.split(java.util.regex.Pattern.quote(grace), -1).length == 3,
                        "managed nodes: the runtime package's lifecycle manager brings the package's two to active, and each process"
                        + " is given the grace of two nodes:\n" + ctl);
            }
        }
    }

    @Test
    void aProcessorWhosePackageWouldBeTheDefaultOneIsRefusedWithItsFinding(@TempDir Path tmp) throws Exception {
        Path model = model(tmp, "perProcessor", "<processors name=\"core0\"", "<processors name=\"Default\"");
        GenerationRefusedException e = assertThrows(GenerationRefusedException.class,
                () -> new RsamlGenerator().generate(model, Target.ROS2, tmp.resolve("ws"), false),
                "a processor whose package would be the default one is refused");
        assertEquals(List.of("RSA-29 mobileBase/Default"), e.errors().stream().map(f -> f.ruleId() + " " + f.qualifiedName()).toList(),
                "the processor named Default is found: " + e.errors());
        assertTrue(e.errors().get(0).message().contains("the package of the modules no processor names"), e.errors().get(0).message());
        assertFalse(Files.exists(tmp.resolve("ws")), "nothing is written");
    }

    /** Moves each file the refusal says to move ("Move each ...: A -> B, C -> D."). */
    private static void moveAsSaid(Path out, String message) throws Exception {
        String marker = "(paths in the output directory): ";
        assertTrue(message.contains(marker), "the refusal lists the files to move: " + message);
        String list = message.substring(message.indexOf(marker) + marker.length());
        for (String move : list.substring(0, list.indexOf(". ")).split(", ")) {
            Path from = out.resolve(move.split(" -> ")[0]);
            Path to = out.resolve(move.split(" -> ")[1]);
            Files.createDirectories(to.getParent());
            Files.move(from, to);
        }
    }

    private static void append(Path file, String text) throws Exception {
        Files.writeString(file, Files.readString(file) + text);
    }

    /**
     * From one package to a package per layer: the architect's classes are in mobile_base/src/, where
     * the new layout does not look. Generating refuses, writes nothing and lists each move, and says
     * that what mobile_base's user.cmake and package.user.xml add (for every node, with single) now
     * belongs to the packages of the nodes; once the classes are moved as it says, it generates,
     * keeps them (still the architect's) and removes the regenerated files of the old layout, warns
     * once more about those two files, and keeps the parameters file with the architect's edit (the
     * launch package's in every layout, still loaded by both launch files) and the README.
     */
    @Test
    void changingTheLayoutNeverLeavesTheArchitectsCodeBehind(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model(tmp, "single"), Target.ROS2, out, false);
        Path mine = out.resolve(PKG + "/src/navigation/ObstacleDetector.cpp");
        append(mine, "\n// the detection of mine\n");
        append(out.resolve(PKG + "/user.cmake"), "find_package(tf2_ros REQUIRED)\n");
        Path manifest = out.resolve(PKG + "/package.user.xml");
        Files.writeString(manifest, Files.readString(manifest).replace("<!-- <depend>tf2_ros</depend> -->", "<depend>tf2_ros</depend>"));
        Path params = out.resolve(PKG + "/config/" + PKG + ".params.yaml");
        append(params, "# tuned on the robot\n");
        append(out.resolve("README.md"), "\nOur notes.\n");
        Map<String, byte[]> before = Tools.snapshot(out);
        Path layered = model(tmp, "perLayer");
        GenerationException e = assertThrows(GenerationException.class, () -> new RsamlGenerator().generate(layered, Target.ROS2, out, false), "moving from one package per layer needs the architect's files moved");
        String message = e.toString();
        for (String c : List.of("navigation/ObstacleDetector", "navigation/PathPlanner", "control/VelocityController", "control/Odometry")) {
            String layer = c.substring(0, c.indexOf('/'));
            for (String ext : List.of(".hpp", ".cpp")) {
                assertTrue(message.contains(PKG + "/src/" + c + ext + " -> " + PKG + "_" + layer + "/src/" + c + ext), "the move of " + c + ext
                        + " is said: " + message);
            }
        }
        for (String file : List.of("user.cmake", "package.user.xml")) {
            String said = "what " + PKG + "/" + file + " adds for the nodes now built elsewhere goes into ";
            String into = message.substring(message.indexOf(said) + said.length()).split("[;.] ")[0];
            assertTrue(message.contains(said) && into.contains(PKG + "_navigation/" + file) && into.contains(PKG + "_control/" + file),
                    "what " + file + " adds for the nodes is said to go to their packages: " + message);
        }
        assertTrue(message.contains("packages single (this output) to perLayer (the model)") && message.contains("set packages back to single"), message);
        assertTrue(Tools.sameFiles(before, Tools.snapshot(out)), "the refused generation changed the output");

        moveAsSaid(out, message);
        GenerationResult moved = new RsamlGenerator().generate(layered, Target.ROS2, out, false);
        assertTrue(Files.readString(out.resolve(PKG + "_navigation/src/navigation/ObstacleDetector.cpp")).endsWith("// the detection of mine\n"),
                "the architect's code is kept where it was moved");
        assertFalse(Files.exists(out.resolve(PKG + "/gen/navigation/ObstacleDetectorBase.hpp")), "the old layout's generated node is removed from " + PKG);
        assertFalse(Files.readString(out.resolve(PKG + "/CMakeLists.txt")).contains("add_library"), PKG + " builds no nodes any more");
        assertTrue(Files.exists(out.resolve(PKG + "_navigation/gen/navigation/ObstacleDetectorBase.hpp")), "the nodes are generated in their package");
        assertEquals(1, moved.warnings().stream().filter(w -> w.contains(PKG + "/user.cmake adds for the nodes")
                && w.contains(PKG + "/package.user.xml adds for the nodes")).count(), "the two files are named once more: " + moved.warnings());
        for (String kept : List.of(PKG + "/config/" + PKG + ".params.yaml", PKG + "/user.cmake", PKG + "/package.user.xml", "README.md")) {
            assertEquals(new String(before.get(kept)), Files.readString(out.resolve(kept)), kept + " is kept as the architect left it");
        }
        for (String launch : List.of(PKG + ".launch.py", PKG + "_processes.launch.py")) {
            assertTrue(Files.readString(out.resolve(PKG + "/launch/" + launch)).contains("'config', '" + PKG + ".params.yaml'"),
                    launch + " still loads the architect's parameters file");
        }
        assertEquals(List.of(), new RsamlGenerator().generate(layered, Target.ROS2, out, false).warnings().stream()
                .filter(w -> w.contains("layout changed")).toList(), "the layout change is said when it happens, not on every run");
    }

    /**
     * From a package per layer back to one package: the classes move, and the navigation package's
     * user.cmake and the runtime package's package.user.xml, which add something of the architect's,
     * would be left in packages that no longer exist; generating refuses and names each with the file
     * to merge it into. The control package's files, as RsaML created them, are not in the way; once
     * the rest is moved and merged, generating names them as left over, to delete.
     */
    @Test
    void backToOnePackageTheOldPackagesFilesOfTheArchitectsAreMergedNotLeftBehind(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model(tmp, "perLayer"), Target.ROS2, out, false);
        append(out.resolve(PKG + "_navigation/user.cmake"), "target_compile_definitions(${PROJECT_NAME} PRIVATE NAV_TUNED=1)\n");
        Path runtimeManifest = out.resolve(PKG + "_runtime/package.user.xml");
        Files.writeString(runtimeManifest, Files.readString(runtimeManifest).replace("<license>TODO</license>", "<license>Apache-2.0</license>"));
        Map<String, byte[]> before = Tools.snapshot(out);
        Path single = model(tmp, "single");
        GenerationException e = assertThrows(GenerationException.class, () -> new RsamlGenerator().generate(single, Target.ROS2, out, false), "moving to one package needs the architect's files moved");
        String message = e.toString();
        assertTrue(message.contains(PKG + "_navigation/src/navigation/PathPlanner.hpp -> " + PKG + "/src/navigation/PathPlanner.hpp"), message);
        assertTrue(message.contains(PKG + "_navigation/user.cmake into " + PKG + "/user.cmake")
                && message.contains(PKG + "_runtime/package.user.xml into " + PKG + "/package.user.xml"),
                "the files that add something are named with where they go: " + message);
        assertFalse(message.contains(PKG + "_control/user.cmake") || message.contains(PKG + "_navigation/package.user.xml"),
                "files as RsaML created them are not in the way: " + message);
        assertTrue(Tools.sameFiles(before, Tools.snapshot(out)), "the refused generation changed the output");

        moveAsSaid(out, message);
        append(out.resolve(PKG + "/user.cmake"), Files.readString(out.resolve(PKG + "_navigation/user.cmake")));
        Files.delete(out.resolve(PKG + "_navigation/user.cmake"));
        Files.move(runtimeManifest, out.resolve(PKG + "/package.user.xml"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        GenerationResult merged = new RsamlGenerator().generate(single, Target.ROS2, out, false);
        assertTrue(Files.readString(out.resolve(PKG + "/package.xml")).contains("<license>Apache-2.0</license>"), "the merged manifest is in effect");
        assertTrue(Files.readString(out.resolve(PKG + "/user.cmake")).contains("NAV_TUNED=1"), "the merged user.cmake is kept");
        List<String> leftOver = merged.warnings().stream().filter(w -> w.contains("left over")).toList();
        assertEquals(1, leftOver.size(), "the unused files are named: " + merged.warnings());
        for (String f : List.of(PKG + "_control/user.cmake", PKG + "_control/package.user.xml", PKG + "_navigation/package.user.xml")) {
            assertTrue(leftOver.get(0).contains(f), f + " is named as left over: " + leftOver);
        }
    }

    /**
     * The README is the architect's (created once), so what a generation made of the model is in
     * GENERATED.md, regenerated every time, which the README links: after a change of layout the
     * README is as the architect left it and GENERATED.md tells the new packages. A README that does
     * not link GENERATED.md (written by an earlier RsaML, or by hand) is kept and named in a warning.
     */
    @Test
    void theReadmeIsTheArchitectsAndLinksTheRegeneratedFacts(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        new RsamlGenerator().generate(model(tmp, "single"), Target.ROS2, out, false);
        Path readme = out.resolve("README.md");
        Path generated = out.resolve("GENERATED.md");
        assertTrue(Files.readString(readme).contains("[GENERATED.md](GENERATED.md)"), "the README links GENERATED.md:\n" + Files.readString(readme));
        assertTrue(Files.readString(generated).startsWith("<!-- Generated by RsaML") && Files.readString(generated).contains("ros2 launch " + PKG + " "
                + PKG + ".launch.py"), "GENERATED.md says it is regenerated, and how to launch:\n" + Files.readString(generated));
        assertFalse(Files.readString(generated).contains(PKG + "_navigation"), "one package: no package per layer is named");
        append(readme, "\nOur robot's notes.\n");
        String notes = Files.readString(readme);
        Path layered = model(tmp, "perLayer");
        GenerationException e = assertThrows(GenerationException.class, () -> new RsamlGenerator().generate(layered, Target.ROS2, out, false), "moving from one package per layer needs the architect's files moved");
        moveAsSaid(out, e.toString());
        new RsamlGenerator().generate(layered, Target.ROS2, out, false);
        assertEquals(notes, Files.readString(readme), "the README is kept as the architect left it");
        String facts = Files.readString(generated);
        assertTrue(facts.contains("`packages perLayer` in the model") && facts.contains("`" + PKG + "_navigation` (layer 'navigation')"),
                "GENERATED.md tells the new layout:\n" + facts);

        Files.writeString(readme, "# mobile base\n\nWritten by an earlier RsaML.\n");
        GenerationResult old = new RsamlGenerator().generate(layered, Target.ROS2, out, false);
        assertEquals(1, old.warnings().stream().filter(w -> w.startsWith("README.md") && w.contains("does not link GENERATED.md")).count(),
                "a README without the link is named: " + old.warnings());
        assertEquals("# mobile base\n\nWritten by an earlier RsaML.\n", Files.readString(readme), "and kept");
    }
}
