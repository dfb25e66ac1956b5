/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.nio.file.Path;

/**
 * What a report needs besides the findings.
 *
 * @param toolVersion the version of RsaML that produced the report
 * @param baseDir     the directory relative file names are resolved against (the working directory)
 * @param quiet       text format only: only the findings that fail the run and the inputs that could not
 *                    be read, and the summary line when the run fails
 */
public record ReportOptions(String toolVersion, Path baseDir, boolean quiet) {
}
