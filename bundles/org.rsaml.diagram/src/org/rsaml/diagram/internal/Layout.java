/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.elk.alg.layered.options.LayeredMetaDataProvider;
import org.eclipse.elk.alg.layered.options.LayeredOptions;
import org.eclipse.elk.alg.layered.options.OrderingStrategy;
import org.eclipse.elk.core.RecursiveGraphLayoutEngine;
import org.eclipse.elk.core.data.LayoutMetaDataService;
import org.eclipse.elk.core.math.ElkPadding;
import org.eclipse.elk.core.math.KVector;
import org.eclipse.elk.core.options.CoreOptions;
import org.eclipse.elk.core.options.EdgeRouting;
import org.eclipse.elk.core.options.HierarchyHandling;
import org.eclipse.elk.core.util.BasicProgressMonitor;
import org.eclipse.elk.graph.ElkBendPoint;
import org.eclipse.elk.graph.ElkConnectableShape;
import org.eclipse.elk.graph.ElkEdge;
import org.eclipse.elk.graph.ElkEdgeSection;
import org.eclipse.elk.graph.ElkGraphElement;
import org.eclipse.elk.graph.ElkLabel;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.ElkPort;
import org.eclipse.elk.graph.ElkShape;
import org.eclipse.elk.graph.util.ElkGraphUtil;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.model.Architecture;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;

/**
 * What both views share: text blocks sized by {@link TextMetrics}, the ELK graph and its layered
 * options, the findings each drawn element shows, and the copy of ELK's result into a
 * {@link Drawing} in absolute coordinates.
 */
abstract class Layout {

    static final double TITLE = 13;
    static final double BODY = 11;
    static final double SMALL = 10;
    static final double BADGE = 10;
    static final double PAD = 6;

    private static boolean registered;

    /** A line of text to place in a node. */
    record Line(String text, double size, boolean bold, String css) {
        double width() {
            return TextMetrics.width(text, size, bold);
        }

        double height() {
            return TextMetrics.lineHeight(size);
        }
    }

    protected final Architecture architecture;
    protected final Drawing drawing;
    protected final DiagramOverlay.Notes notes;
    protected final ElkNode root = ElkGraphUtil.createGraph();
    /** Which ELK element stands for which model element. */
    protected final Map<ElkGraphElement, EObject> elementOf = new LinkedHashMap<>();
    protected final Map<EObject, ElkGraphElement> shapeOf = new IdentityHashMap<>();
    private final Map<EObject, List<Finding>> decorated = new LinkedHashMap<>();

    Layout(Architecture architecture, String view, List<Finding> findings, DiagramOverlay.Notes notes) {
        this.architecture = architecture;
        this.drawing = new Drawing(RsamlLabels.name(architecture), view);
        this.notes = notes;
        drawing.items.addAll(notes.items());
        register();
        assign(findings);
        root.setProperty(CoreOptions.ALGORITHM, LayeredOptions.ALGORITHM_ID);
        root.setProperty(CoreOptions.HIERARCHY_HANDLING, HierarchyHandling.INCLUDE_CHILDREN);
        root.setProperty(CoreOptions.EDGE_ROUTING, EdgeRouting.ORTHOGONAL);
        root.setProperty(LayeredOptions.CONSIDER_MODEL_ORDER_STRATEGY, OrderingStrategy.NODES_AND_EDGES);
        spacing(root);
    }

    private static synchronized void register() {
        if (!registered) {
            // Outside Eclipse no extension registry announces the algorithms: name the one we use.
            LayoutMetaDataService.getInstance().registerLayoutMetaDataProviders(new LayeredMetaDataProvider());
            registered = true;
        }
    }

    static void spacing(ElkNode node) {
        node.setProperty(CoreOptions.SPACING_NODE_NODE, 28.0);
        node.setProperty(LayeredOptions.SPACING_NODE_NODE_BETWEEN_LAYERS, 36.0);
        node.setProperty(CoreOptions.SPACING_EDGE_NODE, 14.0);
        node.setProperty(LayeredOptions.SPACING_EDGE_NODE_BETWEEN_LAYERS, 14.0);
        node.setProperty(CoreOptions.SPACING_EDGE_EDGE, 9.0);
        node.setProperty(LayeredOptions.SPACING_EDGE_EDGE_BETWEEN_LAYERS, 9.0);
        node.setProperty(CoreOptions.SPACING_EDGE_LABEL, 4.0);
        node.setProperty(CoreOptions.SPACING_LABEL_LABEL, 4.0);
    }

    /** Whether this view draws the element (findings on other elements go to their nearest drawn container). */
    abstract boolean draws(EObject element);

    /** Builds the ELK graph: nodes, ports, edges and their labels, sized from their text. */
    abstract void build();

