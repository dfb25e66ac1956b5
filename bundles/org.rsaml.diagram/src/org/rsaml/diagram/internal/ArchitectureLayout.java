/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.elk.core.options.CoreOptions;
import org.eclipse.elk.core.options.Direction;
import org.eclipse.elk.core.options.PortConstraints;
import org.eclipse.elk.core.options.PortSide;
import org.eclipse.elk.core.options.SizeConstraint;
import org.eclipse.elk.core.math.KVector;
import org.eclipse.elk.graph.ElkBendPoint;
import org.eclipse.elk.graph.ElkConnectableShape;
import org.eclipse.elk.graph.ElkEdge;
import org.eclipse.elk.graph.ElkEdgeSection;
import org.eclipse.elk.graph.ElkLabel;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.ElkPort;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.diagram.internal.ArchitectureTexts.Item;
import org.rsaml.diagram.internal.ArchitectureTexts.ModuleText;
import org.rsaml.model.Action;
import org.rsaml.model.Actuator;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.Device;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Port;
import org.rsaml.model.Sensor;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Suppressor;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.Finding;

/**
 * The architecture view: layers stacked by level (highest on top) as containers of their modules,
 * entry ports on a module's left side and output ports on its right, connections, inhibitors and
 * suppressors between ports, sensors below the lowest layer and actuators beside it. ELK's layered
 * algorithm places everything; its partitions keep the layers in level order.
 */
public final class ArchitectureLayout extends Layout {

    static final double PORT = 8;
    static final double PORT_PITCH = 18;
    static final double GAP = 8;

    private final ArchitectureTexts texts = new ArchitectureTexts(this);
    private final Map<Module, ModuleText> moduleTexts = new IdentityHashMap<>();
    private final List<Layer> layers;

    public ArchitectureLayout(Architecture architecture, List<Finding> findings, DiagramOverlay.Notes notes) {
        super(architecture, "architecture", findings, notes);
        layers = new ArrayList<>(architecture.getLayers());
        layers.sort(Comparator.comparingInt(Layer::getLevel).reversed());
    }

    /** Lays out and returns the drawing. */
    public static Drawing draw(Architecture architecture, List<Finding> findings, DiagramOverlay.Notes notes) {
        return new ArchitectureLayout(architecture, findings, notes).run();
    }

    @Override
    boolean draws(EObject element) {
        return element instanceof Architecture || element instanceof Layer || element instanceof Module
                || element instanceof Function || element instanceof Action || element instanceof Port
                || element instanceof Connection || element instanceof SubsumptionLink || element instanceof Device;
    }

    // ------------------------------------------------------------ graph

    @Override
    void build() {
        root.setProperty(CoreOptions.DIRECTION, Direction.DOWN);
        root.setProperty(CoreOptions.PARTITIONING_ACTIVATE, true);
        List<Line> title = texts.architectureTitle();
        padding(root, PAD * 2 + height(title), 16);
        double titleWidth = width(title) + badgeWidth(badgeText(architecture)) + 40;
        root.setProperty(CoreOptions.NODE_SIZE_CONSTRAINTS, SizeConstraint.minimumSize());
        root.setProperty(CoreOptions.NODE_SIZE_MINIMUM, new KVector(titleWidth, 0));
        map(root, architecture);

        int partition = 0;
        for (Layer layer : layers) {
            List<Line> lines = texts.layerTitle(layer);
            double minWidth = width(lines) + badgeWidth(badgeText(layer)) + 3 * PAD;
            ElkNode node = node(root, layer, minWidth, height(lines) + 2 * PAD);
            node.setProperty(CoreOptions.PARTITIONING_PARTITION, partition++);
            node.setProperty(CoreOptions.DIRECTION, Direction.RIGHT);
            node.setProperty(CoreOptions.NODE_SIZE_CONSTRAINTS, SizeConstraint.minimumSize());
            node.setProperty(CoreOptions.NODE_SIZE_MINIMUM, new KVector(Math.ceil(minWidth), Math.ceil(height(lines) + 2 * PAD + 20)));
            padding(node, height(lines) + 2 * PAD + 6, 14);
            spacing(node);
            for (Module module : layer.getModules()) {
                module(node, module);
            }
        }
        int lowest = Math.max(0, partition - 1);
        for (Actuator actuator : architecture.getActuators()) {
            device(actuator).setProperty(CoreOptions.PARTITIONING_PARTITION, lowest);
        }
        for (Sensor sensor : architecture.getSensors()) {
            device(sensor).setProperty(CoreOptions.PARTITIONING_PARTITION, partition);
        }

        for (Connection connection : architecture.getConnections()) {
            ElkConnectableShape source = shape(connection.getSource());
            ElkConnectableShape target = shape(connection.getTarget());
            if (source != null && target != null) {
                ElkEdge edge = edge(source, target);
                map(edge, connection);
                String badge = badgeText(connection);
                if (badge != null) {
                    badgeLabel(edge, badge);
                }
            }
        }
        for (Layer layer : layers) {
            for (Module module : layer.getModules()) {
                for (Inhibitor inhibitor : module.getInhibitors()) {
                    subsumption(module, inhibitor, inhibitor.getTarget());
                }
                for (Suppressor suppressor : module.getSuppressors()) {
                    subsumption(module, suppressor, suppressor.getTarget());
                }
            }
        }
        for (Sensor sensor : architecture.getSensors()) {
            for (Module module : sensor.getModules()) {
                if (shapeOf.get(module) != null) {
                    edge((ElkConnectableShape) shapeOf.get(sensor), (ElkConnectableShape) shapeOf.get(module));
                }
            }
        }
        for (Actuator actuator : architecture.getActuators()) {
            for (Module module : actuator.getModules()) {
                if (shapeOf.get(module) != null) {
                    edge((ElkConnectableShape) shapeOf.get(module), (ElkConnectableShape) shapeOf.get(actuator));
                }
            }
        }
    }

