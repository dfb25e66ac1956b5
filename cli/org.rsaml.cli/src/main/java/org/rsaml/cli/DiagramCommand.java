/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;

import org.rsaml.report.ModelFiles;
import org.rsaml.report.DiagramBatch;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.TimingMode;
import org.rsaml.validation.RsamlValidationSetup;

import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/** {@code rsaml diagram [--view V] [--format F] -o DIR MODEL...}: each model drawn into DIR. */
final class DiagramCommand extends RsamlCommand {

    static final String NAME = "diagram";

    private final OptionSpec view = CommandSpecs.option(DiagramView.class, "VIEW", "--view").defaultValue("architecture")
            .description("architecture (layers, modules, ports, links, devices) or mission (missions, goals, plans, supervisors, orders); default ${DEFAULT-VALUE}.")
            .build();

    private final OptionSpec format = CommandSpecs.option(DiagramFormat.class, "FORMAT", "-f", "--format").defaultValue("svg")
            .description("svg or html; default ${DEFAULT-VALUE}.").build();

    private final OptionSpec timing = OptionSpec.builder("--timing").type(Boolean.class).negatable(true)
            .description("Draw the timing analysis over the architecture view: processors' utilisation, tasks' worst-case response",
                    "times and each latency requirement's worst path; --no-timing never draws it. Default: when the model deploys",
                    "modules on processors or states latency requirements.").build();

    private final OptionSpec output = CommandSpecs.option(Path.class, "DIR", "-o", "--output").required(true)
            .description("The directory the diagrams are written to (created if needed).").build();

    private final PositionalParamSpec models = CommandSpecs.paths(Path.class, "MODEL",
            "Model files, or directories searched for *.rsaml files.").build();

    DiagramCommand(RsamlCli parent) {
        super(parent, NAME, "Draws models laid out by the Eclipse Layout Kernel, as SVG images or as self-contained HTML pages",
                "(diagram, findings, timing, validation summary, pan and zoom; no network needed to open them).",
                "Each model is written to DIR/<model>-<view>.<svg|html>; findings decorate the elements they are on.");
        spec.usageMessage().sortOptions(false).footer("", "Example: rsaml diagram --format html -o target/diagrams models/");
        CommandSpecs.exitCodes(spec, "0:every diagram written (findings do not change the exit code; see 'rsaml validate')",
                "2:usage error, a model that cannot be read, or a diagram that cannot be written");
        spec.addOption(view).addOption(format).addOption(timing).addOption(output).addPositional(models);
        CommandSpecs.standardHelpOptions(spec);
    }

    @Override
    public Integer call() {
        RsamlValidationSetup.initInBackground();
        Path output = this.output.getValue();
        Boolean timing = this.timing.getValue();
        PrintWriter out = out();
        PrintWriter err = err();
        Path directory = parent.workingDirectory.resolve(output);
        DiagramBatch batch = new DiagramBatch(List.of((DiagramView) view.getValue()), List.of((DiagramFormat) format.getValue()),
                timing == null ? TimingMode.AUTO : timing ? TimingMode.ON : TimingMode.OFF);
        List<ModelFiles.Input> inputs = ModelFiles.select(parent.workingDirectory, models.getValue());
        batch.refusal(inputs, directory, output).ifPresent(refusal -> {
            throw new CommandLine.ParameterException(spec.commandLine(), refusal);
        });
        DiagramBatch.Outcome outcome = batch.draw(inputs, directory, new DiagramBatch.Listener() {
            @Override
            public void written(Path file) {
                out.println(DiagramBatch.wrote(output.resolve(file.getFileName())));
            }

            @Override
            public void failed(List<String> lines, Throwable cause) {
                lines.forEach(err::println);
                if (parent.debug() && cause != null) {
                    cause.printStackTrace(err);
                }
            }
        });
        out.flush();
        return outcome.exitCode();
    }
}
