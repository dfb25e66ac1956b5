/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The package layouts on a real ROS 2 ({@link Ros2Jazzy}): a model with {@code packages perLayer}
 * and with {@code packages perProcessor}, generated, built with colcon (the runtime package before
 * the packages of nodes that link it, the package of the launch files last) and run as
 * {@link Ros2LaunchTest} runs the default layout: every node starts, loaded by a container of the
 * runtime package from its own package; every release runs at its period (one of them at the period
 * the parameters file of the launch files' package gives it); messages reach every connected port at
 * their publisher's rate; the topics the model names exist; each release's worst response is within
 * the analysis's bound plus the platform's allowance, as in the default layout (the containers of the
 * runtime package schedule the nodes of the other packages through the one shared runtime library);
 * everything exits cleanly on SIGINT. By
 * default the mobile base of examples/mobile-base-latency.rsaml in each of the two layouts; the
 * models {@code -Drsaml.ros2.examples} chooses for {@link Ros2LaunchTest} ({@code all}: every example
 * without errors, and its own models) run in both layouts too.
 */
class Ros2LayoutLaunchTest {

    static final List<String> LAYOUTS = List.of("perLayer", "perProcessor");

    static List<Arguments> runs() throws Exception {
        List<String> examples = Tools.option("rsaml.ros2.examples").isBlank() ? List.of(Ros2LaunchTest.TUNED) : Ros2LaunchTest.models();
        List<Arguments> runs = new ArrayList<>();
        for (String layout : LAYOUTS) {
            for (String example : examples) {
                runs.add(Arguments.of(layout, example));
            }
        }
        return runs;
    }

    private static final Pattern ARCHITECTURE = Pattern.compile("<rsaml:Architecture\\s");

    @ParameterizedTest
    @MethodSource("runs")
    void eachLayoutBuildsStartsAndRuns(String layout, String example, @TempDir Path tmp) throws Exception {
        String missing = Ros2Jazzy.missing();
        Assumptions.assumeTrue(missing == null, missing);
        String text = Files.readString(Ros2Test.model(example));
        Matcher m = ARCHITECTURE.matcher(text);
        assertTrue(m.find(), example + " has no architecture element");
        Path model = tmp.resolve(Path.of(example).getFileName().toString());
        Files.writeString(model, text.substring(0, m.end()) + "packages=\"" + layout + "\" " + text.substring(m.end()));
        System.out.println("Ros2LayoutLaunchTest: " + example + " with packages " + layout);
        long started = System.nanoTime();
        Ros2LaunchTest.run(model, example, tmp, src -> {
        });
        Tools.took("Ros2LayoutLaunchTest", example + " with packages " + layout + " generated, built, run and checked", started);
    }
}