    private ElkConnectableShape shape(EObject element) {
        return element == null ? null : (ElkConnectableShape) shapeOf.get(element);
    }

    private void subsumption(Module owner, SubsumptionLink link, Port target) {
        ElkConnectableShape source = link.getTrigger() != null && shape(link.getTrigger()) != null ? shape(link.getTrigger())
                : shape(owner);
        ElkConnectableShape to = shape(target);
        if (source == null || to == null) {
            return;
        }
        ElkEdge edge = edge(source, to);
        map(edge, link);
        String verb = link instanceof Inhibitor ? "inhibits" : "suppresses";
        label(edge, RsamlLabels.name(link) + " " + verb + (link.getDuration() > 0 ? " " + RsamlLabels.duration(link.getDuration(), link) : ""),
                SMALL, false);
        String badge = badgeText(link);
        if (badge != null) {
            badgeLabel(edge, badge);
        }
    }

    private void module(ElkNode layer, Module module) {
        ModuleText text = texts.measure(module);
        moduleTexts.put(module, text);
        double width = 2 * PAD + text.left() + GAP + text.middle() + GAP + text.right() + (text.left() == 0 ? PORT / 2 : 0)
                + (text.right() == 0 ? PORT / 2 : 0);
        int entries = 0;
        int outputs = 0;
        for (Port port : module.getPorts()) {
            if (port instanceof EntryPort) {
                entries++;
            } else {
                outputs++;
            }
        }
        double height = Math.max(2 * PAD + height(text.head()) + (text.items().isEmpty() ? 0 : 4 + ArchitectureTexts.itemsHeight(text.items())),
                (Math.max(entries, outputs) + 1) * PORT_PITCH);
        ElkNode node = node(layer, module, width, height);
        node.setProperty(CoreOptions.PORT_CONSTRAINTS, PortConstraints.FIXED_SIDE);
        // Ports sit across the border, half inside: they are on the module's outline, not beside it.
        node.setProperty(CoreOptions.PORT_BORDER_OFFSET, -PORT / 2);
        for (Port port : module.getPorts()) {
            ElkPort p = org.eclipse.elk.graph.util.ElkGraphUtil.createPort(node);
            p.setDimensions(PORT, PORT);
            p.setProperty(CoreOptions.PORT_SIDE, port instanceof EntryPort ? PortSide.WEST : PortSide.EAST);
            p.setProperty(CoreOptions.PORT_BORDER_OFFSET, -PORT / 2);
            map(p, port);
        }
    }

    private ElkNode device(Device device) {
        List<Line> lines = texts.deviceLines(device);
        double badge = badgeWidth(badgeText(device));
        return node(root, device, width(lines) + (badge > 0 ? badge + 4 : 0) + 2 * PAD + 4, height(lines) + 2 * PAD);
    }

