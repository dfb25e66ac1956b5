/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.validation.Finding;

/**
 * A laid-out diagram in absolute coordinates, ready to be written: what the layout decided and
 * the SVG shows, kept apart so that both writers read one geometry.
 */
public final class Drawing {

    /** A piece of text: {@code y} is the baseline; {@code anchor} is start, middle or end. */
    public record Text(double x, double y, String text, double size, boolean bold, String anchor, String css) {
    }

    /** A rule id drawn on an element, at its top-left corner (x, y). */
    public record Badge(double x, double y, double width, double height, String text, String severity) {
    }

    /** A drawn model element or a part of one. */
    public static final class Shape {
        public final String kind;
        public final EObject element;
        public final Shape parent;
        public double x;
        public double y;
        public double width;
        public double height;
        /** rect, round, ellipse, item (a list entry) or port. */
        public String form = "rect";
        public final List<String> classes = new ArrayList<>();
        public final List<Text> texts = new ArrayList<>();
        public final List<Badge> badges = new ArrayList<>();
        /** {@code data-} attributes from overlays, by name (sorted: the same model gives the same bytes). */
        public final Map<String, String> data = new TreeMap<>();

        public Shape(String kind, EObject element, Shape parent) {
            this.kind = kind;
            this.element = element;
            this.parent = parent;
        }
    }

    /** A line between two shapes: a model element (connection, inhibitor, ...) or a reference. */
    public static final class Link {
        public final String kind;
        /** The model element the link is, or null when it draws a reference (sensor of a module, ...). */
        public final EObject element;
        public final EObject source;
        public final EObject target;
        public final List<double[]> points = new ArrayList<>();
        public final List<Text> texts = new ArrayList<>();
        public final List<Badge> badges = new ArrayList<>();
        public final List<String> classes = new ArrayList<>();
        public final Map<String, String> data = new TreeMap<>();
        /** A letter drawn in a circle on the link's last segment (I for inhibitors, S for suppressors), or null. */
        public String marker;

        public Link(String kind, EObject element, EObject source, EObject target) {
            this.kind = kind;
            this.element = element;
            this.source = source;
            this.target = target;
        }
    }

    public final String title;
    public final String view;
    public double width;
    public double height;
    /** Containers first, so that what they contain is drawn over them. */
    public final List<Shape> shapes = new ArrayList<>();
    public final List<Link> links = new ArrayList<>();
    /** Findings by the element that shows them (the element itself, or its nearest drawn container). */
    public final Map<EObject, List<Finding>> findings = new LinkedHashMap<>();
    /** Findings on elements this view does not draw at all (not even a container). */
    public final List<Finding> undrawn = new ArrayList<>();
    /** What the overlays list beside the diagram (HTML only). */
    public final List<DiagramOverlay.Item> items = new ArrayList<>();

    public Drawing(String title, String view) {
        this.title = title;
        this.view = view;
    }
}
