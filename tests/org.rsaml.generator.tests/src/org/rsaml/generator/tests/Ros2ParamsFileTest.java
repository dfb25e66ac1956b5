/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * Generating again checks the architect's kept parameters file (config/&lt;pkg&gt;.params.yaml)
 * against the model: a value the file holds that differs from the model's (the architect changed a
 * period in the model, the file kept from before still overrides it) is a warning naming the file,
 * the line, the parameter, both values and how to fix it; so are a misspelt parameter name (which
 * ROS 2 would ignore), a section of a node the package does not have, and a file that is not YAML.
 * The file itself is never changed.
 */
class Ros2ParamsFileTest {

    private static final String PKG = "mobile_base";
    private static final String NODE = "navigation_path_planner";

    @TempDir
    Path tmp;
    private Path model;
    private Path out;
    private Path params;
    private final RsamlGenerator generator = new RsamlGenerator();

    @BeforeEach
    void generate() throws Exception {
        model = Files.copy(Tools.example("mobile-base-latency.rsaml"), tmp.resolve("base.rsaml"));
        out = tmp.resolve("ws");
        GenerationResult first = generator.generate(model, Target.ROS2, out, false);
        params = out.resolve(PKG + "/config/" + PKG + ".params.yaml");
        assertTrue(Files.isRegularFile(params), "no parameters file " + params);
        assertTrue(first.warnings().stream().noneMatch(w -> w.contains(".params.yaml")), "warnings about a fresh parameters file: " + first.warnings());
    }

    /** The line (from 1) of the file on which {@code text} starts. */
    private int lineOf(String text) throws Exception {
        String file = Files.readString(params);
        int at = file.indexOf(text);
        assertTrue(at >= 0, "no '" + text + "' in " + params + ":\n" + file);
        return (int) file.substring(0, at).chars().filter(c -> c == '\n').count() + 1;
    }

    private List<String> generateAgain() throws Exception {
        String before = Files.readString(params);
        GenerationResult again = generator.generate(model, Target.ROS2, out, false);
        assertEquals(before, Files.readString(params), "generating again changed the architect's parameters file");
        return again.warnings().stream().filter(w -> w.startsWith(PKG + "/config/" + PKG + ".params.yaml")).toList();
    }

    @Test
    void aPeriodChangedInTheModelThatTheKeptFileStillOverridesIsAWarning() throws Exception {
        String text = Files.readString(model);
        String changed = text.replace("period=\"100.0\" delay=\"100.0\"", "period=\"200.0\" delay=\"100.0\"");
        assertNotEquals(text, changed);
        Files.writeString(model, changed);
        int line = lineOf("    plan.period_ms: 100.0\n");
        List<String> warnings = generateAgain();
        String expected = PKG + "/config/" + PKG + ".params.yaml:" + line + ": node '" + NODE + "' parameter plan.period_ms is 100.0 in this file but 200.0"
                + " in the model";
        assertEquals(1, warnings.size(), "one warning about the parameters file: " + warnings);
        assertTrue(warnings.get(0).startsWith(expected) && warnings.get(0).contains("edit the line to 'plan.period_ms: 200.0' or delete it"),
                "expected a warning starting '" + expected + "' saying how to fix it: " + warnings);

        // Either fix ends the warning: the line set to the model's value (written as an integer), or deleted.
        Files.writeString(params, Files.readString(params).replace("    plan.period_ms: 100.0\n", "    plan.period_ms: 200\n"));
        assertEquals(List.of(), generateAgain(), "the file now says the model's value");
        Files.writeString(params, Files.readString(params).replace("    plan.period_ms: 200\n", ""));
        assertEquals(List.of(), generateAgain(), "the line is gone: the node takes the model's value");
    }

    @Test
    void aMisspeltParameterAnUnknownNodeAndAFileThatIsNotYamlAreWarnings() throws Exception {
        int line = lineOf("    plan.period_ms: 100.0\n");
        Files.writeString(params, Files.readString(params).replace("    plan.period_ms: 100.0\n", "    plan.perod_ms: 100.0\n"));
        List<String> warnings = generateAgain();
        assertTrue(warnings.size() == 1 && warnings.get(0).startsWith(PKG + "/config/" + PKG + ".params.yaml:" + line + ": node '" + NODE
                + "' has no parameter plan.perod_ms (its parameters: plan.period_ms") && warnings.get(0).endsWith("correct the name or remove the line"),
                "the misspelt name, its line and the node's parameters: " + warnings);

        Files.writeString(params, Files.readString(params).replace("    plan.perod_ms: 100.0\n", "    plan.period_ms: 100.0\n")
                .replace("    qos_overrides.speed_limit.publisher.reliability:", "    qos_overrides.speed_limt.publisher.reliability:"));
        warnings = generateAgain();
        assertTrue(warnings.size() == 1 && warnings.get(0).contains("has no parameter qos_overrides.speed_limt.publisher.reliability"),
                "a QoS override of a topic the node does not have: " + warnings);

        String text = Files.readString(params).replace("qos_overrides.speed_limt.", "qos_overrides.speed_limit.");
        Files.writeString(params, text + "navigation_path_planer:\n  ros__parameters:\n    plan.period_ms: 100.0\n");
        int section = (int) text.chars().filter(c -> c == '\n').count() + 1;
        warnings = generateAgain();
        assertTrue(warnings.size() == 1 && warnings.get(0).startsWith(PKG + "/config/" + PKG + ".params.yaml:" + section
                + ": there is no node 'navigation_path_planer' in this package (its nodes: "), "a section of a node the package lacks: " + warnings);

        Files.writeString(params, text.replace("    plan.period_ms: 100.0\n", "\tplan.period_ms: 100.0\n"));
        warnings = generateAgain();
        assertTrue(warnings.size() == 1 && warnings.get(0).startsWith(PKG + "/config/" + PKG + ".params.yaml:" + line + ": not YAML"),
                "a tab where YAML wants spaces, on line " + line + ": " + warnings);
    }
}
