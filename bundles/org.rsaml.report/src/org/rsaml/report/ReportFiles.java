/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.io.IOException;
import java.nio.file.Path;

import org.rsaml.model.support.AtomicFiles;

/**
 * Writes report files whole or not at all: a failed run never leaves half a report behind. Files
 * get the permissions any compiler output gets (those the umask allows), since CI often reads them
 * as another user.
 */
public final class ReportFiles {

    private ReportFiles() {
    }

    /** Writes {@code report} in {@code format} to {@code file}, replacing it whole ({@link AtomicFiles}). */
    public static void write(Path file, ReportFormat format, Report report, ReportOptions options) throws IOException {
        AtomicFiles.write(file, out -> format.write(report, out, options));
    }

    /**
     * Why a file operation failed, as the operating system says it ({@code permission denied},
     * {@code not a directory}, ...), naming the file when it is not {@code target}.
     */
    public static String reason(IOException e, Path target) {
        return AtomicFiles.reason(e, target);
    }
}
