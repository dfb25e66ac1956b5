/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;

import org.rsaml.report.ExitCodes;
import org.rsaml.report.ModelFiles;
import org.rsaml.report.Text;
import org.rsaml.text.convert.ModelConverter;
import org.rsaml.validation.ModelLoadException;

import picocli.CommandLine.Model.PositionalParamSpec;

/** {@code rsaml convert IN OUT}: the same model in the other syntax (.rsaml XMI, .rsa text). */
final class ConvertCommand extends RsamlCommand {

    static final String NAME = "convert";

    private final PositionalParamSpec input = CommandSpecs.parameter("0", Path.class, "IN",
            "The model to convert (.rsaml or .rsa).").build();

    private final PositionalParamSpec output = CommandSpecs.parameter("1", Path.class, "OUT",
            "The file to write: .rsa for text, .rsaml for XMI.").build();

    ConvertCommand(RsamlCli parent) {
        super(parent, NAME, "Converts a model between XMI (.rsaml) and text (.rsa), losslessly; OUT's extension chooses the syntax.");
        spec.usageMessage().footer("", "Example: rsaml convert robot.rsaml robot.rsa");
        spec.addPositional(input).addPositional(output);
        CommandSpecs.standardHelpOptions(spec);
    }

    @Override
    public Integer call() {
        Path input = this.input.getValue();
        Path output = this.output.getValue();
        PrintWriter out = out();
        PrintWriter err = err();
        Path in = parent.workingDirectory.resolve(input);
        Path target = parent.workingDirectory.resolve(output);
        String shownIn = ModelFiles.display(input);
        String shownOut = ModelFiles.display(output);
        try {
            ModelConverter.convert(in, shownIn, target);
        } catch (ModelLoadException e) {
            Text.lines(e).forEach(err::println);
            parent.printCause(err, shownIn, e.getCause());
            return ExitCodes.INPUT_ERROR;
        } catch (IOException e) {
            err.println(Text.line(shownOut + ": error: cannot be written: " + e.getMessage()));
            return ExitCodes.INPUT_ERROR;
        }
        out.println("wrote " + shownOut);
        out.flush();
        return ExitCodes.OK;
    }
}
