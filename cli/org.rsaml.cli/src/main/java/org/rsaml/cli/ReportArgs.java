/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
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
import picocli.CommandLine.Model.OptionSpec;

/**
 * The report options of every command that checks models ({@code validate}, and any further
 * kind of check): what goes to standard output, which report files are written, what fails the run.
 */
final class ReportArgs {

    private final OptionSpec format = CommandSpecs.option(ReportFormat.class, "FORMAT", "-f", "--format").defaultValue("text")
            .description("Format written to standard output: text, json, sarif or junit (default: ${DEFAULT-VALUE}).").build();

    private final OptionSpec outputs = CommandSpecs.option(List.class, "FORMAT=FILE", "-o", "--output").auxiliaryTypes(String.class)
            .description("Also write a report in FORMAT to FILE (repeatable), e.g. sarif=target/rsaml.sarif.",
                    "A FILE alone takes its format from the extension (.sarif, .json, .xml, .txt).").build();

    private final OptionSpec failOn = CommandSpecs.option(FindingFailOn.class, "LEVEL", "--fail-on").defaultValue("error")
            .description("Lowest severity that makes the exit code 1: error, warning or never (default: ${DEFAULT-VALUE}).").build();

    private final OptionSpec quiet = CommandSpecs.flag("-q", "--quiet")
            .description("Text format: print only what fails the run (findings at or above --fail-on, unreadable inputs) "
                    + "and, when it fails, the summary line. Report files are complete.").build();

    private final CommandSpec spec;

    /** Adds the report options to {@code spec}, the command that checks models. */
    ReportArgs(CommandSpec spec) {
        this.spec = spec;
        spec.addOption(format).addOption(outputs).addOption(failOn).addOption(quiet);
    }

    ReportFormat format() {
        return format.getValue();
    }

    boolean quiet() {
        return CommandSpecs.given(quiet);
    }

    Severity threshold() {
        FindingFailOn level = failOn.getValue();
        return level.threshold();
    }

    /** The {@code --output} files, checked before any model is read. */
    Map<Path, ReportFormat> files() {
        Map<Path, ReportFormat> files = new LinkedHashMap<>();
        List<String> given = outputs.getValue();
        for (String output : given == null ? List.<String>of() : given) {
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
