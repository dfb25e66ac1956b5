/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;

import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.generator.GenerationException;
import org.rsaml.generator.GenerationRefusedException;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.validation.Finding;

/**
 * Generates the code skeleton of an RsaML model: a CMake C++17 project ({@code cpp}) or ROS 2
 * packages ({@code ros2}). Files under {@code gen/} are regenerated; the architect's files under
 * {@code src/} are created once and never overwritten. A model with error findings fails the build
 * (the findings are logged) unless {@code force} is set.
 */
@Mojo(name = "generate", defaultPhase = LifecyclePhase.GENERATE_SOURCES, threadSafe = true)
public class GenerateMojo extends AbstractMojo {

    /** The {@code .rsaml} model to generate from. */
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

    /** Skips generation. */
    @Parameter(property = "rsaml.skip", defaultValue = "false")
    boolean skip;

    @Parameter(defaultValue = "${project.basedir}", readonly = true, required = true)
    File baseDirectory;

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        Log log = getLog();
        if (skip) {
            log.info("Skipping RsaML generation (rsaml.skip)");
            return;
        }
        Target t;
        try {
            t = Target.parse(target);
        } catch (IllegalArgumentException e) {
            throw new MojoExecutionException("target: " + e.getMessage());
        }
        String shown = relative(model.toPath());
        GenerationResult result;
        try {
            result = new RsamlGenerator().generate(model.toPath(), shown, t, outputDirectory.toPath(), force);
        } catch (GenerationRefusedException e) {
            for (Finding finding : e.findings()) {
                log.error(finding.toString());
            }
            throw new MojoFailureException("RsaML generation refused: " + shown + " has " + e.errors().size()
                    + " error finding" + (e.errors().size() == 1 ? "" : "s") + "; fix them or set force");
        } catch (GenerationException e) {
            log.error(e.toString());
            throw new MojoFailureException("RsaML generation failed: " + e.getMessage());
        }
        for (Finding finding : result.findings()) {
            log.warn(finding.toString());
        }
        for (String warning : result.warnings()) {
            log.warn(shown + ": warning: " + warning);
        }
        log.info("RsaML: generated " + t.id() + " into " + relative(outputDirectory.toPath()) + ": "
                + result.written().size() + " written, " + result.unchanged().size() + " unchanged, "
                + result.preserved().size() + " of yours kept");
    }

    private String relative(Path path) {
        return ProjectPaths.relative(baseDirectory.toPath(), path);
    }
}
