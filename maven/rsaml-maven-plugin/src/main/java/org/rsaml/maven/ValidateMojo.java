/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.report.ModelBatch;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFiles;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.ReportOptions;
import org.rsaml.validation.Severity;

/**
 * Validates the project's RsaML models against every RsaML rule. Findings appear in the build log
 * in compiler style ({@code file:line:column: error RSA-08: ...}), reports are written under
 * {@code target/rsaml/}, and the build fails on findings at or above {@code failOn} and on models
 * that cannot be read.
 */
@Mojo(name = "validate", defaultPhase = LifecyclePhase.VERIFY, threadSafe = true)
public class ValidateMojo extends AbstractRsamlMojo {

    /** The directory searched for models. */
    @Parameter(property = "rsaml.modelDirectory", defaultValue = "${project.basedir}")
    File modelDirectory;

    /** Ant-style patterns, relative to {@code modelDirectory}, of the models to validate. */
    @Parameter
    List<String> includes = new ArrayList<>(List.of("**/*.rsaml"));

    /** Ant-style patterns of files to leave out; the build output folder is always left out. */
    @Parameter
    List<String> excludes = new ArrayList<>();

    /** Lowest severity that fails the build: {@code error}, {@code warning} or {@code never}. */
    @Parameter(property = "rsaml.failOn", defaultValue = "error")
    String failOn;

    /** Report files to write under {@code reportDirectory}: any of {@code sarif}, {@code junit}, {@code json}, {@code text}. */
    @Parameter(property = "rsaml.formats", defaultValue = "sarif,junit")
    List<String> formats;

    /** Where reports are written: {@code rsaml.sarif}, {@code TEST-rsaml.xml}, {@code rsaml.json}, {@code rsaml.txt}. */
    @Parameter(property = "rsaml.reportDirectory", defaultValue = "${project.build.directory}/rsaml")
    File reportDirectory;

    @Parameter(defaultValue = "${project.build.directory}", readonly = true, required = true)
    File buildDirectory;

    @Parameter(defaultValue = "${plugin.version}", readonly = true)
    String pluginVersion;

    @Override
    String goal() {
        return "validation";
    }

    @Override
    void run() throws MojoExecutionException, MojoFailureException {
        Log log = getLog();
        Severity threshold = failOn("failOn", failOn);
        List<ReportFormat> reportFormats = reportFormats();
        if (!modelDirectory.isDirectory()) {
            throw new MojoFailureException("RsaML model directory " + modelDirectory + " does not exist");
        }
        List<Path> models = ProjectPaths.models(baseDirectory, modelDirectory, buildDirectory, includes, excludes);
        if (models.isEmpty()) {
            log.warn("No RsaML models in " + relative(modelDirectory.toPath()) + " matching " + includes);
            return;
        }

        Path base = baseDirectory.toPath();
        Report report = ModelBatch.validate(base, models, threshold);
        log(report);
        ReportOptions options = new ReportOptions(pluginVersion, base, false);
        for (ReportFormat format : reportFormats) {
            Path file = reportDirectory.toPath().resolve(fileName(format));
            try {
                ReportFiles.write(file, format, report, options);
            } catch (IOException e) {
                throw new MojoExecutionException("Cannot write the RsaML " + format.id() + " report " + file + ": "
                        + ReportFiles.reason(e, file), e);
            }
        }
        log.info("RsaML: " + report.summary() + (reportFormats.isEmpty() ? "" : "; reports in " + relative(reportDirectory.toPath())));

        if (report.unreadable() > 0) {
            throw new MojoFailureException("RsaML could not read " + report.unreadable() + " model file"
                    + (report.unreadable() == 1 ? "" : "s") + "; see the errors above");
        }
        if (report.hasFailingFindings()) {
            throw new MojoFailureException("RsaML validation failed: " + report.summary() + " (failOn: " + failOn + ")");
        }
    }

    private List<ReportFormat> reportFormats() throws MojoExecutionException {
        List<ReportFormat> result = new ArrayList<>();
        for (String name : formats == null ? List.<String>of() : formats) {
            if (name.isBlank()) {
                continue;
            }
            try {
                result.add(ReportFormat.parse(name));
            } catch (IllegalArgumentException e) {
                throw new MojoExecutionException("formats: " + e.getMessage());
            }
        }
        return result;
    }

    static String fileName(ReportFormat format) {
        return switch (format) {
            case JUNIT -> "TEST-rsaml.xml";
            default -> "rsaml." + format.extension();
        };
    }
}
