/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.report.FindingFailOn;
import org.rsaml.report.FileResult;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFiles;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.ReportOptions;
import org.rsaml.report.Text;
import org.rsaml.validation.Severity;

import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * The report options of every command that checks models ({@code validate}, and any further
 * kind of check): what goes to standard output, which report files are written, what fails the run.
 */
final class ReportArgs {

    @Option(names = { "-f", "--format" }, defaultValue = "text", paramLabel = "FORMAT",
            description = "Format written to standard output: text, json, sarif or junit (default: ${DEFAULT-VALUE}).")
    ReportFormat format;

    @Option(names = { "-o", "--output" }, paramLabel = "FORMAT=FILE",
            description = { "Also write a report in FORMAT to FILE (repeatable), e.g. sarif=target/rsaml.sarif.",
                    "A FILE alone takes its format from the extension (.sarif, .json, .xml, .txt)." })
    List<String> outputs = new ArrayList<>();

    @Option(names = "--fail-on", defaultValue = "error", paramLabel = "LEVEL",
            description = "Lowest severity that makes the exit code 1: error, warning or never (default: ${DEFAULT-VALUE}).")
    FindingFailOn failOn;

    @Option(names = { "-q", "--quiet" },
            description = "Text format: print only what fails the run (findings at or above --fail-on, unreadable inputs) "
                    + "and, when it fails, the summary line. Report files are complete.")
    boolean quiet;

    @Spec(Spec.Target.MIXEE)
    CommandSpec spec;

    Severity threshold() {
        return failOn.threshold();
    }

    /** The {@code --output} files, checked before any model is read. */
    Map<Path, ReportFormat> files() {
        Map<Path, ReportFormat> files = new LinkedHashMap<>();
        for (String output : outputs) {
            int eq = output.indexOf('=');
            ReportFormat fmt;
            String file;
            try {
                if (eq > 0) {
                    fmt = ReportFormat.parse(output.substring(0, eq));
                    file = output.substring(eq + 1);
                } else {
                    file = output;
                    fmt = ReportFormat.ofFileName(file);
                }
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(spec.commandLine(), "--output " + output + ": " + e.getMessage());
            }
            if (file.isBlank()) {
                throw new CommandLine.ParameterException(spec.commandLine(), "--output " + output + ": no file name");
            }
            files.put(Path.of(file), fmt);
        }
        return files;
    }

    /**
     * Writes {@code report} to standard output and to the report files.
     *
     * @return the exit code: the report's, or 2 when a report file cannot be written
     */
    static int emit(Report report, ReportFormat format, Map<Path, ReportFormat> files, boolean quiet, RsamlCli cli,
            CommandSpec spec) {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        for (FileResult result : report.results()) {
            if (result.readable()) {
                continue;
            }
            if (format != ReportFormat.TEXT) {
                // Structured output owns standard output; a person still reads input errors on standard error.
                Text.lines(result.error()).forEach(err::println);
            }
            cli.printCause(err, result.file(), result.error().getCause());
        }
        ReportOptions options = new ReportOptions(RsamlCli.version(), cli.workingDirectory, quiet);
        try {
            format.write(report, out, options);
        } catch (IOException e) {
            throw new RsamlCli.UserException("cannot write the report: " + e.getMessage());
        }
        out.flush();
        List<String> failures = ReportFiles.writeAll(report, files, cli.workingDirectory, options);
        failures.forEach(err::println);
        int code = ReportFiles.exitCode(report, failures);
        err.flush();
        return code;
    }
}
