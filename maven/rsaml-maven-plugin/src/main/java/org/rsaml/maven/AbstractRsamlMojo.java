/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.Locale;

import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.report.FileResult;
import org.rsaml.report.Report;
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
        Path base = baseDirectory.toPath().toAbsolutePath().normalize();
        Path p = path.toAbsolutePath().normalize();
        return (p.startsWith(base) && !p.equals(base) ? base.relativize(p) : p).toString().replace('\\', '/');
    }

    /** {@code error}, {@code warning} or {@code never} (then {@code null}: findings never fail the build). */
    static Severity failOn(String parameter, String value) throws MojoExecutionException {
        return switch (value == null ? "" : value.trim().toLowerCase(Locale.ROOT)) {
            case "error" -> Severity.ERROR;
            case "warning" -> Severity.WARNING;
            case "never" -> null;
            default -> throw new MojoExecutionException(parameter + " must be error, warning or never, not '" + value + "'");
        };
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
                String line = Text.line(finding.toString());
                switch (finding.severity()) {
                    case ERROR -> log.error(line);
                    case WARNING -> log.warn(line);
                    case INFO -> log.info(line);
                }
            }
        }
    }
}
