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
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.model.support.RsamlPackages;

/**
 * No generated ROS 2 package is named like one of ROS 2's own (it would depend on itself, which colcon refuses, or
 * hide ROS 2's): {@link RsamlPackages#ROS2_OWN} lists every ROS 2 package the generated package.xml files and
 * CMakeLists.txt name, in every package layout and with managed nodes, and an architecture named like one of them
 * (or whose interfaces or runtime package would be) gets the next free name, with a warning saying why.
 */
class Ros2OwnPackagesTest {

    private static final Pattern MANIFEST_DEPENDENCY = Pattern.compile("<(?:build_|buildtool_|exec_|test_|build_export_)?depend>\\s*([^<\\s]+)\\s*<");
    private static final Pattern FIND_PACKAGE = Pattern.compile("^\\s*find_package\\(\\s*([A-Za-z0-9_]+)", Pattern.MULTILINE);

    /** The ROS 2 packages an output's manifests and CMake files name that it does not generate itself. */
    private static Set<String> named(Path out) throws Exception {
        Set<String> generated = new TreeSet<>();
        Set<String> named = new TreeSet<>();
        try (Stream<Path> files = Files.walk(out)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                String file = f.getFileName().toString();
                if (file.equals("package.xml")) {
                    generated.add(f.getParent().getFileName().toString());
                    Matcher m = MANIFEST_DEPENDENCY.matcher(Files.readString(f));
                    while (m.find()) {
                        named.add(m.group(1));
                    }
                } else if (file.equals("CMakeLists.txt")) {
                    Matcher m = FIND_PACKAGE.matcher(Files.readString(f));
                    while (m.find()) {
                        named.add(m.group(1));
                    }
                }
            }
        }
        named.removeAll(generated);
        named.remove("Threads"); // CMake's own module, not a ROS package
        return named;
    }

    @Test
    void everyRos2PackageTheGeneratedPackagesNameIsOneNoGeneratedPackageTakes(@TempDir Path tmp) throws Exception {
        Set<String> named = new TreeSet<>();
        for (String layout : List.of("single", "perLayer", "perProcessor")) {
            Path model = Ros2PackagesTest.model(tmp, layout, "declaredLayers=\"2\"", "declaredLayers=\"2\" lifecycle=\"managed\"");
            Path out = tmp.resolve("out-" + layout);
            new RsamlGenerator().generate(model, Target.ROS2, out, false);
            named.addAll(named(out));
        }
        assertTrue(named.containsAll(List.of("rclcpp", "rclcpp_components", "rclcpp_lifecycle", "ament_cmake", "launch_ros")),
                "the manifests are read: " + named);
        Set<String> unknown = new TreeSet<>(named);
        unknown.removeAll(RsamlPackages.ROS2_OWN);
        assertEquals(Set.of(), unknown, "every ROS 2 package the generator names is one a generated package may not be named like"
                + " (add it to RsamlPackages.ROS2_OWN)");
    }

    @Test
    void aLayerOrProcessorPackageNamedLikeARos2PackageGetsTheNextFreeNameAndIsToldWhy(@TempDir Path tmp) throws Exception {
        // Architecture 'nav' with a layer (or processor) 'msgs': its package would be nav_msgs, ROS 2's own.
        for (String[] c : new String[][] { { "perLayer", "navigation", "layer 'msgs'" }, { "perProcessor", "core1", "processor 'msgs'" } }) {
            Path model = Ros2PackagesTest.model(tmp, c[0], "name=\"mobileBase\"", "name=\"nav\"", c[1], "msgs");
            Path out = tmp.resolve("out-" + c[0]);

            GenerationResult result = new RsamlGenerator().generate(model, Target.ROS2, out, false);

            assertTrue(Files.exists(out.resolve("nav_msgs_2/package.xml")) && !Files.exists(out.resolve("nav_msgs")),
                    c[0] + ": the nodes of " + c[2] + " are in package nav_msgs_2, not in one named like ROS 2's nav_msgs");
            assertTrue(Files.readString(out.resolve("nav_msgs_2/package.xml")).contains("<name>nav_msgs_2</name>"),
                    "the manifest says the package's name");
            String expected = c[2] + " is named nav_msgs_2 in ROS 2, not nav_msgs: nav_msgs is a package of ROS 2 itself (a generated"
                    + " package of that name would depend on itself or hide ROS 2's); the package of its nodes is named nav_msgs_2 (rename the "
                    + c[2].replaceFirst(" .*", "") + " to choose another name)";
            assertEquals(1, result.warnings().stream().filter(expected::equals).count(),
                    c[0] + ": the generation says once which element's package changed name, why and what to do: " + result.warnings());
            assertTrue(Files.readString(out.resolve("nav/package.xml")).contains("<exec_depend>nav_msgs_2</exec_depend>"),
                    "the launch files' package runs the nodes from the renamed package");
        }
    }

    @Test
    void anArchitectureNamedLikeARos2PackageGetsTheNextFreeNameAndIsToldWhy(@TempDir Path tmp) throws Exception {
        for (String[] c : new String[][] { { "std_msgs", "std_msgs_2", "std_msgs is a package of ROS 2 itself" },
                { "rcl", "rcl_2", "rcl and rcl_interfaces are packages of ROS 2 itself" },
                { "sensorMsgs", "sensor_msgs_2", "sensor_msgs is a package of ROS 2 itself" } }) {
            Path model = Ros2PackagesTest.model(tmp, "single", "name=\"mobileBase\"", "name=\"" + c[0] + "\"");
            Path out = tmp.resolve("out-" + c[0]);

            GenerationResult result = new RsamlGenerator().generate(model, Target.ROS2, out, false);

            Set<String> packages = new TreeSet<>();
            try (Stream<Path> dirs = Files.list(out)) {
                dirs.filter(d -> Files.exists(d.resolve("package.xml"))).forEach(d -> packages.add(d.getFileName().toString()));
            }
            assertEquals(Set.of(c[1], c[1] + "_interfaces"), packages, "architecture '" + c[0] + "' gives packages of the next free name");
            assertTrue(Files.readString(out.resolve(c[1] + "/package.xml")).contains("<name>" + c[1] + "</name>"),
                    "the manifest says the package's name");
            assertFalse(named(out).stream().anyMatch(packages::contains), "no package depends on itself");
            assertTrue(result.warnings().stream().anyMatch(w -> w.contains(c[2]) && w.contains("are named " + c[1])
                    && w.contains("rename the architecture")), "the generation says why the name changed and what to do: " + result.warnings());
        }
        Path plain = tmp.resolve("out-plain");
        GenerationResult result = new RsamlGenerator().generate(Ros2PackagesTest.model(tmp, "single"), Target.ROS2, plain, false);
        assertTrue(Files.exists(plain.resolve(Ros2PackagesTest.PKG + "/package.xml")), "a name ROS 2 does not use is kept");
        assertFalse(result.warnings().stream().anyMatch(w -> w.contains("of ROS 2 itself")), "and nothing is said of it: " + result.warnings());
    }
}
