/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.util.List;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.generator.Target;
import org.rsaml.report.Generation;
import org.rsaml.report.Text;

/**
 * Generates the code skeleton of an RsaML model: a CMake C++17 project ({@code cpp}) or ROS 2
 * packages ({@code ros2}). Files under {@code gen/} are regenerated; the architect's files under
 * {@code src/} are created once and never overwritten. A model with error findings fails the build
 * (the findings are logged) unless {@code force} is set.
 */
@Mojo(name = "generate", defaultPhase = LifecyclePhase.GENERATE_SOURCES, threadSafe = true)
public class GenerateMojo extends AbstractRsamlMojo {

    /** The model ({@code .rsaml} or textual {@code .rsa}) to generate from. */
    @Parameter(property = "rsaml.model", required = true)
    File model;

    /** {@code cpp} or {@code ros2}. */
    @Parameter(property = "rsaml.target", required = true)
    String target;

    /** The project directory to create or update (kept under version control: it holds the architect's code). */
    @Parameter(property = "rsaml.outputDirectory", required = true)
    File outputDirectory;

    /** Generate even when the model has error findings. */
    @Parameter(property = "rsaml.force", defaultValue = "false")
    boolean force;

    @Override
    String goal() {
        return "generation";
    }

    @Override
    void run() throws MojoExecutionException, MojoFailureException {
        Log log = getLog();
        Target t;
        try {
            t = Target.parse(target);
        } catch (IllegalArgumentException e) {
            throw new MojoExecutionException("target: " + e.getMessage());
        }
        String shown = relative(model.toPath());
        Generation.Outcome outcome = Generation.run(model.toPath(), shown, t, outputDirectory.toPath(), force, "set force");
        log(outcome.report());
        for (String warning : outcome.warnings(shown)) {
            log.warn(Text.line(warning));
        }
        if (!outcome.errors().isEmpty()) {
            if (log.isDebugEnabled() && outcome.cause() != null) {
                log.debug(outcome.cause());
            }
            // The command line's first line: refused for error findings, or why the model or output is unusable
            // (a model's further load errors were logged with the report).
            List<String> errors = outcome.errors();
            throw new MojoFailureException("RsaML: " + errors.get(0)
                    + (errors.size() > 1 ? " (and " + (errors.size() - 1) + " more errors, listed above)" : ""));
        }
        log.info("RsaML: " + Text.line(outcome.summary(relative(outputDirectory.toPath()))));
    }
}
