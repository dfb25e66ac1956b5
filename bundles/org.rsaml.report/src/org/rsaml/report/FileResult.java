/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.util.List;

import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.Severity;

/**
 * What validation found in one input: its findings, or why it could not be read.
 *
 * @param file     the file as the user named it (relative paths stay relative)
 * @param findings findings sorted by position; empty when the file could not be read
 * @param error    the reason the input could not be read, or {@code null}
 * @param seconds  how long loading and validating took
 */
public record FileResult(String file, List<Finding> findings, ModelLoadException error, double seconds) {

    public FileResult {
        findings = List.copyOf(findings);
    }

    public static FileResult of(String file, List<Finding> findings, double seconds) {
        return new FileResult(file, findings, null, seconds);
    }

    public static FileResult unreadable(ModelLoadException error, double seconds) {
        return new FileResult(error.file(), List.of(), error, seconds);
    }

    public boolean readable() {
        return error == null;
    }

    public long count(Severity severity) {
        return findings.stream().filter(f -> f.severity() == severity).count();
    }
}