    /** Adjusts ELK's result before it is copied; nothing by default. */
    void arrange() {
    }

    /** Copies ELK's result into the drawing: shapes, texts, links. */
    abstract void collect();

    final Drawing run() {
        build();
        new RecursiveGraphLayoutEngine().layout(root, new BasicProgressMonitor());
        if (root.getChildren().isEmpty()) {
            // ELK leaves an empty graph unsized: the frame still holds its title.
            ElkPadding padding = root.getProperty(CoreOptions.PADDING);
            KVector minimum = root.getProperty(CoreOptions.NODE_SIZE_MINIMUM);
            root.setDimensions(Math.max(minimum.x, padding.left + padding.right), padding.top + PAD);
        }
        arrange();
        drawing.width = root.getWidth();
        drawing.height = root.getHeight();
        collect();
        for (Map.Entry<EObject, List<Finding>> e : decorated.entrySet()) {
            drawing.findings.put(e.getKey(), e.getValue());
        }
        return drawing;
    }

    // ---------------------------------------------------------------- findings

    private void assign(List<Finding> findings) {
        Resource resource = architecture.eResource();
        for (Finding finding : findings) {
            EObject element = resource == null ? null : resource.getEObject(finding.uriFragment());
            EObject shown = element;
            if (element != architecture) {
                while (shown != null && (shown == architecture || !draws(shown))) {
                    shown = shown == architecture ? null : shown.eContainer();
                }
            }
            if (shown == null) {
                drawing.undrawn.add(finding);
            } else {
                decorated.computeIfAbsent(shown, k -> new ArrayList<>()).add(finding);
            }
        }
    }

    /** The findings an element shows, empty when none. */
    protected List<Finding> findingsOn(EObject element) {
        return decorated.getOrDefault(element, List.of());
    }

    /** The badge text (rule ids) an element shows, or null. */
    protected String badgeText(EObject element) {
        List<Finding> on = findingsOn(element);
        if (on.isEmpty()) {
            return null;
        }
        Set<String> ids = new LinkedHashSet<>();
        for (Finding f : on) {
            ids.add(f.ruleId());
        }
        return String.join(" ", ids);
    }

    protected String badgeSeverity(EObject element) {
        for (Finding f : findingsOn(element)) {
            if (f.severity() == Severity.ERROR) {
                return "error";
            }
        }
        return "warning";
    }

    static double badgeWidth(String text) {
        return text == null ? 0 : TextMetrics.width(text, BADGE, true) + 8;
    }

    static double badgeHeight() {
        return TextMetrics.lineHeight(BADGE) + 2;
    }

    /** The overlay's extra lines for an element. */
    protected List<Line> overlayLines(EObject element) {
        List<Line> lines = new ArrayList<>();
        for (DiagramOverlay.Line line : notes.lines().getOrDefault(RsamlLabels.qualifiedName(element), List.of())) {
            lines.add(new Line(line.text(), SMALL, false, line.style()));
        }
        return lines;
    }

    /** The overlay's classes and data attributes for an element, in a fixed order. */
    protected void emphasise(EObject element, List<String> classes, Map<String, String> data) {
        String qname = RsamlLabels.qualifiedName(element);
        classes.addAll(new java.util.TreeSet<>(notes.classes().getOrDefault(qname, Set.of())));
        data.putAll(notes.data().getOrDefault(qname, Map.of()));
    }

    // ---------------------------------------------------------------- text blocks

    static double width(List<Line> lines) {
        double w = 0;
        for (Line line : lines) {
            w = Math.max(w, line.width());
        }
        return w;
    }

    static double height(List<Line> lines) {
        double h = 0;
        for (Line line : lines) {
            h += line.height();
        }
        return h;
    }

    /** Writes lines top-down from (x, top); returns the y below the last line. */
    static double place(List<Drawing.Text> out, List<Line> lines, double x, double top, String anchor) {
        double y = top;
        for (Line line : lines) {
            double baseline = y + (line.height() - line.size() * (TextMetrics.ASCENT + TextMetrics.DESCENT)) / 2
                    + line.size() * TextMetrics.ASCENT;
            out.add(new Drawing.Text(x, baseline, line.text(), line.size(), line.bold(), anchor, line.css()));
            y += line.height();
        }
        return y;
    }

    /** A title line followed by room for the element's badge; returns the badge's width (0 when none). */
    protected double titleWithBadge(EObject element, Line title, List<Line> lines) {
        lines.add(title);
        return badgeWidth(badgeText(element));
    }

    protected void addBadge(Drawing.Shape shape, double x, double y) {
        String text = badgeText(shape.element);
        if (text != null) {
            shape.badges.add(new Drawing.Badge(x, y, badgeWidth(text), badgeHeight(), text, badgeSeverity(shape.element)));
        }
    }

