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

import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/** {@code rsaml generate --target cpp|ros2 -o DIR MODEL}: the code skeleton of a valid model. */
final class GenerateCommand extends RsamlCommand {

    static final String NAME = "generate";

    private final OptionSpec target = CommandSpecs.option(Target.class, "TARGET", "-t", "--target").required(true)
            .description("cpp (CMake C++17 project) or ros2 (ament_cmake packages).").build();

    private final OptionSpec output = CommandSpecs.option(Path.class, "DIR", "-o", "--output").required(true)
            .description("The project directory to create or update.").build();

    private final OptionSpec force = CommandSpecs.flag("--force")
            .description("Generate even when the model has error findings.").build();

    private final OptionSpec format = CommandSpecs.option(ReportFormat.class, "FORMAT", "-f", "--format").defaultValue("text")
            .description("Format of the model's findings on standard output: text, json, sarif or junit (default: ${DEFAULT-VALUE}).")
            .build();

    private final PositionalParamSpec model = CommandSpecs.parameter("0", Path.class, "MODEL", "The .rsaml model.").build();

    GenerateCommand(RsamlCli parent) {
        super(parent, NAME, "Generates the code skeleton of a model: a CMake C++17 project (cpp) or ROS 2 packages (ros2).",
                "Files under gen/ are regenerated each time; your files under src/ are created once and never overwritten.",
                "A model with error findings is refused (see 'rsaml validate'); --force generates anyway.");
        spec.usageMessage().sortOptions(false);
        CommandSpecs.exitCodes(spec, "0:generated", "1:refused: the model has error findings",
                "2:usage error, a model that cannot be read, or output that cannot be written");
        spec.addOption(target).addOption(output).addOption(force).addOption(format).addPositional(model);
        CommandSpecs.standardHelpOptions(spec);
    }

    @Override
    public Integer call() {
        RsamlValidationSetup.initInBackground();
        Path model = this.model.getValue();
        Path output = this.output.getValue();
        ReportFormat format = this.format.getValue();
        PrintWriter out = out();
        PrintWriter err = err();
        String shown = ModelFiles.display(model);
        Generation.Outcome outcome = Generation.run(parent.workingDirectory.resolve(model), shown, target.getValue(),
                parent.workingDirectory.resolve(output), CommandSpecs.given(force), "generate anyway with --force");
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
