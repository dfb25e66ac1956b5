/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.rsaml.cli.report.ExitCodes;
import org.rsaml.generator.GenerationException;
import org.rsaml.generator.GenerationRefusedException;
import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlValidationSetup;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code rsaml generate --target cpp|ros2 -o DIR MODEL}: the code skeleton of a valid model. */
@Command(name = "generate", mixinStandardHelpOptions = true, sortOptions = false,
        description = { "Generates the code skeleton of a model: a CMake C++17 project (cpp) or ROS 2 packages (ros2).",
                "Files under gen/ are regenerated each time; your files under src/ are created once and never overwritten.",
                "A model with error findings is refused (see 'rsaml validate'); --force generates anyway." },
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = { "0:generated", "1:refused: the model has error findings",
                "2:usage error, a model that cannot be read, or output that cannot be written" })
final class GenerateCommand implements Callable<Integer> {

    @Option(names = { "-t", "--target" }, required = true, paramLabel = "TARGET", converter = TargetConverter.class,
            description = "cpp (CMake C++17 project) or ros2 (ament_cmake packages).")
    Target target;

    @Option(names = { "-o", "--output" }, required = true, paramLabel = "DIR",
            description = "The project directory to create or update.")
    Path output;

    @Option(names = "--force", description = "Generate even when the model has error findings.")
    boolean force;

    @Parameters(arity = "1", paramLabel = "MODEL", description = "The .rsaml model.")
    Path model;

    @ParentCommand
    RsamlCli parent;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        RsamlValidationSetup.initInBackground();
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        String shown = ModelFiles.display(model);
        GenerationResult result;
        try {
            result = new RsamlGenerator().generate(parent.workingDirectory.resolve(model), shown, target,
                    parent.workingDirectory.resolve(output), force);
        } catch (GenerationRefusedException e) {
            for (Finding finding : e.findings()) {
                out.println(finding);
            }
            err.println(shown + ": error: generation refused: the model has " + e.errors().size() + " error finding"
                    + (e.errors().size() == 1 ? "" : "s") + "; fix " + (e.errors().size() == 1 ? "it" : "them")
                    + " or generate anyway with --force");
            return ExitCodes.FINDINGS;
        } catch (GenerationException e) {
            err.println(e);
            if (parent.debug && e.getCause() != null) {
                e.getCause().printStackTrace(err);
            }
            return ExitCodes.INPUT_ERROR;
        }
        for (Finding finding : result.findings()) {
            out.println(finding);
        }
        for (String warning : result.warnings()) {
            out.println(shown + ": warning: " + warning);
        }
        out.println("generated " + target.id() + " into " + ModelFiles.display(output) + ": "
                + result.written().size() + " written, " + result.unchanged().size() + " unchanged, "
                + result.preserved().size() + " of yours kept" + (result.deleted().isEmpty() ? "" : ", " + result.deleted().size() + " obsolete removed"));
        out.flush();
        return ExitCodes.OK;
    }

    static final class TargetConverter implements CommandLine.ITypeConverter<Target> {
        @Override
        public Target convert(String value) {
            try {
                return Target.parse(value);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }
}
