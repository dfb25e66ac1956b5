/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.GenerationException;
import org.rsaml.generator.GenerationResult;
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
 * What a ROS 2 developer adds to the generated packages survives regeneration and still builds
 * with the real rosidl: the manifest's version, people, licence and dependencies
 * ({@code package.user.xml}), CMake additions ({@code user.cmake}), a service of their own listed
 * in the interfaces package's {@code user.cmake}, message fields of other
 * packages (declared as dependencies when found); a model change that drops a method of theirs is
 * a compile error; a reactive cycle is bounded.
 */
class Ros2ExtensionTest {

    static final String USER_MANIFEST = """
            <?xml version="1.0"?>
            <package_user>
              <version>1.2.3</version>
              <maintainer email="ada@robots.example.org">Ada Lovelace</maintainer>
              <license>Apache-2.0</license>
              <url type="repository">https://robots.example.org/arm.git</url>
              <depend>geometry_msgs</depend>
              <depend>rclcpp</depend>
              <test_depend>ament_lint_auto</test_depend>
            </package_user>
            """;

    /** In the interfaces package, a further message package to depend on. */
    static final String USER_INTERFACES_MANIFEST = """
            <?xml version="1.0"?>
            <package_user>
              <version>2.0.0</version>
              <license>Apache-2.0</license>
              <maintainer email="ada@robots.example.org">Ada Lovelace</maintainer>
              <depend>builtin_interfaces</depend>
            </package_user>
            """;

    static final String USER_MESSAGE = """
            # A motion instruction, with a stamp and a target velocity.
            std_msgs/Header header
            geometry_msgs/Twist target
            float64 speed
            """;

    /** The architect's code reads the message's fields of other packages: rosidl's headers must be found. */
    static final String USER_CODE = """

            static_assert(ARM_USER_SETTING == 42, "user.cmake is included");

            double instruction_speed(const pick_and_place_arm_interfaces::msg::MotionInstruction& m) {
              return m.speed + m.target.linear.x + m.header.stamp.sec + static_cast<double>(m.header.frame_id.size());
            }
            """;

    /** A service of the architect's own in the interfaces package, listed in its user.cmake. */
    static final String USER_SERVICE = """
            # Asks the arm for a new speed.
            float64 speed
            ---
            bool accepted
            """;

    static final String USER_SERVICE_CODE = """

            bool speed_request_ok(const pick_and_place_arm_interfaces::srv::SetSpeed::Request& r) {
              return r.speed >= 0.0;
            }
            """;

    @Test
    void userAdditionsSurviveAModelChangeAndStillBuild(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("exp3-task-interpreter.rsaml"), tmp.resolve("arm.rsaml"));
        Path out = tmp.resolve("ws");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(model, Target.ROS2, out, false);

        Path pkg = out.resolve("pick_and_place_arm");
        Path ipkg = out.resolve("pick_and_place_arm_interfaces");
        assertTrue(Files.readString(pkg.resolve("package.xml")).contains("<license>TODO</license>"), "a first generation's package.xml leaves the license for the architect");
        Files.writeString(pkg.resolve("package.user.xml"), USER_MANIFEST);
        Files.writeString(ipkg.resolve("package.user.xml"), USER_INTERFACES_MANIFEST);
        Files.writeString(pkg.resolve("user.cmake"), Files.readString(pkg.resolve("user.cmake"))
                + "target_compile_definitions(${PROJECT_NAME} PRIVATE ARM_USER_SETTING=42)\n");
        Files.writeString(ipkg.resolve("msg/MotionInstruction.msg"), USER_MESSAGE);
        Files.createDirectories(ipkg.resolve("srv"));
        Files.writeString(ipkg.resolve("srv/SetSpeed.srv"), USER_SERVICE);
        Files.writeString(ipkg.resolve("user.cmake"), Files.readString(ipkg.resolve("user.cmake"))
                + "list(APPEND RSAML_USER_INTERFACES \"srv/SetSpeed.srv\")\n");
        Path cpp = pkg.resolve("src/motion_control/MotionController.cpp");
        Files.writeString(cpp, "#include \"pick_and_place_arm_interfaces/srv/set_speed.hpp\"\n"
                + Files.readString(cpp).replace("}  // namespace", USER_CODE + USER_SERVICE_CODE + "\n}  // namespace"));
        Map<String, byte[]> before = userFiles(out);

