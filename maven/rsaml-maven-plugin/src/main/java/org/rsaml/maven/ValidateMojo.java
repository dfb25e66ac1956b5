/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.List;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.report.FindingFailOn;
import org.rsaml.report.ModelBatch;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFormat;

/**
 * Validates the project's RsaML models against every RsaML rule. Findings appear in the build log
 * in compiler style ({@code file:line:column: error RSA-08: ...}), reports are written under
 * {@code target/rsaml/}, and the build fails on findings at or above {@code failOn} and on models
 * that cannot be read.
 */
@Mojo(name = "validate", defaultPhase = LifecyclePhase.VERIFY, threadSafe = true)
public class ValidateMojo extends AbstractModelsMojo {

    /** Lowest severity that fails the build: {@code error}, {@code warning} or {@code never}. */
    @Parameter(property = "rsaml.failOn", defaultValue = "error")
    String failOn;

    /** Report files to write under {@code reportDirectory}: any of {@code sarif}, {@code junit}, {@code json}, {@code text}. */
    @Parameter(property = "rsaml.formats", defaultValue = "sarif,junit")
    List<String> formats;

    /** Where reports are written: {@code rsaml.sarif}, {@code TEST-rsaml.xml}, {@code rsaml.json}, {@code rsaml.txt}. */
    @Parameter(property = "rsaml.reportDirectory", defaultValue = "${project.build.directory}/rsaml")
    File reportDirectory;

    @Override
    String goal() {
        return "validation";
    }

    @Override
    void run() throws MojoExecutionException, MojoFailureException {
        Log log = getLog();
        FindingFailOn level = parameter("failOn", failOn, FindingFailOn::parse);
        List<ReportFormat> reportFormats = reportFormats("formats", formats);
        List<Path> models = models();
        if (models.isEmpty()) {
            return;
        }

        Path base = baseDirectory.toPath();
        Report report = ModelBatch.validate(base, models, level.threshold());
        log(report);
        writeReports(report, reportFormats, reportDirectory, format -> format.fileName("rsaml"));
        log.info("RsaML: " + report.summary(reportFormats.isEmpty() ? null : relative(reportDirectory.toPath())));

        String failure = report.failure();
        if (failure != null) {
            throw new MojoFailureException("RsaML " + failure);
        }
    }
}
