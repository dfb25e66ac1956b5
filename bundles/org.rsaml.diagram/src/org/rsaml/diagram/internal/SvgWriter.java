/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlText;
import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;

/**
 * Writes a {@link Drawing} as SVG 1.1: one group per element with its qualified name
 * ({@code data-qname}), its URI fragment ({@code data-uri}) and its kind ({@code data-kind}); the
 * same drawing always gives the same text (coordinates rounded to 0.01, no dates, no paths).
 */
public final class SvgWriter {

    private final Drawing drawing;
    // Insertion order, so that everything written from it comes in drawing order (EObjects compare by identity).
    private final Map<EObject, String> ids = new LinkedHashMap<>();
    private final StringBuilder out = new StringBuilder(64 * 1024);

    private SvgWriter(Drawing drawing) {
        this.drawing = drawing;
    }

    /** The SVG document, with an XML declaration when {@code standalone}, ready to be embedded in HTML otherwise. */
    public static String write(Drawing drawing, boolean standalone) {
        return new SvgWriter(drawing).svg(standalone);
    }

    /** The element id given to each drawn model element, in drawing order. */
    public static Map<EObject, String> ids(Drawing drawing) {
        SvgWriter writer = new SvgWriter(drawing);
        writer.assignIds();
        return writer.ids;
    }

    private void assignIds() {
        int n = 0;
        for (Drawing.Shape shape : drawing.shapes) {
            if (shape.element != null && !ids.containsKey(shape.element)) {
                ids.put(shape.element, "el-" + ++n);
            }
        }
        for (Drawing.Link link : drawing.links) {
            if (link.element != null && !ids.containsKey(link.element)) {
                ids.put(link.element, "el-" + ++n);
            }
        }
    }

