/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.daemon;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;

import org.rsaml.model.resource.ModelFormats;
import org.rsaml.report.ModelFiles;

/** The size of a command's inputs, for the resident process to send large ones to a JVM of their own. */
final class Inputs {

    private Inputs() {
    }

    /**
     * Whether the models that {@code args} name (relative to {@code workingDirectory}), and those a command finds below
     * the folders they name ({@link ModelFiles#modelsUnder}: model files only, hidden folders skipped), are together
     * larger than {@code limit} bytes. Arguments that are not models (options, formats, report files, output folders'
     * other files, a checkout's history) count nothing.
     */
    static boolean larger(Path workingDirectory, String[] args, long limit) {
        long total = 0;
        for (String arg : args) {
            if (arg.startsWith("-")) {
                continue;
            }
            try {
                Path path = workingDirectory.resolve(arg);
                if (Files.isDirectory(path)) {
                    for (Path model : ModelFiles.modelsUnder(path)) {
                        total += Files.size(model);
                    }
                } else if (ModelFormats.isModelFile(path.getFileName().toString()) && Files.isRegularFile(path)) {
                    total += Files.size(path);
                }
            } catch (IOException | UncheckedIOException | InvalidPathException | SecurityException | NullPointerException e) {
                // Unreadable, or no file name: the command says so, wherever it runs.
            }
            if (total > limit) {
                return true;
            }
        }
        return false;
    }
}
