/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;

/**
 * Writes one self-contained HTML page: the diagram inline, its findings and validation summary,
 * the elements' attributes as JSON, and the page's own style and script inlined from the files
 * beside this class (report.html, report.css, report.js), so it opens without a network.
 */
public final class HtmlWriter {

    private static final Pattern TOKEN = Pattern.compile("@([A-Z]+)@");

    private HtmlWriter() {
    }

    public static String write(Drawing drawing, String file, List<Finding> findings) {
        Map<EObject, String> ids = SvgWriter.ids(drawing);
        Map<String, String> values = new LinkedHashMap<>();
        long errors = findings.stream().filter(f -> f.severity() == Severity.ERROR).count();
        long warnings = findings.stream().filter(f -> f.severity() == Severity.WARNING).count();
        values.put("TITLE", SvgWriter.esc(drawing.title + " \u2014 " + drawing.view + " view"));
        values.put("MODEL", SvgWriter.esc(drawing.title));
        values.put("FILE", SvgWriter.esc(file));
        values.put("VIEW", drawing.view);
        values.put("SUMMARY", SvgWriter.esc(summary(errors, warnings)));
        values.put("STATUS", errors > 0 ? "error" : warnings > 0 ? "warning" : "clean");
        values.put("CSS", resource("report.css"));
        values.put("JS", resource("report.js"));
        values.put("SVG", SvgWriter.write(drawing, false));
        values.put("FINDINGS", findingItems(drawing, findings, ids));
        values.put("OVERLAY", overlayItems(drawing, ids));
        values.put("DATA", data(drawing, file, findings, ids));
        String template = resource("report.html");
        Matcher m = TOKEN.matcher(template);
        StringBuilder out = new StringBuilder(template.length() + values.values().stream().mapToInt(String::length).sum());
        int last = 0;
        while (m.find()) {
            String value = values.get(m.group(1));
            if (value == null) {
                throw new IllegalStateException("report.html names an unknown value " + m.group());
            }
            // Appended as is: appendReplacement would scan the megabytes of a large diagram twice.
            out.append(template, last, m.start()).append(value);
            last = m.end();
        }
        out.append(template, last, template.length());
        return out.toString();
    }

    static String summary(long errors, long warnings) {
        if (errors == 0 && warnings == 0) {
            return "valid: no findings";
        }
        return errors + (errors == 1 ? " error, " : " errors, ") + warnings + (warnings == 1 ? " warning" : " warnings");
    }

    private static String findingItems(Drawing drawing, List<Finding> findings, Map<EObject, String> ids) {
        Map<Finding, EObject> shownOn = new LinkedHashMap<>();
        for (Map.Entry<EObject, List<Finding>> e : drawing.findings.entrySet()) {
            for (Finding f : e.getValue()) {
                shownOn.put(f, e.getKey());
            }
        }
        StringBuilder b = new StringBuilder();
        for (Finding f : findings) {
            EObject on = shownOn.get(f);
            String target = on == null ? "" : ids.getOrDefault(on, "");
            String severity = f.severity().label();
            b.append("<li class=\"finding ").append(severity).append("\" tabindex=\"0\" data-target=\"").append(target)
                    .append("\" data-rule=\"").append(SvgWriter.esc(f.ruleId())).append("\" data-qname=\"")
                    .append(SvgWriter.esc(f.qualifiedName())).append("\">")
                    .append("<span class=\"severity\">").append(severity).append("</span> ")
                    .append("<span class=\"rule\">").append(SvgWriter.esc(f.ruleId())).append("</span> ")
                    .append("<span class=\"message\">").append(SvgWriter.esc(f.message())).append("</span>")
                    .append("<span class=\"where\">").append(SvgWriter.esc(f.file() + ":" + f.line() + ":" + f.column()))
                    .append(" \u00b7 ").append(SvgWriter.esc(f.qualifiedName()))
                    .append(on == null ? " \u00b7 not drawn in this view" : "").append("</span></li>\n");
        }
        return b.toString();
    }

