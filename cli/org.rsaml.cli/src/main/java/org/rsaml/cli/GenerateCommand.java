/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;

import org.rsaml.generator.Target;
import org.rsaml.report.Generation;
import org.rsaml.report.ModelFiles;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.ReportOptions;
import org.rsaml.report.Text;
import org.rsaml.validation.RsamlValidationSetup;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code rsaml generate --target cpp|ros2 -o DIR MODEL}: the code skeleton of a valid model. */
@Command(name = "generate", mixinStandardHelpOptions = true, sortOptions = false,
        description = { "Generates the code skeleton of a model: a CMake C++17 project (cpp) or ROS 2 packages (ros2).",
                "Files under gen/ are regenerated each time; your files under src/ are created once and never overwritten.",
                "A model with error findings is refused (see 'rsaml validate'); --force generates anyway." },
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = { "0:generated", "1:refused: the model has error findings",
                "2:usage error, a model that cannot be read, or output that cannot be written" })
final class GenerateCommand extends RsamlCommand {

    @Option(names = { "-t", "--target" }, required = true, paramLabel = "TARGET",
            description = "cpp (CMake C++17 project) or ros2 (ament_cmake packages).")
    Target target;

    @Option(names = { "-o", "--output" }, required = true, paramLabel = "DIR",
            description = "The project directory to create or update.")
    Path output;

    @Option(names = "--force", description = "Generate even when the model has error findings.")
    boolean force;

    @Option(names = { "-f", "--format" }, defaultValue = "text", paramLabel = "FORMAT",
            description = "Format of the model's findings on standard output: text, json, sarif or junit (default: ${DEFAULT-VALUE}).")
    ReportFormat format;

    @Parameters(arity = "1", paramLabel = "MODEL", description = "The .rsaml model.")
    Path model;

    @Override
    public Integer call() {
        RsamlValidationSetup.initInBackground();
        PrintWriter out = out();
        PrintWriter err = err();
        String shown = ModelFiles.display(model);
        Generation.Outcome outcome = Generation.run(parent.workingDirectory.resolve(model), shown, target,
                parent.workingDirectory.resolve(output), force, "generate anyway with --force");
        if (outcome.showsReport(format)) {
            try {
                format.write(outcome.report(), out, new ReportOptions(RsamlCli.version(), parent.workingDirectory, false));
            } catch (IOException e) {
                throw new RsamlCli.UserException("cannot write the report: " + e.getMessage());
            }
        }
        PrintWriter notes = format == ReportFormat.TEXT ? out : err;
        for (String warning : outcome.warnings(shown)) {
            notes.println(Text.line(warning));
        }
        if (!outcome.errors().isEmpty()) {
            outcome.errors().forEach(err::println);
            parent.printCause(err, shown, outcome.cause());
        } else {
            notes.println(Text.line(outcome.summary(ModelFiles.display(output))));
        }
        out.flush();
        err.flush();
        return outcome.exitCode();
    }
}
