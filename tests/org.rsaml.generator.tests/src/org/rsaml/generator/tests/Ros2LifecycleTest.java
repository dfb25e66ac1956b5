/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * Managed nodes in the generated ROS 2 package (resources/ros2-lifecycle.rsaml: the architecture's
 * nodes managed, the monitor plain): what a ROS 2 developer expects of an rclcpp_lifecycle node —
 * nothing created in the constructor but parameters, publishers and subscriptions created on
 * configure, timers started and publishers activated on activate, both stopped on deactivate,
 * nothing published or processed while inactive — the package's lifecycle manager started by both
 * launch files for exactly the managed nodes, and a plain node unchanged by its neighbours' choice.
 * {@link Ros2LaunchTest} runs them on ROS 2.
 */
class Ros2LifecycleTest {

    private static final String MODEL = "ros2-lifecycle.rsaml";
    private static final String PKG = "managed_robot";

    private static Path generate(Path tmp, String name, String xmi) throws Exception {
        Path model = tmp.resolve(name + ".rsaml");
        Files.writeString(model, xmi);
        Path out = tmp.resolve(name);
        new RsamlGenerator().generate(model, Target.ROS2, out, false);
        return out.resolve(PKG);
    }

    private static String xmi() throws Exception {
        return Files.readString(Tools.resource(MODEL));
    }

    /** The text of `file` from the first `from` on, up to the next `to` after it. */
    private static String section(String file, String from, String to) {
        int begin = file.indexOf(from);
        assertTrue(begin >= 0, "no " + from + " in:\n" + file);
        int end = file.indexOf(to, begin + from.length());
        assertTrue(end >= 0, "no " + to + " after " + from + " in:\n" + file);
        return file.substring(begin, end);
    }

    @Test
    void aManagedNodeCreatesItsEntitiesInTheTransitionsARos2DeveloperExpects(@TempDir Path tmp) throws Exception {
        Path pkg = generate(tmp, "managed", xmi());
        String lidar = Files.readString(pkg.resolve("gen/perception/LidarBase.hpp"));
        assertTrue(lidar.contains("#include \"rsaml/lifecycle.hpp\"") && lidar.contains("class LidarBase : public ::" + PKG
                + "::rsaml_ros2::ScheduledLifecycleNode {"), "the lidar's node is an rclcpp_lifecycle node:\n" + lidar);
        String constructor = section(lidar, "explicit LidarBase(", "CallbackReturn on_configure(");
        for (String created : List.of("create_publisher", "create_subscription", "rsaml_add_timer")) {
            assertFalse(constructor.contains(created), "a managed node is created unconfigured, yet its constructor calls " + created
                    + ":\n" + constructor);
        }
        assertTrue(constructor.contains("declare_parameter<double>(\"scanLoop.period_ms\""),
                "the parameters are declared at construction, so they can be set before configure:\n" + constructor);
        String configure = section(lidar, "CallbackReturn on_configure(", "CallbackReturn on_activate(");
        assertTrue(configure.contains("create_publisher<std_msgs::msg::Float64>(") && !configure.contains("rsaml_add_timer"),
                "configure creates the publisher, not the timer:\n" + configure);
        String activate = section(lidar, "CallbackReturn on_activate(", "CallbackReturn on_deactivate(");
        assertTrue(activate.contains("out_scan_pub_->on_activate();") || activate.matches("(?s).*\\w+_->on_activate\\(\\);.*"),
                "activate activates the publisher:\n" + activate);
        assertTrue(activate.contains("rsaml_add_timer(") && activate.contains("this->rsaml_state(true, \"active\");"),
                "activate starts the timer and says so:\n" + activate);
        String deactivate = section(lidar, "CallbackReturn on_deactivate(", "CallbackReturn on_cleanup(");
        assertTrue(deactivate.contains("rsaml_stop_timers();") && deactivate.matches("(?s).*\\w+_->on_deactivate\\(\\);.*"),
                "deactivate stops the timer and deactivates the publisher:\n" + deactivate);
        assertTrue(section(lidar, "void rsaml_stop_timers() {", "void rsaml_release_entities()").contains("->cancel();"),
                "stopping cancels the timers:\n" + lidar);
        assertTrue(section(lidar, "virtual void publish_outputs() {", "}").contains("if (!this->rsaml_active()) {"),
                "nothing is published while the node is not active:\n" + lidar);

        // The mapper reacts to data: it drops what arrives while inactive, its inhibitor's trigger too.
        String mapper = Files.readString(pkg.resolve("gen/mapping/MapperBase.hpp"));
        String mapperConfigure = section(mapper, "CallbackReturn on_configure(", "CallbackReturn on_activate(");
        assertEquals(2, mapperConfigure.split("create_subscription<", -1).length - 1,
                "configure subscribes to the scan and to the inhibitor's trigger:\n" + mapperConfigure);
        assertEquals(2, mapperConfigure.split("if \\(!this->rsaml_active\\(\\)\\) \\{", -1).length - 1,
                "both subscriptions drop what arrives while the node is inactive:\n" + mapperConfigure);
    }