        // The model changes: a new output port.
        String text = Files.readString(model).replace("<ports xsi:type=\"rsaml:OutputPort\" name=\"s0_motionController\"",
                "<ports xsi:type=\"rsaml:OutputPort\" name=\"s1_motionController\" dataType=\"boolean\"/>\n      "
                        + "<ports xsi:type=\"rsaml:OutputPort\" name=\"s0_motionController\"");
        assertNotEquals(Files.readString(model), text, "the test changed the model's output port");
        Files.writeString(model, text);
        generator.generate(model, Target.ROS2, out, false);

        assertTrue(Tools.sameFiles(before, userFiles(out)), "the architect's files changed");
        assertTrue(Files.readString(pkg.resolve("gen/motion_control/MotionControllerBase.hpp")).contains("out_s1_motionController"), "the regenerated base class has the new output port");
        String manifest = Files.readString(pkg.resolve("package.xml"));
        for (String expected : List.of("<version>1.2.3</version>", "<maintainer email=\"ada@robots.example.org\">Ada Lovelace</maintainer>",
                "<license>Apache-2.0</license>", "<url type=\"repository\">https://robots.example.org/arm.git</url>",
                "<depend>geometry_msgs</depend>", "<test_depend>ament_lint_auto</test_depend>")) {
            assertTrue(manifest.contains(expected), expected + " missing from\n" + manifest);
        }
        assertEquals(1, count(manifest, "<depend>rclcpp</depend>"), manifest);
        assertTrue(!manifest.contains("TODO") && !manifest.contains("maintainer@example.com"), manifest);
        // The message's fields of std_msgs and geometry_msgs: declared where rosidl and rosdep look.
        String imanifest = Files.readString(ipkg.resolve("package.xml"));
        assertTrue(imanifest.contains("<version>2.0.0</version>") && imanifest.contains("<depend>std_msgs</depend>")
                && imanifest.contains("<depend>geometry_msgs</depend>"), imanifest);
        String icmake = Files.readString(ipkg.resolve("CMakeLists.txt"));
        assertTrue(imanifest.contains("<depend>builtin_interfaces</depend>"), imanifest);
        assertTrue(icmake.contains("find_package(std_msgs REQUIRED)") && icmake.contains("DEPENDENCIES builtin_interfaces geometry_msgs std_msgs"), icmake);

