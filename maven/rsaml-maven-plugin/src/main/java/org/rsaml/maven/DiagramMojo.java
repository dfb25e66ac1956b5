/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.TimingMode;
import org.rsaml.report.DiagramBatch;
import org.rsaml.report.ModelFiles;

/**
 * Draws the project's RsaML models, laid out by the Eclipse Layout Kernel, as SVG images and
 * self-contained HTML pages ({@code <model>-<view>.<format>} in {@code outputDirectory}); findings
 * decorate their elements. The build fails when a model cannot be read or a diagram cannot be
 * written, not because of findings (the {@code validate} goal judges those).
 */
@Mojo(name = "diagram", defaultPhase = LifecyclePhase.PREPARE_PACKAGE, threadSafe = true)
public class DiagramMojo extends AbstractModelsMojo {

    /** The views to draw: {@code architecture}, {@code mission}. */
    @Parameter(property = "rsaml.views", defaultValue = "architecture")
    List<String> views;

    /** The formats to write: {@code svg}, {@code html} (not named {@code formats}, which the validate goal uses for its reports). */
    @Parameter(property = "rsaml.diagramFormats", defaultValue = "svg,html")
    List<String> diagramFormats;

    /**
     * Whether the architecture view draws the timing analysis (processors' utilisation, tasks' response
     * times, latency requirements' worst paths): {@code auto} (when the model deploys modules on
     * processors or states latency requirements), {@code on} or {@code off}.
     */
    @Parameter(property = "rsaml.timing", defaultValue = "auto")
    String timing;

    /** Where the diagrams are written. */
    @Parameter(property = "rsaml.diagramDirectory", defaultValue = "${project.build.directory}/rsaml/diagrams")
    File outputDirectory;

    @Override
    String goal() {
        return "diagrams";
    }

    @Override
    void run() throws MojoExecutionException, MojoFailureException {
        Log log = getLog();
        List<DiagramView> diagramViews = new ArrayList<>();
        List<DiagramFormat> formats = new ArrayList<>();
        TimingMode timingMode = parameter("timing", timing, TimingMode::parse);
        for (String view : views) {
            if (!view.isBlank()) {
                diagramViews.add(parameter("views", view, DiagramView::parse));
            }
        }
        for (String format : diagramFormats) {
            if (!format.isBlank()) {
                formats.add(parameter("diagramFormats", format, DiagramFormat::parse));
            }
        }
        List<Path> models = models();
        if (models.isEmpty()) {
            return;
        }
        DiagramBatch batch = new DiagramBatch(diagramViews, formats, timingMode);
        List<ModelFiles.Input> inputs = ModelFiles.select(baseDirectory.toPath(), models);
        Optional<String> refusal = batch.refusal(inputs, outputDirectory.toPath(), Path.of(relative(outputDirectory.toPath())));
        if (refusal.isPresent()) {
            throw new MojoFailureException(refusal.get());
        }
        DiagramBatch.Outcome outcome = batch.draw(inputs, outputDirectory.toPath(), new DiagramBatch.Listener() {
            @Override
            public void written(Path file) {
                log.info("RsaML: " + DiagramBatch.wrote(Path.of(relative(file))));
            }

            @Override
            public void failed(List<String> lines, Throwable cause) {
                lines.forEach(log::error);
            }
        });
        if (outcome.failure() != null) {
            throw new MojoFailureException("RsaML " + outcome.failure());
        }
    }

}