    /**
     * Widens every layer to the span of the widest, keeping what it holds in place, so that the
     * layers read as the paper's horizontal bands rather than boxes of different widths.
     */
    @Override
    void arrange() {
        double left = Double.MAX_VALUE;
        double right = -Double.MAX_VALUE;
        for (Layer layer : layers) {
            ElkNode node = (ElkNode) shapeOf.get(layer);
            left = Math.min(left, node.getX());
            right = Math.max(right, node.getX() + node.getWidth());
        }
        for (Layer layer : layers) {
            ElkNode node = (ElkNode) shapeOf.get(layer);
            double dx = node.getX() - left;
            node.setX(left);
            node.setWidth(right - left);
            for (ElkNode child : node.getChildren()) {
                child.setX(child.getX() + dx);
            }
            for (ElkEdge edge : node.getContainedEdges()) {
                shift(edge, dx);
            }
        }
    }

    private static void shift(ElkEdge edge, double dx) {
        for (ElkEdgeSection section : edge.getSections()) {
            section.setStartX(section.getStartX() + dx);
            section.setEndX(section.getEndX() + dx);
            for (ElkBendPoint bend : section.getBendPoints()) {
                bend.setX(bend.getX() + dx);
            }
        }
        for (ElkLabel label : edge.getLabels()) {
            label.setX(label.getX() + dx);
        }
    }

    // ------------------------------------------------------------ result

    @Override
    void collect() {
        Drawing.Shape frame = shape("architecture", root, null);
        frame.form = "round";
        place(frame.texts, texts.architectureTitle(), frame.x + 16, frame.y + PAD, "start");
        addBadge(frame, frame.x + 16 + width(texts.architectureTitle().subList(0, 1)) + 8, frame.y + PAD);
        List<Drawing.Shape> ports = new ArrayList<>();
        for (Layer layer : layers) {
            ElkNode node = (ElkNode) shapeOf.get(layer);
            Drawing.Shape shape = shape("layer", node, frame);
            shape.form = "round";
            shape.classes.add("level-" + layer.getLevel());
            List<Line> title = texts.layerTitle(layer);
            place(shape.texts, title, shape.x + 10, shape.y + PAD, "start");
            addBadge(shape, shape.x + 10 + title.get(0).width() + 8, shape.y + PAD);
            for (Module module : layer.getModules()) {
                collectModule(module, shape, ports);
            }
        }
        for (Sensor sensor : architecture.getSensors()) {
            collectDevice(sensor, frame, "sensor");
        }
        for (Actuator actuator : architecture.getActuators()) {
            collectDevice(actuator, frame, "actuator");
        }
        collectLinks();
        // Ports last: drawn over the links that end on them.
        drawing.shapes.removeAll(new java.util.HashSet<>(ports)); // a set: a list would make this quadratic
        drawing.shapes.addAll(ports);
    }

    private void collectDevice(Device device, Drawing.Shape frame, String kind) {
        Drawing.Shape shape = shape(kind, (org.eclipse.elk.graph.ElkShape) shapeOf.get(device), frame);
        shape.form = kind.equals("sensor") ? "round" : "rect";
        List<Line> lines = texts.deviceLines(device);
        place(shape.texts, lines, shape.x + PAD + 2, shape.y + PAD, "start");
        addBadge(shape, shape.x + PAD + 2 + lines.get(0).width() + 4, shape.y + PAD);
    }

