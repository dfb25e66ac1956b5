/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.nio.file.Path;
import java.util.List;

import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;

/**
 * A source of findings on one model file: the RsaML rules, a timing analysis, ... Each kind of
 * check brings its findings (with its own {@link org.rsaml.validation.Rule}s) and reuses the
 * batch ({@link ModelBatch}) and every report format.
 */
@FunctionalInterface
public interface ModelCheck {

    /**
     * @param file        the model file to read
     * @param displayName the file as the user named it, used in findings and messages
     * @return the findings, sorted by position
     * @throws ModelLoadException when the file cannot be read as a model
     */
    List<Finding> check(Path file, String displayName) throws ModelLoadException;
}
