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
import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.Severity;

import com.google.gson.stream.JsonWriter;

/** RsaML's JSON report: one object per file with its findings or its input error, and totals. */
public final class JsonReport {

    private JsonReport() {
    }

    public static void write(Report report, Writer out, ReportOptions options) throws IOException {
        JsonWriter json = new JsonWriter(out);
        json.setIndent("  ");
        json.setHtmlSafe(false);
        json.beginObject();
        json.name("tool").beginObject().name("name").value("rsaml").name("version").value(options.toolVersion()).endObject();
        json.name("files").beginArray();
        for (FileResult result : report.results()) {
            json.beginObject();
            json.name("file").value(result.file());
            if (result.readable()) {
                json.name("status").value(result.findings().isEmpty() ? "clean" : "findings");
                json.name("findings").beginArray();
                for (Finding f : result.findings()) {
                    json.beginObject();
                    json.name("ruleId").value(f.ruleId());
                    json.name("rule").value(f.rule().name());
                    json.name("severity").value(f.severity().label());
                    json.name("message").value(f.message());
                    if (f.detail() != null) {
                        json.name("detail").value(f.detail());
                    }
                    json.name("element").value(f.qualifiedName());
                    json.name("uriFragment").value(f.uriFragment());
                    json.name("line").value(f.line());
                    json.name("column").value(f.column());
                    json.name("fails").value(report.fails(f));
                    json.endObject();
                }
                json.endArray();
            } else {
                json.name("status").value("unreadable");
                // "error" is the first problem, "errors" every one of them.
                json.name("error");
                problem(json, result.error().problems().get(0));
                json.name("errors").beginArray();
                for (ModelLoadException.Problem problem : result.error().problems()) {
                    problem(json, problem);
                }
                json.endArray();
            }
            json.endObject();
        }
        json.endArray();
        json.name("summary").beginObject();
        json.name("files").value(report.files());
        json.name("errors").value(report.count(Severity.ERROR));
        json.name("warnings").value(report.count(Severity.WARNING));
        json.name("infos").value(report.count(Severity.INFO));
        json.name("unreadable").value(report.unreadable());
        json.name("failOn").value(report.failOn() == null ? "never" : report.failOn().label());
        json.name("exitCode").value(report.exitCode());
        json.endObject();
        json.endObject();
        json.flush();
        out.write('\n');
    }

    private static void problem(JsonWriter json, ModelLoadException.Problem problem) throws IOException {
        json.beginObject();
        json.name("message").value(problem.message());
        if (problem.location().line() > 0) {
            json.name("line").value(problem.location().line());
        }
        if (problem.location().column() > 0) {
            json.name("column").value(problem.location().column());
        }
        json.endObject();
    }
}