    private void collectModule(Module module, Drawing.Shape layer, List<Drawing.Shape> ports) {
        ModuleText text = moduleTexts.get(module);
        ElkNode node = (ElkNode) shapeOf.get(module);
        Drawing.Shape shape = shape("module", node, layer);
        shape.form = "round";
        if (module.getType() == ElementType.REAL_TIME) {
            shape.classes.add("realtime");
        }
        double left = shape.x + PAD + (text.left() == 0 ? PORT / 2 : text.left()) + GAP;
        double y = place(shape.texts, text.head(), left, shape.y + PAD, "start");
        addBadge(shape, left + text.head().get(0).width() + 4, shape.y + PAD);
        y += 4;
        Drawing.Shape function = null;
        for (int i = 0; i < text.items().size(); i++) {
            Item item = text.items().get(i);
            double itemHeight = height(item.lines()) + 2;
            if (item.depth() == 0) {
                double h = itemHeight;
                for (Item a : text.items().subList(i + 1, text.items().size())) {
                    if (a.depth() == 0) {
                        break;
                    }
                    h += height(a.lines()) + 2;
                }
                function = item(item, shape, left - 3, y, text.middle() + 6, h);
            } else {
                item(item, function, left + 10, y, text.middle() - 10, itemHeight);
            }
            y += itemHeight;
        }
        for (ElkPort p : node.getPorts()) {
            Port port = (Port) elementOf.get(p);
            Drawing.Shape ps = shape(port instanceof EntryPort ? "entry-port" : "output-port", p, shape);
            ps.form = "port";
            ports.add(ps);
            boolean entry = port instanceof EntryPort;
            double cx = ps.x + ps.width / 2;
            double cy = ps.y + ps.height / 2;
            List<Line> label = List.of(new Line(RsamlLabels.name(port), SMALL, false, "port-label"));
            double lx = entry ? cx + PORT / 2 + 3 : cx - PORT / 2 - 3;
            place(ps.texts, label, lx, cy - label.get(0).height() / 2, entry ? "start" : "end");
            String badge = badgeText(port);
            if (badge != null) {
                double w = badgeWidth(badge);
                double bx = entry ? lx + label.get(0).width() + 3 : lx - label.get(0).width() - 3 - w;
                ps.badges.add(new Drawing.Badge(bx, cy - badgeHeight() / 2, w, badgeHeight(), badge, badgeSeverity(port)));
            }
        }
    }

    private Drawing.Shape item(Item item, Drawing.Shape parent, double x, double y, double width, double height) {
        Drawing.Shape shape = new Drawing.Shape(item.depth() == 0 ? "function" : "action", item.element(), parent);
        shape.form = "item";
        shape.x = x;
        shape.y = y;
        shape.width = width;
        shape.height = height;
        emphasise(item.element(), shape.classes, shape.data);
        if (item.element() instanceof org.rsaml.model.RealTimeElement rt && rt.getExecType() == ExecutionType.PERIODIC) {
            shape.classes.add("periodic");
        }
        place(shape.texts, item.lines(), x + 3, y + 1, "start");
        addBadge(shape, x + 3 + item.lines().get(0).width() + 4, y + 1);
        drawing.shapes.add(shape);
        return shape;
    }

    private void collectLinks() {
        for (Connection connection : architecture.getConnections()) {
            ElkEdge edge = (ElkEdge) shapeOfEdge(connection);
            if (edge != null) {
                link("connection", edge, connection, connection.getSource(), connection.getTarget(), badgeText(connection));
            }
        }
        for (Layer layer : layers) {
            for (Module module : layer.getModules()) {
                for (Inhibitor inhibitor : module.getInhibitors()) {
                    subsumptionLink(inhibitor, module, inhibitor.getTarget(), "I");
                }
                for (Suppressor suppressor : module.getSuppressors()) {
                    subsumptionLink(suppressor, module, suppressor.getTarget(), "S");
                }
            }
        }
        for (ElkEdge edge : allEdges(root)) {
            EObject source = elementOf.get(edge.getSources().get(0));
            EObject target = elementOf.get(edge.getTargets().get(0));
            if (source instanceof Sensor) {
                link("sensor-link", edge, null, source, target, null);
            } else if (target instanceof Actuator) {
                link("actuator-link", edge, null, source, target, null);
            }
        }
    }

    private void subsumptionLink(SubsumptionLink element, Module owner, Port target, String marker) {
        ElkEdge edge = (ElkEdge) shapeOfEdge(element);
        if (edge != null) {
            EObject source = element.getTrigger() != null && shapeOf.get(element.getTrigger()) != null ? element.getTrigger() : owner;
            Drawing.Link link = link(marker.equals("I") ? "inhibitor" : "suppressor", edge, element, source, target, badgeText(element));
            link.marker = marker;
        }
    }

    private Object shapeOfEdge(EObject element) {
        return shapeOf.get(element);
    }

    static List<ElkEdge> allEdges(ElkNode node) {
        List<ElkEdge> edges = new ArrayList<>(node.getContainedEdges());
        for (ElkNode child : node.getChildren()) {
            edges.addAll(allEdges(child));
        }
        return edges;
    }
}
