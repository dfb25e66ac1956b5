/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.report;

import java.io.IOException;
import java.io.Writer;

import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;

/**
 * Compiler-style lines ({@code file:line:column: error RSA-08: message}) that terminals, editors and
 * CI log parsers turn into links and annotations, and a summary line.
 */
final class TextReport {

    private TextReport() {
    }

    static void write(ValidationReport report, Writer out, ReportOptions options) throws IOException {
        for (FileResult result : report.results()) {
            if (!result.readable()) {
                out.write(result.error().toString());
                out.write('\n');
                continue;
            }
            for (Finding finding : result.findings()) {
                if (!options.quiet() || finding.severity() == Severity.ERROR) {
                    out.write(finding.toString());
                    out.write('\n');
                }
            }
        }
        if (!options.quiet()) {
            out.write(report.summary());
            out.write('\n');
        }
    }
}
