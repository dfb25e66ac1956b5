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

import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code rsaml convert IN OUT}: the same model in the other syntax (.rsaml XMI, .rsa text). */
@Command(name = "convert", mixinStandardHelpOptions = true,
        description = "Converts a model between XMI (.rsaml) and text (.rsa), losslessly; OUT's extension chooses the syntax.",
        footer = { "", "Example: rsaml convert robot.rsaml robot.rsa" })
final class ConvertCommand extends RsamlCommand {

    @Parameters(index = "0", paramLabel = "IN", description = "The model to convert (.rsaml or .rsa).")
    Path input;

    @Parameters(index = "1", paramLabel = "OUT", description = "The file to write: .rsa for text, .rsaml for XMI.")
    Path output;

    @Override
    public Integer call() {
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
