/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.TimingText;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.TimingBatch;
import org.rsaml.report.TimingFailOn;
import org.rsaml.report.TimingJson;

/**
 * Analyses the timing of RsaML models as the generated runtime runs them (docs/timing.md): the
 * build fails when a deadline or a latency requirement can be missed (with {@code failOn} not-analysed,
 * also when anything is not analysed; {@link TimingFailOn} decides, as for rsaml analyze); the verdicts, with their
 * witnesses, are logged, and the timing rules' findings ({@code rsaml rules} lists them) are written as reports
 * ({@code target/rsaml/rsaml-timing.sarif}, {@code TEST-rsaml-timing.xml}) by the writers validate uses;
 * {@code timingJson} names a file for the verdicts as JSON, as {@code rsaml analyze --format json} prints them.
 * A model that cannot be read or analysed fails the build whatever {@code failOnMiss} says, after
 * the reports are written, as {@code rsaml analyze} exits 2 for it in every format.
 */
@Mojo(name = "analyze", defaultPhase = LifecyclePhase.VERIFY, threadSafe = true)
public class AnalyzeMojo extends AbstractRsamlMojo {

    /** The models ({@code .rsaml} or textual {@code .rsa}) to analyse. */
    @Parameter(property = "rsaml.models", required = true)
    List<File> models = new ArrayList<>();

    /** A directory for an SVG timeline of each witness: missed deadline, overloaded EDF interval, exceeded latency requirement (none when not set). */
    @Parameter(property = "rsaml.timeline")
    File timeline;

    /**
     * A file for the verdicts and witnesses as JSON, the document {@code rsaml analyze --format json} prints
     * (none when not set).
     */
    @Parameter(property = "rsaml.analysis.timingJson")
    File timingJson;

    /** Log the verdicts but do not fail the build on them (false: whatever {@code failOn} says, the verdicts only fail the reports' entries). */
    @Parameter(property = "rsaml.analysis.failOnMiss", defaultValue = "true")
    boolean failOnMiss;

    /**
     * Which verdicts fail the build, as {@code rsaml analyze --fail-on} decides its exit code: {@code miss}
     * (a deadline or a latency requirement can be missed), {@code not-analysed} (also anything not
     * analysed: only a proven model passes) or {@code never}.
     */
    @Parameter(property = "rsaml.analysis.failOn", defaultValue = "miss")
    String failOn;

    /** Report formats (text, json, sarif, junit) of the timing rules' findings; empty for none. */
    @Parameter(property = "rsaml.analysis.formats", defaultValue = "sarif,junit")
    List<String> formats;

    /** Where the reports are written. */
    @Parameter(property = "rsaml.reportDirectory", defaultValue = "${project.build.directory}/rsaml")
    File reportDirectory;

    @Override
    String goal() {
        return "timing analysis";
    }

    @Override
    void run() throws MojoExecutionException, MojoFailureException {
        Log log = getLog();
        List<ReportFormat> reportFormats = reportFormats("formats", formats);
        TimingFailOn level = parameter("failOn", failOn, TimingFailOn::parse);
        // failOnMiss false: the verdicts fail nothing in the build, as under failOn never (the reports still fail as failOn says).
        TimingFailOn build = failOnMiss ? level : TimingFailOn.NEVER;
        List<Path> shown = models.stream().map(model -> Path.of(relative(model.toPath()))).toList();
        TimingBatch.Request request = new TimingBatch.Request(timeline == null ? null : Path.of(relative(timeline.toPath())), level,
                timingJson != null, !reportFormats.isEmpty());
        TimingBatch.Outcome outcome = TimingBatch.run(baseDirectory.toPath(), shown, request, new TimingBatch.Listener() {
            @Override
            public void analysed(String displayName, ArchitectureTiming timing) {
                TimingText.render(displayName, timing).lines().forEach(logAt(build.shown(timing.verdict())));
            }

            @Override
            public void unanalysable(List<String> lines) {
                lines.forEach(log::error);
            }

            @Override
            public void timeline(Path file, String line) {
                log.info("RsaML: " + line);
            }

            @Override
            public void noTimeline(String displayName, String line) {
                log.info("RsaML: " + line);
            }

            @Override
            public void timelineFailed(String line) {
                log.error(line);
            }
        });
        if (outcome.json() != null) {
            String failure = outcome.json().writeTo(baseDirectory.toPath(), Path.of(relative(timingJson.toPath())));
            if (failure != null) {
                log.error(failure);
                throw new MojoExecutionException("RsaML timing: " + failure);
            }
            log.info("RsaML: " + TimingJson.Document.written(Path.of(relative(timingJson.toPath()))));
        }
        if (outcome.findings() != null) {
            writeReports(outcome.findings(), reportFormats, reportDirectory, format -> format.fileName("rsaml-timing"));
            log.info("RsaML: " + outcome.findingsSummary(relative(reportDirectory.toPath())));
        }
        if (outcome.outputFailure() != null) {
            throw new MojoExecutionException("RsaML timing: " + outcome.outputFailure());
        }
        if (outcome.inputFailure() != null) {
            throw new MojoFailureException("RsaML timing: " + outcome.inputFailure());
        }
        if (build != TimingFailOn.NEVER && outcome.verdictFailure() != null) {
            throw new MojoFailureException("RsaML timing: " + outcome.verdictFailure());
        }
    }
}