    @Test
    void bothLaunchFilesStartTheLifecycleManagerForTheManagedNodesAlone(@TempDir Path tmp) throws Exception {
        Path pkg = generate(tmp, "managed", xmi());
        Map<String, String> nodes = Ros2Test.nodes(pkg);
        String managed = "'node_names': ['" + nodes.get("perception/lidar") + "', '" + nodes.get("mapping/mapper") + "']";
        for (String launch : List.of(PKG + ".launch.py", PKG + "_processes.launch.py")) {
            String text = Files.readString(pkg.resolve("launch/" + launch));
            assertTrue(text.contains("executable='" + PKG + "_lifecycle_manager'") && text.contains(managed),
                    launch + " starts the lifecycle manager for the lidar and the mapper (" + managed + "), not the plain monitor:\n" + text);
        }
        String cmake = Files.readString(pkg.resolve("CMakeLists.txt"));
        assertTrue(cmake.contains("find_package(rclcpp_lifecycle REQUIRED)") && cmake.contains("rclcpp_lifecycle::rclcpp_lifecycle")
                && cmake.contains("add_executable(" + PKG + "_lifecycle_manager gen/rsaml/lifecycle_manager.cpp)")
                && cmake.matches("(?s).*install\\(TARGETS [^)]*" + PKG + "_lifecycle_manager[^)]*\\).*"),
                "the package builds and installs the lifecycle manager against rclcpp_lifecycle:\n" + cmake);
        String manifest = Files.readString(pkg.resolve("package.xml"));
        assertTrue(manifest.contains("<depend>rclcpp_lifecycle</depend>") && manifest.contains("<depend>lifecycle_msgs</depend>"), manifest);
    }

    @Test
    void aModuleMayChooseOtherwiseAndPlainNodesAreUnchanged(@TempDir Path tmp) throws Exception {
        String xmi = xmi();
        assertTrue(xmi.contains(" lifecycle=\"managed\">") && xmi.contains(" lifecycle=\"plain\">"), xmi);
        Path plain = generate(tmp, "plain", xmi.replace(" lifecycle=\"managed\">", ">").replace(" lifecycle=\"plain\">", ">"));
        Path managed = generate(tmp, "managed", xmi);
        assertEquals(Files.readString(plain.resolve("gen/supervision/MonitorBase.hpp")),
                Files.readString(managed.resolve("gen/supervision/MonitorBase.hpp")),
                "the monitor chose a plain node: the same node as in an architecture of plain nodes");
        assertFalse(Files.exists(plain.resolve("gen/rsaml/lifecycle.hpp")) || Files.exists(plain.resolve("gen/rsaml/lifecycle_manager.cpp")),
                "a package of plain nodes has no lifecycle runtime");
        for (String file : List.of("CMakeLists.txt", "package.xml", "launch/" + PKG + ".launch.py", "launch/" + PKG + "_processes.launch.py",
                "gen/perception/LidarBase.hpp")) {
            String text = Files.readString(plain.resolve(file));
            assertFalse(text.contains("lifecycle"), "plain nodes only, yet " + file + " speaks of a lifecycle:\n" + text);
        }

        // The other way round: plain nodes, one module managed.
        Path one = generate(tmp, "one", xmi.replace(" lifecycle=\"managed\">", ">").replace(" lifecycle=\"plain\">", " lifecycle=\"managed\">"));
        Map<String, String> nodes = Ros2Test.nodes(one);
        String launch = Files.readString(one.resolve("launch/" + PKG + ".launch.py"));
        assertTrue(launch.contains("'node_names': ['" + nodes.get("supervision/monitor") + "']"), "the monitor alone is managed:\n" + launch);
        List<String> lifecycleNodes = Files.list(one.resolve("gen")).flatMap(d -> {
            try {
                return Files.isDirectory(d) ? Files.list(d) : java.util.stream.Stream.<Path>empty();
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }).filter(f -> f.toString().endsWith("Base.hpp")).filter(f -> {
            try {
                return Files.readString(f).contains("ScheduledLifecycleNode");
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }).map(f -> f.getFileName().toString()).sorted().collect(Collectors.toList());
        assertEquals(List.of("MonitorBase.hpp"), lifecycleNodes, "the one managed module's node is the one lifecycle node");
    }
}