    // ---------------------------------------------------------------- ELK graph

    protected ElkNode node(ElkNode parent, EObject element, double width, double height) {
        ElkNode node = ElkGraphUtil.createNode(parent);
        node.setDimensions(Math.ceil(width), Math.ceil(height));
        map(node, element);
        return node;
    }

    protected void map(ElkGraphElement shape, EObject element) {
        if (element != null) {
            elementOf.put(shape, element);
            shapeOf.put(element, shape);
        }
    }

    protected static void padding(ElkNode node, double top, double side) {
        node.setProperty(CoreOptions.PADDING, new ElkPadding(Math.ceil(top), side, side, side));
    }

    protected static ElkLabel label(ElkEdge edge, String text, double size, boolean bold) {
        ElkLabel label = ElkGraphUtil.createLabel(text, edge);
        label.setDimensions(Math.ceil(TextMetrics.width(text, size, bold)) + 2, Math.ceil(TextMetrics.lineHeight(size)));
        return label;
    }

    protected static ElkLabel badgeLabel(ElkEdge edge, String text) {
        ElkLabel label = ElkGraphUtil.createLabel(text, edge);
        label.setProperty(CoreOptions.NO_LAYOUT, false);
        label.setDimensions(Math.ceil(badgeWidth(text)), Math.ceil(badgeHeight()));
        return label;
    }

    /** The absolute position of a shape's top-left corner. */
    static double[] absolute(ElkShape shape) {
        double x = shape.getX();
        double y = shape.getY();
        ElkNode parent = shape instanceof ElkPort port ? port.getParent() : ((ElkNode) shape).getParent();
        for (ElkNode n = parent; n != null; n = n.getParent()) {
            x += n.getX();
            y += n.getY();
        }
        return new double[] { x, y };
    }

    protected Drawing.Shape shape(String kind, ElkShape elk, Drawing.Shape parent) {
        EObject element = elementOf.get(elk);
        Drawing.Shape shape = new Drawing.Shape(kind, element, parent);
        double[] at = absolute(elk);
        shape.x = at[0];
        shape.y = at[1];
        shape.width = elk.getWidth();
        shape.height = elk.getHeight();
        if (element != null) {
            emphasise(element, shape.classes, shape.data);
        }
        drawing.shapes.add(shape);
        return shape;
    }

    /** Copies an edge's route and labels; the first label that is a badge becomes the link's badge. */
    protected Drawing.Link link(String kind, ElkEdge edge, EObject element, EObject source, EObject target, String badge) {
        Drawing.Link link = new Drawing.Link(kind, element, source, target);
        ElkNode container = edge.getContainingNode();
        double[] origin = container == null ? new double[] { 0, 0 } : absoluteOfNode(container);
        for (ElkEdgeSection section : edge.getSections()) {
            if (link.points.isEmpty()) {
                link.points.add(new double[] { origin[0] + section.getStartX(), origin[1] + section.getStartY() });
            }
            for (ElkBendPoint bend : section.getBendPoints()) {
                link.points.add(new double[] { origin[0] + bend.getX(), origin[1] + bend.getY() });
            }
            link.points.add(new double[] { origin[0] + section.getEndX(), origin[1] + section.getEndY() });
        }
        for (ElkLabel label : edge.getLabels()) {
            double x = origin[0] + label.getX();
            double y = origin[1] + label.getY();
            if (badge != null && label.getText().equals(badge) && link.badges.isEmpty()) {
                link.badges.add(new Drawing.Badge(x, y, label.getWidth(), label.getHeight(), badge,
                        element == null ? "error" : badgeSeverity(element)));
            } else {
                List<Line> one = List.of(new Line(label.getText(), SMALL, false, "link-label"));
                place(link.texts, one, x + 1, y, "start");
            }
        }
        if (element != null) {
            emphasise(element, link.classes, link.data);
        } else if (source != null && target != null) {
            String name = RsamlLabels.qualifiedName(source) + " -> " + RsamlLabels.qualifiedName(target);
            link.classes.addAll(new java.util.TreeSet<>(notes.classes().getOrDefault(name, Set.of())));
            link.data.putAll(notes.data().getOrDefault(name, Map.of()));
        }
        drawing.links.add(link);
        return link;
    }

    static double[] absoluteOfNode(ElkNode node) {
        double x = 0;
        double y = 0;
        for (ElkNode n = node; n != null; n = n.getParent()) {
            x += n.getX();
            y += n.getY();
        }
        return new double[] { x, y };
    }

    protected static ElkEdge edge(ElkConnectableShape source, ElkConnectableShape target) {
        return ElkGraphUtil.createSimpleEdge(source, target);
    }
}
