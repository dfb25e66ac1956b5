/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.rsaml.report.ModelBatch;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFormat;
import org.rsaml.validation.RsamlValidationSetup;

import picocli.CommandLine.Model.PositionalParamSpec;

/** {@code rsaml validate PATH...}: checks models against every RsaML rule and reports the findings. */
final class ValidateCommand extends RsamlCommand {

    static final String NAME = "validate";

    private final PositionalParamSpec paths = CommandSpecs.paths(Path.class, "PATH", "Model files and directories to validate.").build();

    private final ReportArgs report;

    ValidateCommand(RsamlCli parent) {
        super(parent, NAME, "Validates .rsaml models against the RsaML rules (see 'rsaml rules').",
                "Directories are searched recursively for .rsaml files; every input is reported, "
                        + "also when another one cannot be read.");
        spec.usageMessage().sortOptions(false);
        CommandSpecs.exitCodes(spec, CommandSpecs.VALIDATION_EXIT_CODES);
        spec.addPositional(paths);
        report = new ReportArgs(spec);
        CommandSpecs.standardHelpOptions(spec);
    }

    @Override
    public Integer call() {
        // Parsing the rules takes longer than reading a few models: let the two overlap.
        RsamlValidationSetup.initInBackground();
        Map<Path, ReportFormat> files = report.files();
        List<Path> inputs = paths.getValue();
        Report result = ModelBatch.validate(parent.workingDirectory, inputs, report.threshold());
        return ReportArgs.emit(result, report.format(), files, report.quiet(), parent, spec);
    }
}
