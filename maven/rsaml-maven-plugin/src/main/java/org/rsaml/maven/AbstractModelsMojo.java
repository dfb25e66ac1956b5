/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.Parameter;

/** A goal over the project's models: those under {@code modelDirectory} that match the patterns. */
abstract class AbstractModelsMojo extends AbstractRsamlMojo {

    /** The directory searched for models. */
    @Parameter(property = "rsaml.modelDirectory", defaultValue = "${project.basedir}")
    File modelDirectory;

    /** Ant-style patterns, relative to {@code modelDirectory}, of the models to take: XMI and textual models by default. */
    @Parameter
    List<String> includes = new ArrayList<>(List.of("**/*.rsaml", "**/*.rsa"));

    /** Ant-style patterns of files to leave out; the build output folder is always left out. */
    @Parameter
    List<String> excludes = new ArrayList<>();

    @Parameter(defaultValue = "${project.build.directory}", readonly = true, required = true)
    File buildDirectory;

    /** The models, relative to the project; empty (with a warning) when none matches. */
    List<Path> models() throws MojoFailureException {
        if (!modelDirectory.isDirectory()) {
            throw new MojoFailureException("RsaML model directory " + modelDirectory + " does not exist");
        }
        List<Path> models = ProjectPaths.models(baseDirectory, modelDirectory, buildDirectory, includes, excludes);
        if (models.isEmpty()) {
            getLog().warn("No RsaML models in " + relative(modelDirectory.toPath()) + " matching " + includes);
        }
        return models;
    }
}
