/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.internal;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.report.FileResult;
import org.rsaml.report.Report;
import org.rsaml.report.ReportOptions;
import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Severity;

import com.google.gson.stream.JsonWriter;

/**
 * SARIF 2.1.0: the rules with id, description and help; one result per finding with its physical
 * location (file, line, column) and its logical location (the element's qualified name); inputs that
 * could not be read as tool execution notifications. File names are relative to {@code %SRCROOT%},
 * the working directory, which is what code-scanning services expect.
 */
public final class SarifReport {

    static final String SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json";
    static final String SRCROOT = "%SRCROOT%";

    private SarifReport() {
    }

    public static void write(Report report, Writer out, ReportOptions options) throws IOException {
        List<Rule> rules = report.rules();
        Map<String, Integer> ruleIndex = new HashMap<>();
        for (int i = 0; i < rules.size(); i++) {
            ruleIndex.put(rules.get(i).id(), i);
        }
        Path base = options.baseDir().toAbsolutePath().normalize();

        JsonWriter json = new JsonWriter(out);
        json.setIndent("  ");
        json.setHtmlSafe(false);
        json.beginObject();
        json.name("$schema").value(SCHEMA);
        json.name("version").value("2.1.0");
        json.name("runs").beginArray().beginObject();

        json.name("tool").beginObject().name("driver").beginObject();
        json.name("name").value("rsaml");
        json.name("fullName").value("RsaML model validation");
        json.name("version").value(options.toolVersion());
        json.name("semanticVersion").value(options.toolVersion());
        json.name("rules").beginArray();
        for (Rule rule : rules) {
            json.beginObject();
            json.name("id").value(rule.id());
            json.name("name").value(rule.name());
            json.name("shortDescription").beginObject().name("text").value(rule.description()).endObject();
            json.name("fullDescription").beginObject().name("text").value(rule.description()).endObject();
            json.name("help").beginObject()
                    .name("text").value(rule.help())
                    .name("markdown").value("**" + rule.id() + " " + rule.name() + "**: " + rule.description() + "\n\n" + rule.help())
                    .endObject();
            json.name("defaultConfiguration").beginObject().name("level").value(level(rule.severity())).endObject();
            json.name("properties").beginObject().name("tags").beginArray().value("rsaml").value(rule.source()).endArray().endObject();
            json.endObject();
        }
        json.endArray();
        json.endObject().endObject();

        json.name("invocations").beginArray().beginObject();
        json.name("executionSuccessful").value(report.unreadable() == 0);
        json.name("toolExecutionNotifications").beginArray();
        for (FileResult result : report.results()) {
            if (!result.readable()) {
                for (ModelLoadException.Problem problem : result.error().problems()) {
                    json.beginObject();
                    json.name("level").value("error");
                    json.name("message").beginObject().name("text").value(problem.message()).endObject();
                    json.name("locations").beginArray().beginObject();
                    physicalLocation(json, result.file(), problem.location().line(), problem.location().column(), base);
                    json.endObject().endArray();
                    json.endObject();
                }
            }
        }
        json.endArray();
        json.endObject().endArray();

        json.name("originalUriBaseIds").beginObject().name(SRCROOT).beginObject()
                .name("uri").value(directoryUri(base)).endObject().endObject();
        json.name("columnKind").value("unicodeCodePoints");

        json.name("results").beginArray();
        for (FileResult result : report.results()) {
            for (Finding f : result.findings()) {
                json.beginObject();
                json.name("ruleId").value(f.ruleId());
                Integer index = ruleIndex.get(f.ruleId());
                if (index != null) {
                    json.name("ruleIndex").value(index);
                }
                json.name("level").value(level(f.severity()));
                json.name("message").beginObject().name("text").value(f.message()).endObject();
                if (f.detail() != null) {
                    json.name("properties").beginObject().name("detail").value(f.detail()).endObject();
                }
                json.name("locations").beginArray().beginObject();
                physicalLocation(json, f.file(), f.line(), f.column(), base);
                json.name("logicalLocations").beginArray().beginObject()
                        .name("fullyQualifiedName").value(f.qualifiedName())
                        .name("kind").value("element")
                        .endObject().endArray();
                json.endObject().endArray();
                json.endObject();
            }
        }
        json.endArray();

        json.endObject().endArray();
        json.endObject();
        json.flush();
        out.write('\n');
    }

    private static void physicalLocation(JsonWriter json, String file, int line, int column, Path base) throws IOException {
        json.name("physicalLocation").beginObject();
        json.name("artifactLocation").beginObject();
        Path path;
        try {
            path = base.resolve(file).normalize();
        } catch (InvalidPathException e) {
            path = null; // not a name the file system takes, but still the name the user gave
        }
        if (path == null || path.startsWith(base)) {
            json.name("uri").value(relativeUri(path == null ? file : base.relativize(path).toString()));
            json.name("uriBaseId").value(SRCROOT);
        } else {
            json.name("uri").value(path.toUri().toASCIIString());
        }
        json.endObject();
        if (line > 0) {
            json.name("region").beginObject().name("startLine").value(line);
            if (column > 0) {
                json.name("startColumn").value(column);
            }
            json.endObject();
        }
        json.endObject();
    }

    /** A relative URI reference: every byte but the unreserved ones and '/' percent-encoded (':' too, so no segment reads as a scheme). */
    static String relativeUri(String relative) {
        StringBuilder uri = new StringBuilder();
        for (byte b : relative.replace('\\', '/').getBytes(StandardCharsets.UTF_8)) {
            int c = b & 0xff;
            if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || "-._~/".indexOf(c) >= 0) {
                uri.append((char) c);
            } else {
                uri.append('%').append(Character.toUpperCase(Character.forDigit(c >> 4, 16)))
                        .append(Character.toUpperCase(Character.forDigit(c & 0xf, 16)));
            }
        }
        return uri.toString();
    }

    private static String directoryUri(Path dir) {
        String uri = dir.toUri().toASCIIString();
        return uri.endsWith("/") ? uri : uri + "/";
    }

    static String level(Severity severity) {
        return switch (severity) {
            case ERROR -> "error";
            case WARNING -> "warning";
            case INFO -> "note";
        };
    }
}
