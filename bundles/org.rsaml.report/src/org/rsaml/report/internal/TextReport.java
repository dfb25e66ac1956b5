/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.internal;

import java.io.IOException;
import java.io.Writer;

import org.rsaml.report.FileResult;
import org.rsaml.report.Report;
import org.rsaml.report.ReportOptions;
import org.rsaml.report.Text;
import org.rsaml.validation.Finding;

/**
 * Compiler-style lines ({@code file:line:column: error RSA-08: message}) that terminals, editors and
 * CI log parsers turn into links and annotations, {@code file: no findings} for a file checked
 * without any, and a summary line. Every line goes through
 * {@link Text#line}, so a model cannot forge lines or commands.
 */
public final class TextReport {

    private TextReport() {
    }

    public static void write(Report report, Writer out, ReportOptions options) throws IOException {
        for (FileResult result : report.results()) {
            if (!result.readable()) {
                for (String line : Text.lines(result.error())) {
                    out.write(line);
                    out.write('\n');
                }
                continue;
            }
            if (result.findings().isEmpty() && !options.quiet()) {
                // Checked and clean, said so: otherwise a file without findings cannot be told from one never checked.
                line(out, result.file() + ": no findings");
            }
            for (Finding finding : result.findings()) {
                if (!options.quiet() || report.fails(finding)) {
                    line(out, finding.toString());
                }
            }
        }
        if (!options.quiet() || report.exitCode() != 0) {
            line(out, report.summary());
        }
    }

    private static void line(Writer out, String text) throws IOException {
        out.write(Text.line(text));
        out.write('\n');
    }
}