    /** The overlays' items, one list per section, each pointing at the ids of the elements it concerns. */
    private static String overlayItems(Drawing drawing, Map<EObject, String> ids) {
        Map<String, List<String>> idsByName = new LinkedHashMap<>();
        for (Map.Entry<EObject, String> e : ids.entrySet()) {
            idsByName.computeIfAbsent(RsamlLabels.qualifiedName(e.getKey()), k -> new ArrayList<>()).add(e.getValue());
        }
        Map<String, StringBuilder> sections = new LinkedHashMap<>();
        for (DiagramOverlay.Item item : drawing.items) {
            List<String> targets = new ArrayList<>();
            for (String element : item.elements()) {
                targets.addAll(idsByName.getOrDefault(element, List.of()));
            }
            StringBuilder b = sections.computeIfAbsent(item.section(), k -> new StringBuilder());
            b.append("<li class=\"overlay-item ").append(SvgWriter.esc(item.line().style())).append("\" tabindex=\"0\" data-targets=\"")
                    .append(String.join(" ", targets)).append("\"><span class=\"text\">").append(SvgWriter.esc(item.line().text()))
                    .append("</span>");
            for (String detail : item.details()) {
                b.append("<span class=\"detail\">").append(SvgWriter.esc(detail)).append("</span>");
            }
            b.append("</li>\n");
        }
        StringBuilder out = new StringBuilder();
        for (Map.Entry<String, StringBuilder> e : sections.entrySet()) {
            String id = "overlay-" + e.getKey().toLowerCase(java.util.Locale.ROOT).replaceAll("[^a-z0-9]+", "-");
            out.append("    <h2>").append(SvgWriter.esc(e.getKey())).append("</h2>\n    <ul class=\"overlay-items\" id=\"").append(id)
                    .append("\">\n").append(e.getValue()).append("    </ul>\n");
        }
        return out.toString();
    }

    private static String data(Drawing drawing, String file, List<Finding> findings, Map<EObject, String> ids) {
        Map<String, Object> data = new LinkedHashMap<>();
        data.put("model", drawing.title);
        data.put("file", file);
        data.put("view", drawing.view);
        Map<String, Object> elements = new LinkedHashMap<>();
        for (Map.Entry<EObject, String> e : ids.entrySet()) {
            Map<String, Object> element = new LinkedHashMap<>();
            element.put("qname", RsamlLabels.qualifiedName(e.getKey()));
            element.put("kind", e.getKey().eClass().getName());
            element.put("attributes", attributes(e.getKey()));
            List<Map<String, Object>> on = new ArrayList<>();
            for (Finding f : drawing.findings.getOrDefault(e.getKey(), List.of())) {
                on.add(finding(f));
            }
            element.put("findings", on);
            elements.put(e.getValue(), element);
        }
        data.put("elements", elements);
        Gson gson = new GsonBuilder().disableInnerClassSerialization().create();
        // Gson escapes <, > and & by default, so the JSON cannot close the script element holding it.
        return gson.toJson(data);
    }

    private static Map<String, Object> finding(Finding f) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("rule", f.ruleId());
        m.put("severity", f.severity().label());
        m.put("message", f.message());
        m.put("element", f.qualifiedName());
        m.put("line", f.line());
        return m;
    }

    private static Map<String, String> attributes(EObject element) {
        Map<String, String> attributes = new LinkedHashMap<>();
        for (EAttribute attribute : element.eClass().getEAllAttributes()) {
            Object value = element.eGet(attribute);
            if (value != null && !value.toString().isEmpty()) {
                attributes.put(attribute.getName(), value instanceof Double d ? RsamlLabels.number(d) : value.toString());
            }
        }
        for (EReference reference : element.eClass().getEAllReferences()) {
            if (reference.isContainment() || reference.isContainer() || reference.isTransient()) {
                continue;
            }
            Object value = element.eGet(reference);
            List<String> names = new ArrayList<>();
            if (value instanceof EObject target) {
                names.add(RsamlLabels.qualifiedName(target));
            } else if (value instanceof List<?> list) {
                for (Object o : list) {
                    if (o instanceof EObject target) {
                        names.add(RsamlLabels.qualifiedName(target));
                    }
                }
            }
            if (!names.isEmpty()) {
                attributes.put(reference.getName(), String.join(", ", names));
            }
        }
        return attributes;
    }

    static String resource(String name) {
        try (InputStream in = HtmlWriter.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException(name + " is missing from org.rsaml.diagram");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
