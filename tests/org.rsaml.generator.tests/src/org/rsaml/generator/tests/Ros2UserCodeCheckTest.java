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

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * A node class of the architect's kept from before entry ports held their message by shared pointer
 * reads {@code in_<port>.field}, which no longer compiles: generating again names each such line
 * (not a comment, a string, a read through the pointer, or the pointer's own methods) and says how to
 * write it, and leaves the file as it is.
 */
class Ros2UserCodeCheckTest {

    @Test
    void aReadOfAnEntryPortAsAValueIsAWarningNamingItsLine(@TempDir Path tmp) throws Exception {
        Path model = Files.copy(Tools.example("mobile-base-latency.rsaml"), tmp.resolve("base.rsaml"));
        Path out = tmp.resolve("ws");
        RsamlGenerator generator = new RsamlGenerator();
        generator.generate(model, Target.ROS2, out, false);
        String base = Files.readString(out.resolve("mobile_base/gen/control/VelocityControllerBase.hpp"));
        assertTrue(base.contains("std_msgs::msg::Float64::ConstSharedPtr in_speedLimit;"), base);
        Path source = out.resolve("mobile_base/src/control/VelocityController.cpp");
        String text = Files.readString(source);
        String old = "void VelocityController::on_speedLimit(const std_msgs::msg::Float64& message) { (void)message; }";
        assertTrue(text.contains(old), text);
        String mine = text.replace(old, String.join("\n",
                "void VelocityController::on_speedLimit(const std_msgs::msg::Float64& message) {",
                "  // in_speedLimit.data was the old way",
                "  const char* note = \"in_speedLimit.data\";",
                "  (void)note;",
                "  double limit = in_speedLimit.data;",
                "  if (in_speedLimit && in_speedLimit.get() != nullptr) { limit = in_speedLimit->data; }",
                "  (void)limit;",
                "  (void)message;",
                "}"));
        Files.writeString(source, mine);
        int line = (int) mine.substring(0, mine.indexOf("  double limit = in_speedLimit.data;")).chars().filter(c -> c == '\n').count() + 1;
        GenerationResult again = generator.generate(model, Target.ROS2, out, false);
        List<String> warnings = again.warnings().stream().filter(w -> w.contains("src/control/VelocityController")).toList();
        assertEquals(1, warnings.size(), "one line reads in_speedLimit as a value: " + again.warnings());
        assertTrue(warnings.get(0).startsWith("mobile_base/src/control/VelocityController.cpp:" + line + ": in_speedLimit.data: ")
                && warnings.get(0).contains("write in_speedLimit->data after checking if (in_speedLimit), or take each message in on_speedLimit"),
                "the file, the line and how to write it: " + warnings);
        assertEquals(mine, Files.readString(source), "generating again changed the architect's file");
    }
}
