/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.Function;

import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.report.FileResult;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFiles;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.ReportOptions;
import org.rsaml.report.Text;
import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;

/** What every RsaML goal shares: {@code skip}, the project's paths, fail-on levels, findings in the build log. */
abstract class AbstractRsamlMojo extends AbstractMojo {

    /** Skips the goal. */
    @Parameter(property = "rsaml.skip", defaultValue = "false")
    boolean skip;

    @Parameter(defaultValue = "${project.basedir}", readonly = true, required = true)
    File baseDirectory;

    @Parameter(defaultValue = "${plugin.version}", readonly = true)
    String pluginVersion;

    @Override
    public final void execute() throws MojoExecutionException, MojoFailureException {
        if (skip) {
            getLog().info("Skipping RsaML " + goal() + " (rsaml.skip)");
            return;
        }
        run();
    }

    /** The goal's name, as the skip message says it. */
    abstract String goal();

    abstract void run() throws MojoExecutionException, MojoFailureException;

    /** Paths as the build log shows them: relative to the project when inside it, with forward slashes. */
    String relative(Path path) {
        return ProjectPaths.relative(baseDirectory.toPath(), path);
    }

    /**
     * The value of a goal's {@code parameter} as the report bundle's {@code parser} reads it (a fail-on level, a report
     * format); a value it refuses stops the build, named by the parameter.
     */
    static <T> T parameter(String parameter, String value, Function<String, T> parser) throws MojoExecutionException {
        try {
            return parser.apply(value);
        } catch (IllegalArgumentException e) {
            throw new MojoExecutionException(parameter + ": " + e.getMessage());
        }
    }

    /** Every input error and finding of {@code report}, one safe line each, at its severity. */
    void log(Report report) {
        Log log = getLog();
        for (FileResult result : report.results()) {
            if (!result.readable()) {
                Text.lines(result.error()).forEach(log::error);
                if (log.isDebugEnabled() && result.error().getCause() != null) {
                    log.debug(Text.line(result.file() + ": cause of the error above:"), result.error().getCause());
                }
            }
            for (Finding finding : result.findings()) {
                logAt(finding.severity()).accept(Text.line(finding.toString()));
            }
        }
    }

    /** The build log's method for lines of {@code severity}: a finding's, or how a verdict is shown. */
    Consumer<CharSequence> logAt(Severity severity) {
        Log log = getLog();
        return switch (severity) {
            case ERROR -> log::error;
            case WARNING -> log::warn;
            case INFO -> log::info;
        };
    }

    /** The report formats a goal's {@code parameter} names; blank entries are ignored. */
    static List<ReportFormat> reportFormats(String parameter, List<String> names) throws MojoExecutionException {
        List<ReportFormat> result = new ArrayList<>();
        for (String name : names == null ? List.<String>of() : names) {
            if (name.isBlank()) {
                continue;
            }
            result.add(parameter(parameter, name, ReportFormat::parse));
        }
        return result;
    }

    /** Writes {@code report} in each format into {@code directory}, named by {@code fileName}. */
    void writeReports(Report report, List<ReportFormat> formats, File directory, Function<ReportFormat, String> fileName)
            throws MojoExecutionException {
        Map<Path, ReportFormat> files = new LinkedHashMap<>();
        for (ReportFormat format : formats) {
            files.put(Path.of(relative(directory.toPath().resolve(fileName.apply(format)))), format);
        }
        List<String> failures = ReportFiles.writeAll(report, files, baseDirectory.toPath(),
                new ReportOptions(pluginVersion, baseDirectory.toPath(), false));
        failures.forEach(getLog()::error);
        String failure = ReportFiles.failure(failures);
        if (failure != null) {
            throw new MojoExecutionException("RsaML: " + failure);
        }
    }
}
