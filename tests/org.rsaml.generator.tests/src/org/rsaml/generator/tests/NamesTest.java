/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.NameScope;
import org.rsaml.generator.internal.Names;

/** Model names become safe, unique file names and identifiers, the same ones on every run. */
class NamesTest {

    @ParameterizedTest
    @CsvSource({ "../../etc/passwd, etc_passwd", "class, class_", "None, None_", "3d camera, n3d_camera", "a--b  c, a_b_c",
            "__init__, init", "été, t", "linux, linux_", "'', unnamed" })
    void identifiers(String raw, String expected) {
        assertEquals(expected, Names.identifier(raw), "the model name '" + raw + "' becomes a safe identifier");
    }

    @ParameterizedTest
    @CsvSource({ "taskInterpreter, TaskInterpreter, task_interpreter", "eMoveSP, EMoveSP, e_move_sp",
            "motor-left, MotorLeft, motor_left", "none, None_, none", "HTTPServer, HTTPServer, http_server" })
    void classAndRosNames(String raw, String pascal, String snake) {
        assertEquals(pascal, Names.pascal(raw), "'" + raw + "' becomes the class name " + pascal);
        assertEquals(snake, Names.snake(raw), "'" + raw + "' becomes the ROS name " + snake);
    }

    @ParameterizedTest
    @CsvSource({ "Pose2D, pose2_d", "MotionInstruction, motion_instruction", "LaserScan, laser_scan", "Twist, twist" })
    void rosidlHeaderNames(String type, String header) {
        assertEquals(header, Names.rosidlHeaderStem(type), "the ROS message type " + type + " is included from the header rosidl generates");
    }

    @Test
    void collisionsGetSuffixesInModelOrder() {
        NameScope files = new NameScope(true);
        assertEquals("Foo", files.allocate("Foo"), "the first name is kept as it is");
        assertEquals("foo_2", files.allocate("foo"), "a name that differs only in case gets a suffix (files are case-insensitive on some systems)");
        assertEquals("Foo_3", files.allocate("Foo"), "the third name of the same spelling gets the next suffix");
        NameScope members = new NameScope(false, "react");
        assertEquals("x", members.allocate("x", "in_", "", "on_", ""), "a member name without a collision is kept");
        assertEquals("react_2", members.allocate("react"), "a reserved member name gets a suffix");
        assertTrue(members.isTaken("in_x") && members.isTaken("on_x"), "the derived port members in_x and on_x are reserved with x");
    }

    @Test
    void stringsAndCommentsCannotEscape() {
        assertEquals("\"a\\\"b\\\\c\\012\\303\\251\"", Names.cppString("a\"b\\c\né"), "a C++ string literal escapes quotes, backslashes, newlines and non-ASCII bytes");
        assertEquals("'it\\'s'", Names.pythonString("it's"), "a Python string literal escapes its quote");
        assertEquals("a * / b", Names.comment("a */ b\\"), "a model text can neither close a C++ comment nor continue it with a trailing backslash");
        assertEquals("x &lt;y&gt; &amp;", Names.xml("x <y> &"), "a model text cannot open XML markup");
    }

    /** A model full of hostile names generates a project whose files are exactly these, and that builds and runs. */
    @Test
    void hostileNamesGiveSafeFilesThatBuild(@TempDir Path tmp) throws Exception {
        Path out = tmp.resolve("out");
        new RsamlGenerator().generate(Tools.resource("names-hostile.rsaml"), Target.CPP, out, false);
        Set<String> gen = Tools.snapshot(out).keySet();
        Set<String> expected = new TreeSet<>(Set.of(".rsaml-generated", "CMakeLists.txt", "GENERATED.md", "README.md", "gen/Architecture.cpp",
                "gen/Architecture.hpp", "gen/main.cpp", "gen/messages.hpp", "gen/rsaml/realtime.hpp", "gen/rsaml/jobs.hpp", "gen/rsaml/tracequeue.hpp",
                "gen/class_/None_Base.cpp", "gen/class_/None_Base.hpp", "gen/class_/MotorLeftBase.cpp", "gen/class_/MotorLeftBase.hpp",
                "gen/class_/MotorLeft_2Base.cpp", "gen/class_/MotorLeft_2Base.hpp", "gen/my_layer/FooBase.cpp", "gen/my_layer/FooBase.hpp",
                "gen/my_layer/Foo_2Base.cpp", "gen/my_layer/Foo_2Base.hpp", "gen/my_layer_2/XBase.cpp", "gen/my_layer_2/XBase.hpp",
                "src/class_/None_.cpp", "src/class_/None_.hpp", "src/class_/MotorLeft.cpp", "src/class_/MotorLeft.hpp",
                "src/class_/MotorLeft_2.cpp", "src/class_/MotorLeft_2.hpp", "src/my_layer/Foo.cpp", "src/my_layer/Foo.hpp",
                "src/my_layer/Foo_2.cpp", "src/my_layer/Foo_2.hpp", "src/my_layer_2/X.cpp", "src/my_layer_2/X.hpp",
                "src/msg/geometry_msgs/msg_/Twist.hpp", "src/user.cmake"));
        CppRuntimeTest.files().forEach(file -> expected.add("gen/rsaml/" + file));
        assertEquals(expected, new TreeSet<>(gen), "the project's files, the runtime's included");
        String motorLeft = Files.readString(out.resolve("gen/class_/MotorLeftBase.hpp"));
        // A function named like a runtime hook, and two actions named 'delete' in two functions.
        for (String decl : List.of("virtual void on_start_2();", "virtual void delete_();", "virtual void g_delete();",
                "::rsaml::Input<double> in_x_y;")) {
            assertTrue(motorLeft.contains(decl), decl);
        }

        Path exe = Tools.cmakeBuild(out, "etc_passwd");
        RunTrace trace = new RunTrace(Tools.ok(out, 60, exe.toString(), "--run-for-ms", "150"));
        // The trace speaks the model's own names.
        assertTrue(trace.received("class/motor-left.x.y", "class/none.in", false).size() >= 2, trace.output);
        assertTrue(trace.count("action class/none.switch.../up") >= 2, trace.output);
    }
}
