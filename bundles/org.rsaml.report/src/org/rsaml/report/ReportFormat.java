/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;

import org.rsaml.model.support.Choices;
import org.rsaml.report.internal.JUnitReport;
import org.rsaml.report.internal.JsonReport;
import org.rsaml.report.internal.SarifReport;
import org.rsaml.report.internal.TextReport;

/** The formats a report is written in. */
public enum ReportFormat {
    /** Compiler style, one finding a line, then a summary line. */
    TEXT("txt") {
        @Override
        public void write(Report report, Writer out, ReportOptions options) throws IOException {
            TextReport.write(report, out, options);
        }
    },
    /** RsaML's own JSON document: files, findings, input errors, summary. */
    JSON("json") {
        @Override
        public void write(Report report, Writer out, ReportOptions options) throws IOException {
            JsonReport.write(report, out, options);
        }
    },
    /** SARIF 2.1.0, read by GitHub code scanning and most static-analysis dashboards. */
    SARIF("sarif") {
        @Override
        public void write(Report report, Writer out, ReportOptions options) throws IOException {
            SarifReport.write(report, out, options);
        }
    },
    /** JUnit XML, read by the test reporters of Jenkins, GitLab and GitHub Actions. */
    JUNIT("xml") {
        @Override
        public void write(Report report, Writer out, ReportOptions options) throws IOException {
            JUnitReport.write(report, out, options);
        }
    };

    private final String extension;

    ReportFormat(String extension) {
        this.extension = extension;
    }

    public abstract void write(Report report, Writer out, ReportOptions options) throws IOException;

    /** The usual file extension of this format, without the dot. */
    public String extension() {
        return extension;
    }

    /**
     * The name of a report file of this format in a build's report directory: {@code STEM.EXT}, and for JUnit
     * {@code TEST-STEM.xml}, the prefix by which CI servers (Surefire's convention) find test reports.
     */
    public String fileName(String stem) {
        return (this == JUNIT ? "TEST-" : "") + stem + "." + extension;
    }

    /** The name users type: {@code text}, {@code json}, {@code sarif}, {@code junit}. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The format a user names ({@code text}, {@code json}, {@code sarif}, {@code junit}; any case). */
    public static ReportFormat parse(String name) {
        return Choices.parse(values(), ReportFormat::id, "report format", name);
    }

    /**
     * The format of a report file named {@code file}, told by its extension ({@code .sarif}, {@code .json},
     * {@code .xml}, {@code .txt}).
     *
     * @throws IllegalArgumentException when the extension is none of them
     */
    public static ReportFormat ofFileName(String file) {
        String lower = file.toLowerCase(Locale.ROOT);
        for (ReportFormat f : values()) {
            if (lower.endsWith("." + f.extension())) {
                return f;
            }
        }
        throw new IllegalArgumentException("cannot tell the format from the file name; write FORMAT=FILE");
    }
}