    static String css() {
        try (InputStream in = SvgWriter.class.getResourceAsStream("diagram.css")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private String svg(boolean standalone) {
        assignIds();
        double w = Math.ceil(drawing.width);
        double h = Math.ceil(drawing.height);
        if (standalone) {
            out.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        }
        out.append("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" class=\"rsaml-diagram\" width=\"").append(num(w))
                .append("\" height=\"").append(num(h)).append("\" viewBox=\"0 0 ").append(num(w)).append(' ').append(num(h))
                .append("\" font-family=\"").append(esc(TextMetrics.FONT_FAMILY)).append("\" data-view=\"").append(drawing.view)
                .append("\" data-model=\"").append(esc(drawing.title)).append("\">\n");
        out.append("<title>").append(esc(drawing.title)).append(" \u2014 ").append(drawing.view).append(" view</title>\n");
        out.append("<style>\n").append(css()).append("</style>\n");
        defs();
        for (Drawing.Shape shape : drawing.shapes) {
            if (!shape.form.equals("port")) {
                shape(shape);
            }
        }
        for (Drawing.Link link : drawing.links) {
            link(link);
        }
        for (Drawing.Shape shape : drawing.shapes) {
            if (shape.form.equals("port")) {
                shape(shape);
            }
        }
        out.append("</svg>\n");
        return out.toString();
    }

    private void defs() {
        out.append("<defs>\n");
        gradient("rsaml-layer-fill", "#ffffff", "#d1d1d1");
        gradient("rsaml-module-fill", "#ffffff", "#c2efff");
        gradient("rsaml-realtime-fill", "#fdce89", "#fcaf3e");
        gradient("rsaml-plan-fill", "#ffffff", "#fff5b5");
        arrow("rsaml-arrow", "#000000");
        arrow("rsaml-arrow-inhibitor", "#ef2929");
        arrow("rsaml-arrow-suppressor", "#ad7fa8");
        arrow("rsaml-arrow-gray", "#888888");
        arrow("rsaml-arrow-green", "#4e9a06");
        arrow("rsaml-arrow-blue", "#274c72");
        out.append("<marker id=\"rsaml-diamond\" viewBox=\"0 0 12 8\" refX=\"0\" refY=\"4\" markerWidth=\"12\" markerHeight=\"8\" orient=\"auto\" markerUnits=\"userSpaceOnUse\">")
                .append("<path d=\"M0,4 L6,0 L12,4 L6,8 Z\" fill=\"#4e9a06\"/></marker>\n");
        out.append("</defs>\n");
    }

    private void gradient(String id, String from, String to) {
        out.append("<linearGradient id=\"").append(id).append("\" x1=\"0\" y1=\"0\" x2=\"0\" y2=\"1\">")
                .append("<stop offset=\"0\" stop-color=\"").append(from).append("\"/>")
                .append("<stop offset=\"1\" stop-color=\"").append(to).append("\"/></linearGradient>\n");
    }

    private void arrow(String id, String colour) {
        out.append("<marker id=\"").append(id).append("\" viewBox=\"0 0 10 8\" refX=\"10\" refY=\"4\" markerWidth=\"10\" markerHeight=\"8\" orient=\"auto\" markerUnits=\"userSpaceOnUse\">")
                .append("<path d=\"M0,0 L10,4 L0,8 Z\" fill=\"").append(colour).append("\"/></marker>\n");
    }

    private void open(String kind, EObject element, List<String> classes, Map<String, String> data, String extra) {
        out.append("<g");
        if (element != null) {
            out.append(" id=\"").append(ids.get(element)).append('"');
        }
        Set<String> all = new LinkedHashSet<>();
        all.add(element != null ? "el" : "ref");
        all.add(kind);
        all.addAll(classes);
        String severity = severity(element);
        if (severity != null) {
            all.add(severity);
        }
        out.append(" class=\"").append(String.join(" ", all)).append('"');
        out.append(" data-kind=\"").append(kind).append('"');
        if (element != null) {
            out.append(" data-qname=\"").append(esc(RsamlLabels.qualifiedName(element))).append('"');
            String fragment = element.eResource() == null ? "" : element.eResource().getURIFragment(element);
            out.append(" data-uri=\"").append(esc(fragment)).append('"');
        }
        for (Map.Entry<String, String> d : data.entrySet()) {
            out.append(" data-").append(d.getKey()).append("=\"").append(esc(d.getValue())).append('"');
        }
        out.append(extra).append(">");
        if (element != null) {
            out.append("<title>").append(esc(RsamlLabels.describe(element))).append("</title>");
        }
    }

    private String severity(EObject element) {
        List<Finding> on = element == null ? null : drawing.findings.get(element);
        if (on == null || on.isEmpty()) {
            return null;
        }
        for (Finding f : on) {
            if (f.severity() == Severity.ERROR) {
                return "error";
            }
        }
        return "warning";
    }

    private void shape(Drawing.Shape shape) {
        String parent = shape.parent == null || shape.parent.element == null ? "" : ids.get(shape.parent.element);
        open(shape.kind, shape.element, shape.classes, shape.data, parent.isEmpty() ? "" : " data-parent=\"" + parent + "\"");
        switch (shape.form) {
            case "ellipse" -> out.append("<ellipse class=\"shape\" cx=\"").append(num(shape.x + shape.width / 2)).append("\" cy=\"")
                    .append(num(shape.y + shape.height / 2)).append("\" rx=\"").append(num(shape.width / 2)).append("\" ry=\"")
                    .append(num(shape.height / 2)).append("\"/>");
            default -> {
                out.append("<rect class=\"shape\" x=\"").append(num(shape.x)).append("\" y=\"").append(num(shape.y))
                        .append("\" width=\"").append(num(shape.width)).append("\" height=\"").append(num(shape.height)).append('"');
                if (shape.form.equals("round")) {
                    out.append(" rx=\"6\" ry=\"6\"");
                } else if (shape.form.equals("item")) {
                    out.append(" rx=\"2\" ry=\"2\"");
                }
                out.append("/>");
            }
        }
        close(shape.texts, shape.badges);
    }

    private void link(Drawing.Link link) {
        StringBuilder extra = new StringBuilder();
        if (link.source != null) {
            extra.append(" data-source=\"").append(esc(RsamlLabels.qualifiedName(link.source))).append('"');
        }
        if (link.target != null) {
            extra.append(" data-target=\"").append(esc(RsamlLabels.qualifiedName(link.target))).append('"');
        }
        List<String> classes = new java.util.ArrayList<>(link.classes);
        classes.add(0, "link");
        open(link.kind, link.element, classes, link.data, extra.toString());
        out.append("<path d=\"");
        for (int i = 0; i < link.points.size(); i++) {
            double[] p = link.points.get(i);
            out.append(i == 0 ? "M" : " L").append(num(p[0])).append(',').append(num(p[1]));
        }
        out.append("\"/>");
        if (link.marker != null && link.points.size() >= 2) {
            double[] end = link.points.get(link.points.size() - 1);
            double[] before = link.points.get(link.points.size() - 2);
            double dx = before[0] - end[0];
            double dy = before[1] - end[1];
            double length = Math.max(1e-9, Math.hypot(dx, dy));
            double back = Math.min(18, length / 2);
            double cx = end[0] + dx / length * back;
            double cy = end[1] + dy / length * back;
            out.append("<g class=\"marker\"><circle cx=\"").append(num(cx)).append("\" cy=\"").append(num(cy)).append("\" r=\"6.5\"/>");
            text(new Drawing.Text(cx, cy + 3.5, link.marker, 10, true, "middle", "marker-text"));
            out.append("</g>");
        }
        close(link.texts, link.badges);
    }

    /** An element's texts and badges, over what it draws, then the end of its group. */
    private void close(List<Drawing.Text> texts, List<Drawing.Badge> badges) {
        for (Drawing.Text text : texts) {
            text(text);
        }
        for (Drawing.Badge badge : badges) {
            badge(badge);
        }
        out.append("</g>\n");
    }

    private void text(Drawing.Text text) {
        out.append("<text x=\"").append(num(text.x())).append("\" y=\"").append(num(text.y())).append("\" font-size=\"")
                .append(num(text.size())).append('"');
        if (text.bold()) {
            out.append(" font-weight=\"bold\"");
        }
        if (!text.anchor().equals("start")) {
            out.append(" text-anchor=\"").append(text.anchor()).append('"');
        }
        if (text.css() != null) {
            out.append(" class=\"").append(text.css()).append('"');
        }
        out.append('>').append(esc(text.text())).append("</text>");
    }

    private void badge(Drawing.Badge badge) {
        out.append("<g class=\"badge ").append(badge.severity()).append("\"><rect x=\"").append(num(badge.x())).append("\" y=\"")
                .append(num(badge.y())).append("\" width=\"").append(num(badge.width())).append("\" height=\"")
                .append(num(badge.height())).append("\" rx=\"3\" ry=\"3\"/>");
        text(new Drawing.Text(badge.x() + 4, badge.y() + (badge.height() - Layout.BADGE * (TextMetrics.ASCENT + TextMetrics.DESCENT)) / 2
                + Layout.BADGE * TextMetrics.ASCENT, badge.text(), Layout.BADGE, true, "start", "badge-text"));
        out.append("</g>");
    }

    /** Rounded to 0.01 and printed the same on every platform. */
    static String num(double value) {
        // By hand: String.format was the larger part of writing a diagram of 1,000 modules.
        long hundredths = Math.round(value * 100);
        long whole = Math.abs(hundredths) / 100;
        int fraction = (int) (Math.abs(hundredths) % 100);
        StringBuilder b = new StringBuilder(12);
        if (hundredths < 0) {
            b.append('-');
        }
        b.append(whole);
        if (fraction != 0) {
            b.append('.').append(fraction / 10);
            if (fraction % 10 != 0) {
                b.append(fraction % 10);
            }
        }
        return b.toString();
    }

    static String esc(String text) {
        return RsamlText.xml(text);
    }
}
