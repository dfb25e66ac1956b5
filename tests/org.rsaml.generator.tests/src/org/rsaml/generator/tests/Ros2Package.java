/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import java.nio.file.Path;
import java.util.Map;

import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.generator.internal.Names;
import org.rsaml.validation.ModelLoader;

/**
 * The ROS 2 package of a model, generated under {@code <work>/src} and built with colcon against the real ROS 2
 * ({@link Ros2Jazzy}) into {@code install}: its name {@code pkg} and the node of each module ({@code nodes}, by
 * layer/module).
 */
record Ros2Package(Path src, Path install, String pkg, Map<String, String> nodes) {

    /** What a test changes in the generated package (its folder) before it is built. */
    interface Edit {
        void apply(Path packageFolder) throws Exception;
    }

    /** Generates {@code model} (as {@link Ros2Test#model} names it), lets {@code edit} change it, and builds it; says how long it took. */
    static Ros2Package of(String model, Path work, String test, Edit edit) throws Exception {
        long started = System.nanoTime();
        Path file = Ros2Test.model(model);
        String pkg = Names.snake(ModelLoader.load(file, file.getFileName().toString()).architecture().getName());
        Path src = work.resolve("src");
        new RsamlGenerator().generate(file, Target.ROS2, src, false);
        edit.apply(src.resolve(pkg));
        Ros2Package built = new Ros2Package(src, Ros2Jazzy.colconBuild(src, work), pkg, Ros2Test.nodes(src.resolve(pkg)));
        Tools.took(test, "generated and built", started);
        return built;
    }
}
