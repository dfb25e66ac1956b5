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

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;

/** {@code rsaml validate PATH...}: checks models against every RsaML rule and reports the findings. */
@Command(name = "validate", mixinStandardHelpOptions = true, sortOptions = false,
        description = { "Validates .rsaml models against the RsaML rules (see 'rsaml rules').",
                "Directories are searched recursively for .rsaml files; every input is reported, "
                        + "also when another one cannot be read." },
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = { "0:clean: no finding at or above --fail-on",
                "1:findings at or above --fail-on",
                "2:usage error, or an input that could not be read" })
final class ValidateCommand extends RsamlCommand {

    @Parameters(arity = "1..*", paramLabel = "PATH", description = "Model files and directories to validate.")
    List<Path> paths;

    @Mixin
    ReportArgs report;

    @Override
    public Integer call() {
        // Parsing the rules takes longer than reading a few models: let the two overlap.
        RsamlValidationSetup.initInBackground();
        Map<Path, ReportFormat> files = report.files();
        Report result = ModelBatch.validate(parent.workingDirectory, paths, report.threshold());
        return ReportArgs.emit(result, report.format, files, report.quiet, parent, spec);
    }
}
