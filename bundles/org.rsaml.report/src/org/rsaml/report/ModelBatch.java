/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;
import org.rsaml.validation.Severity;

/**
 * Checks every model a user named, each on its own: whatever goes wrong with one file (it cannot be
 * read, or the check itself fails) becomes that file's error, and the other files are still checked.
 * Shared by the command line, the Maven plugin and any other front end.
 */
public final class ModelBatch {

    private ModelBatch() {
    }

    /** Validates the named files and directories against the RsaML rules, relative ones resolved against {@code base}. */
    public static Report validate(Path base, List<Path> paths, Severity failOn) {
        return run(base, paths, failOn, Rules.all(), RsamlModelValidator::validate);
    }

    /**
     * Runs {@code check} on every model under {@code paths}.
     *
     * @param rules the rules {@code check} can report, as the SARIF and JUnit reports list them
     */
    public static Report run(Path base, List<Path> paths, Severity failOn, List<Rule> rules, ModelCheck check) {
        List<FileResult> results = new ArrayList<>();
        for (ModelFiles.Input input : ModelFiles.select(base, paths)) {
            results.add(input.unusable() != null ? FileResult.unreadable(input.unusable(), 0) : check(input.path(), input.displayName(), check));
        }
        return new Report(rules, results, failOn);
    }

    /** Runs {@code check} on one file; never throws for what happens inside the check. */
    public static FileResult check(Path file, String displayName, ModelCheck check) {
        long start = System.nanoTime();
        try {
            return FileResult.of(displayName, check.check(file, displayName), seconds(start));
        } catch (ModelLoadException e) {
            return FileResult.unreadable(e, seconds(start));
        } catch (OutOfMemoryError e) {
            // A model that only just loaded; the memory is free again once it is dropped.
            return FileResult.unreadable(new ModelLoadException(displayName, 0, 0,
                    "the model is too large for the available heap (" + Runtime.getRuntime().maxMemory() / (1024 * 1024)
                            + " MiB) to be checked; give the JVM more memory with -Xmx",
                    null), seconds(start));
        } catch (RuntimeException | StackOverflowError | LinkageError | AssertionError e) {
            // A defect of RsaML's own: it must cost this file only, not the run.
            return FileResult.unreadable(new ModelLoadException(displayName, 0, 0,
                    "internal error while checking this file (a defect in RsaML, please report it): " + e, e),
                    seconds(start));
        }
    }

    private static double seconds(long startNanos) {
        return (System.nanoTime() - startNanos) / 1e9;
    }
}
