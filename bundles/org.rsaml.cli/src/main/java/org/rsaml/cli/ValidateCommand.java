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
import java.util.concurrent.Callable;

import org.rsaml.cli.report.ExitCodes;
import org.rsaml.cli.report.FileResult;
import org.rsaml.cli.report.ReportFiles;
import org.rsaml.cli.report.ReportFormat;
import org.rsaml.cli.report.ReportOptions;
import org.rsaml.cli.report.ValidationReport;
import org.rsaml.validation.RsamlValidationSetup;
import org.rsaml.validation.Severity;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code rsaml validate PATH...}: checks models against every RsaML rule and reports the findings. */
@Command(name = "validate", mixinStandardHelpOptions = true, sortOptions = false,
        description = { "Validates .rsaml models against the RsaML rules (see 'rsaml rules').",
                "Directories are searched recursively for .rsaml files; every input is reported, "
                        + "also when another one cannot be read." },
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = { "0:clean: no finding at or above --fail-on",
                "1:findings at or above --fail-on",
                "2:usage error, or an input that could not be read" })
final class ValidateCommand implements Callable<Integer> {

    enum FailOn { error, warning, never }

    @Parameters(arity = "1..*", paramLabel = "PATH", description = "Model files and directories to validate.")
    List<Path> paths;

    @Option(names = { "-f", "--format" }, defaultValue = "text", paramLabel = "FORMAT",
            converter = FormatConverter.class,
            description = "Format written to standard output: text, json, sarif or junit (default: ${DEFAULT-VALUE}).")
    ReportFormat format;

    @Option(names = { "-o", "--output" }, paramLabel = "FORMAT=FILE",
            description = { "Also write a report in FORMAT to FILE (repeatable), e.g. sarif=target/rsaml.sarif.",
                    "A FILE alone takes its format from the extension (.sarif, .json, .xml, .txt)." })
    List<String> outputs = new ArrayList<>();

    @Option(names = "--fail-on", defaultValue = "error", paramLabel = "LEVEL",
            description = "Lowest severity that makes the exit code 1: error, warning or never (default: ${DEFAULT-VALUE}).")
    FailOn failOn;

    @Option(names = { "-q", "--quiet" }, description = "Text format: print errors only, and no summary line.")
    boolean quiet;

    @ParentCommand
    RsamlCli parent;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        // Parsing the rules takes longer than reading a few models: let the two overlap.
        RsamlValidationSetup.initInBackground();
        Map<Path, ReportFormat> files = reportFiles();
        Severity threshold = switch (failOn) {
            case error -> Severity.ERROR;
            case warning -> Severity.WARNING;
            case never -> null;
        };
        ValidationReport report = Validation.run(parent.workingDirectory, paths, threshold);
        ReportOptions options = new ReportOptions(RsamlCli.version(), parent.workingDirectory, quiet);

        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        for (FileResult result : report.results()) {
            if (result.readable()) {
                continue;
            }
            if (format != ReportFormat.TEXT) {
                // Structured output owns standard output; a person still reads input errors on standard error.
                err.println(result.error());
            }
            if (parent.debug && result.error().getCause() != null) {
                err.println(result.file() + ": cause of the error above:");
                result.error().getCause().printStackTrace(err);
            }
        }
        try {
            format.write(report, out, options);
        } catch (IOException e) {
            throw new RsamlCli.UserException("cannot write the report: " + e.getMessage());
        }
        out.flush();
        int code = report.exitCode();
        for (Map.Entry<Path, ReportFormat> file : files.entrySet()) {
            Path target = parent.workingDirectory.resolve(file.getKey());
            try {
                ReportFiles.write(target, file.getValue(), report, options);
            } catch (IOException e) {
                err.println(file.getKey() + ": error: cannot write the " + file.getValue().id() + " report: " + e.getMessage());
                code = ExitCodes.INPUT_ERROR;
            }
        }
        err.flush();
        return code;
    }

    private Map<Path, ReportFormat> reportFiles() {
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
                    fmt = byExtension(file);
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

    private static ReportFormat byExtension(String file) {
        String lower = file.toLowerCase(java.util.Locale.ROOT);
        for (ReportFormat f : ReportFormat.values()) {
            if (lower.endsWith("." + f.extension())) {
                return f;
            }
        }
        throw new IllegalArgumentException("cannot tell the format from the file name; write FORMAT=FILE");
    }

    static final class FormatConverter implements CommandLine.ITypeConverter<ReportFormat> {
        @Override
        public ReportFormat convert(String value) {
            try {
                return ReportFormat.parse(value);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }
}
