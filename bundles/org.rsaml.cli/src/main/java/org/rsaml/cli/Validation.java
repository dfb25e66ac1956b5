/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.cli.report.FileResult;
import org.rsaml.cli.report.ValidationReport;
import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Severity;

/**
 * Validates every model a user named, each on its own: a file that cannot be read is reported and
 * the others are still validated. Shared by the command line and the Maven plugin.
 */
public final class Validation {

    private Validation() {
    }

    /** Validates the named files and directories, relative ones resolved against {@code base}. */
    public static ValidationReport run(Path base, List<Path> paths, Severity failOn) {
        List<FileResult> results = new ArrayList<>();
        for (ModelFiles.Input input : ModelFiles.select(base, paths)) {
            results.add(input.unusable() != null ? FileResult.unreadable(input.unusable(), 0) : validate(input));
        }
        return new ValidationReport(results, failOn);
    }

    private static FileResult validate(ModelFiles.Input input) {
        long start = System.nanoTime();
        try {
            List<Finding> findings = RsamlModelValidator.validate(input.path(), input.displayName());
            return FileResult.of(input.displayName(), findings, seconds(start));
        } catch (ModelLoadException e) {
            return FileResult.unreadable(e, seconds(start));
        } catch (OutOfMemoryError e) {
            // Validation of a model that only just loaded; the memory is free again once it is dropped.
            return FileResult.unreadable(new ModelLoadException(input.displayName(), 0, 0,
                    "the model is too large for the available heap (" + Runtime.getRuntime().maxMemory() / (1024 * 1024)
                            + " MiB) to be validated; give the JVM more memory with -Xmx (for the rsaml command: RSAML_JAVA_OPTS=-Xmx4g)",
                    null), seconds(start));
        }
    }

    private static double seconds(long startNanos) {
        return (System.nanoTime() - startNanos) / 1e9;
    }
}