        Ros2Build.validateManifest(pkg.resolve("package.xml"));
        Ros2Build.validateManifest(ipkg.resolve("package.xml"));
        Ros2Build.buildAll(out, tmp.resolve("colcon"));
    }

    @Test
    void aBrokenUserManifestIsRefusedWithItsLine(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("ws");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.ROS2, out, false);
        Path user = out.resolve("pick_and_place_arm/package.user.xml");
        Files.writeString(user, "<?xml version=\"1.0\"?>\n<package_user>\n  <licence>MIT</licence>\n"
                + "  <maintainer email=\"a@b.org\">A</maintainer>\n  <license>MIT</license>\n</package_user>\n");
        Map<String, byte[]> before = Tools.snapshot(out);

        GenerationException e = assertThrows(GenerationException.class,
                () -> generator.generate(Tools.example("exp3-task-interpreter.rsaml"), Target.ROS2, out, false),
                "a package.user.xml with an unknown element stops the generation");
        assertEquals("pick_and_place_arm/package.user.xml", e.file().replace('\\', '/'), e.toString());
        assertEquals(3, e.line(), e.toString());
        assertTrue(e.getMessage().contains("<licence>"), e.getMessage());
        assertTrue(Tools.sameFiles(before, Tools.snapshot(out)), "the output changed");
    }

    /**
     * config/&lt;pkg&gt;.params.yaml is the architect's: an edit survives generating again after a
     * model change, and it is what both launch files give the node (a time written without a decimal
     * point too; the file's value over the model's); a QoS override written under the model's name of
     * a topic reaches the topic as remapped (its launch argument) and namespaced; an invalid edit is
     * refused when a launch file reads it, naming the file, the line and what is wrong, and generating
     * again keeps it as written.
     */
    @Test
    void theParametersFileIsKeptAndBothLaunchFilesApplyIt(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("mobile-base-latency.rsaml"), tmp.resolve("base.rsaml"));
        Path out = tmp.resolve("ws");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(model, Target.ROS2, out, false);
        String pkg = Names.snake(ModelLoader.load(model, "base.rsaml").architecture().getName());
        Path root = out.resolve(pkg);
        Path params = root.resolve("config/" + pkg + ".params.yaml");
        String node = Ros2Test.nodes(root).get("navigation/obstacleDetector");
        String text = Files.readString(params);
        Matcher period = Pattern.compile("(?m)^" + node + ":\\n  ros__parameters:\\n(?:    #.*\\n)?    ([\\w.]+\\.period_ms): 20\\.0$").matcher(text);
        assertTrue(period.find(), "no period of obstacleDetector in ms, the model's 20.0, in node " + node + "'s section:\n" + text);
        String name = period.group(1);
        String qos = "qos_overrides.speed_limit.publisher.reliability: best_effort";
        assertTrue(text.contains("    " + qos + "\n"), "the sensor topic's QoS, under the model's name:\n" + text);
        String edited = text.replace("    " + name + ": 20.0\n", "    # tuned on the robot\n    " + name + ": 40\n")
                .replace(qos, qos.replace("best_effort", "reliable"));
        Files.writeString(params, edited);

        // The model changes (the planner's period); the file stays as the architect wrote it.
        String changed = Files.readString(model).replace("period=\"100.0\" delay=\"100.0\"", "period=\"200.0\" delay=\"100.0\"");
        assertNotEquals(Files.readString(model), changed, "the test changed the model's period");
        Files.writeString(model, changed);
        GenerationResult again = generator.generate(model, Target.ROS2, out, false);
        assertTrue(again.preserved().stream().anyMatch(f -> f.endsWith(Path.of("config", pkg + ".params.yaml"))), "not kept: " + again.preserved());
        assertEquals(edited, Files.readString(params), "the architect's parameters file changed on generating again");
        assertTrue(Files.readString(root.resolve("gen/navigation/PathPlannerBase.hpp")).contains("period_ms\", 200.0)"), "the model's change is not in the node");

        // Both launch files give the node the file's values, the override under the topic's resolved name.
        for (String file : List.of(pkg + ".launch.py", pkg + "_processes.launch.py")) {
            Tools.Result r = Ros2Test.launch(root.resolve("launch/" + file), "namespace:=robot1", "speed_limit_topic:=renamed/speed_limit");
            assertEquals(0, r.exit(), r.output());
            String given = r.output().lines().filter(l -> l.contains(" " + node + " [{")).findFirst().orElse("");
            assertTrue(given.contains("'" + name + "': 40.0"), file + " does not give " + node + " the file's " + name + ": 40 as a double:\n" + r.output());
            assertTrue(given.contains("'qos_overrides./robot1/renamed/speed_limit.publisher.reliability': 'reliable'"),
                    file + ": the override of speed_limit does not follow its remapping and namespace:\n" + given);
        }

        // Invalid edits: each refused with the file and its line; generating again keeps it.
        int line = (int) edited.substring(0, edited.indexOf("    " + name + ": 40")).lines().count() + 1;
        String history = "qos_overrides.speed_limit.publisher.history: ";
        int historyLine = (int) edited.substring(0, edited.indexOf("    " + history + "keep_last\n")).lines().count() + 1;
        Map<String, String> invalid = Map.of(
                // rclcpp refuses intra-process communication (on in a container) with keep_all
                edited.replace("    " + history + "keep_last\n", "    " + history + "keep_all\n"), ":" + historyLine + ": " + history.strip()
                        + " 'keep_all': the nodes of a container share messages within the process",
                edited.replace("    " + name + ": 40\n", "    " + name + ": fast\n"), ":" + line + ": " + name + " of node " + node
                        + " must be a positive number of ms (the unit its name ends with), not 'fast'",
                edited.replace("    " + name + ": 40\n", "    " + name.replace("_ms", "_us") + ": 40\n"), ":" + line + ": node '" + node
                        + "' has no parameter " + name.replace("_ms", "_us") + " (its times: " + name + "): the model changed",
                edited.replace("    " + name + ": 40\n", "\t" + name + ": 40\n"), ":" + line + ": not YAML");
        for (Map.Entry<String, String> e : invalid.entrySet()) {
            Files.writeString(params, e.getKey());
            Tools.Result r = Ros2Test.launch(root.resolve("launch/" + pkg + ".launch.py"));
            assertNotEquals(0, r.exit(), "an invalid parameters file was taken:\n" + e.getKey());
            assertTrue(r.output().contains(params + e.getValue()), "expected '" + params + e.getValue() + "' in:\n" + r.output());
            generator.generate(model, Target.ROS2, out, false);
            assertEquals(e.getKey(), Files.readString(params), "generating again changed the architect's invalid parameters file");
        }
        Files.writeString(params, edited.replace("    " + history + "keep_last\n", "    " + history + "keep_all\n"));
        Tools.Result processes = Ros2Test.launch(root.resolve("launch/" + pkg + "_processes.launch.py"));
        assertEquals(0, processes.exit(), "a process per node takes keep_all (no intra-process communication):\n" + processes.output());

        // A function renamed in the model: generating again says which line of the file names its old
        // parameter, and the launch files refuse that line.
        Files.writeString(params, edited);
        Files.writeString(model, Files.readString(model).replace("<functions name=\"plan\" ", "<functions name=\"replan\" "));
        int planLine = (int) edited.substring(0, edited.indexOf("    plan.period_ms: ")).lines().count() + 1;
        String stale = pkg + "/config/" + pkg + ".params.yaml:" + planLine + ": node 'navigation_path_planner' has no parameter plan.period_ms";
        GenerationResult renamed = generator.generate(model, Target.ROS2, out, false);
        assertTrue(renamed.warnings().stream().anyMatch(w -> w.startsWith(stale) && w.contains("replan.period_ms")),
                "no warning starting '" + stale + "': " + renamed.warnings());
        assertEquals(edited, Files.readString(params), "generating again changed the architect's parameters file");
        Tools.Result r = Ros2Test.launch(root.resolve("launch/" + pkg + "_processes.launch.py"));
        assertTrue(r.exit() != 0 && r.output().contains(params + ":" + planLine + ": node 'navigation_path_planner' has no parameter plan.period_ms"),
                "the launch files took a time the node no longer has:\n" + r.output());
    }

    @Test
    void aMethodTheModelDropsIsACompileError(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("exp3-task-interpreter.rsaml"), tmp.resolve("arm.rsaml"));
        Path out = tmp.resolve("ws");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(model, Target.ROS2, out, false);
        Files.writeString(model, Files.readString(model).replace("instruction6", "placePart"));
        GenerationResult again = generator.generate(model, Target.ROS2, out, false);
        assertTrue(again.warnings().stream().anyMatch(w -> w.contains("MotionController.hpp: instruction6 is no longer in the model")),
                again.warnings().toString());

        Path work = tmp.resolve("colcon");
        Path install = work.resolve("install");
        Ros2Build.buildPackage(out.resolve("pick_and_place_arm_interfaces"), work.resolve("build/i"), install,
                List.of(Ros2Build.underlay(), install));
        Path pkg = out.resolve("pick_and_place_arm");
        String prefixes = Ros2Build.underlay() + ";" + install;
        Tools.ok(pkg, 600, "cmake", "-S", ".", "-B", work.resolve("build/p").toString(), "-DCMAKE_PREFIX_PATH=" + prefixes,
                "-DPython3_EXECUTABLE=" + Ros2Build.python(),
                "-DCMAKE_CXX_FLAGS=" + Ros2Build.CXX_FLAGS);
        Tools.Result build = Tools.run(pkg, 900, "cmake", "--build", work.resolve("build/p").toString(), "-j2");
        assertNotEquals(0, build.exit(), "the build did not notice the dropped method");
        assertTrue(Pattern.compile("instruction6\\(\\)['\u2018\u2019] marked ['\u2018\u2019]override['\u2018\u2019], but does not override").matcher(build.output()).find(),
                Tools.last(build.output(), 4000));
    }

    @Test
    void modulesInAReactiveCycleReactAtMostOncePerWave(@TempDir Path tmp) throws Exception {
        String name = "exp1-hybrid.rsaml";
        Path out = tmp.resolve("ws");
        GenerationResult result = new RsamlGenerator().generate(Tools.example(name), Target.ROS2, out, false);
        Architecture arch = ModelLoader.load(Tools.example(name), name).architecture();
        List<String> cycles = result.warnings().stream().filter(w -> w.contains("react to each other's data in a cycle")).toList();
        assertTrue(!cycles.isEmpty(), "exp1 has a reactive cycle: " + result.warnings());

        int bounded = 0;
        for (Layer layer : arch.getLayers()) {
            for (Module m : layer.getModules()) {
                String qn = layer.getName() + "/" + m.getName();
                if (cycles.stream().noneMatch(w -> w.contains(" " + qn + " ") || w.contains("modules " + qn + " "))) {
                    continue;
                }
                Path base = out.resolve(Names.snake(arch.getName()) + "/gen/" + Names.snake(layer.getName()) + "/"
                        + Names.pascal(m.getName()) + "Base.hpp");
                String text = Files.readString(base);
                // in the module's time unit, as the parameters file has it
                String unit = m.getTimeUnit().getLiteral();
                Matcher p = Pattern.compile("declare_parameter<double>\\(\"reaction.min_interval_" + unit + "\", ([\\d.]+)\\), ([\\d.]+)\\)").matcher(text);
                assertTrue(p.find(), qn + " has no reaction bound in " + unit);
                assertEquals(m.getTimeUnit().getValue() + ".0", p.group(2), qn + ": nanoseconds per " + unit);
                assertEquals(new BigDecimal(shortestFeedingPeriodNs(arch, m)), new BigDecimal(p.group(1)).multiply(new BigDecimal(m.getTimeUnit().getValue()))
                        .stripTrailingZeros().setScale(0), qn);
                assertTrue(text.contains("if (!due(last_reaction_, reaction_interval_)) {"), qn);
                bounded++;
            }
        }
        assertTrue(bounded >= 2, "no module of the cycle found: " + cycles);
    }

    /** The shortest period of the periodic modules and functions whose data can reach m. */
    private static long shortestFeedingPeriodNs(Architecture arch, Module m) {
        Set<Module> seen = new HashSet<>();
        Deque<Module> todo = new ArrayDeque<>(List.of(m));
        long shortest = Long.MAX_VALUE;
        while (!todo.isEmpty()) {
            Module u = todo.pop();
            if (!seen.add(u)) {
                continue;
            }
            if (u.getExecType() == ExecutionType.PERIODIC && u.getPeriod() > 0) {
                shortest = Math.min(shortest, Math.round(u.getPeriod() * u.getTimeUnit().getValue()));
            }
            for (Function f : u.getFunctions()) {
                if (f.getExecType() == ExecutionType.PERIODIC && f.getPeriod() > 0) {
                    shortest = Math.min(shortest, Math.round(f.getPeriod() * f.getTimeUnit().getValue()));
                }
            }
            for (Connection c : arch.getConnections()) {
                if (c.getTarget().getModule() == u) {
                    todo.add(c.getSource().getModule());
                }
            }
        }
        return shortest;
    }

    private static int count(String text, String part) {
        return text.split(Pattern.quote(part), -1).length - 1;
    }

    /** The architect's files: src/, the .msg files, user.cmake and package.user.xml. */
    private static Map<String, byte[]> userFiles(Path out) throws Exception {
        Map<String, byte[]> all = Tools.snapshot(out);
        all.keySet().removeIf(k -> !(k.contains("/src/") || k.endsWith(".msg") || k.endsWith(".srv") || k.endsWith("user.cmake")
                || k.endsWith("package.user.xml")));
        return all;
    }
}
