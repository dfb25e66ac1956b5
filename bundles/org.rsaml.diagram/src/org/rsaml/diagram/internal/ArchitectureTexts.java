/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import static org.rsaml.diagram.internal.ArchitectureLayout.PORT;
import static org.rsaml.diagram.internal.Layout.BODY;
import static org.rsaml.diagram.internal.Layout.SMALL;
import static org.rsaml.diagram.internal.Layout.TITLE;
import static org.rsaml.diagram.internal.Layout.badgeWidth;
import static org.rsaml.diagram.internal.Layout.height;
import static org.rsaml.diagram.internal.Layout.width;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.diagram.internal.Layout.Line;
import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Device;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Port;
import org.rsaml.model.Sensor;
import org.rsaml.model.support.RsamlLabels;

/**
 * What the architecture view writes in its shapes (titles, timing facts, the functions and actions a
 * module lists, the findings' and the timing's lines) and how much room that text takes; the layout
 * places the shapes around it.
 */
final class ArchitectureTexts {

    /** What a module's text looks like once measured: three columns, ports' labels outside the middle. */
    record ModuleText(List<Line> head, List<Item> items, double left, double middle, double right,
            double headBadge) {
    }

    /** A function or action listed in a module. */
    record Item(EObject element, List<Line> lines, double badge, int depth) {
    }

    private final Layout layout;
    private final Architecture architecture;

    ArchitectureTexts(Layout layout) {
        this.layout = layout;
        this.architecture = layout.architecture;
    }

    List<Line> architectureTitle() {
        List<Line> lines = new ArrayList<>();
        lines.add(new Line(RsamlLabels.name(architecture) + " (" + architecture.getCategory().getLiteral() + " architecture)",
                TITLE + 2, true, "title"));
        lines.add(new Line(architecture.getLayers().size() + " layers (" + architecture.getDeclaredLayers() + " declared), "
                + count(Module.class) + " modules, " + architecture.getConnections().size() + " connections", BODY, false, "subtitle"));
        lines.addAll(layout.overlayLines(architecture));
        return lines;
    }

    private long count(Class<?> type) {
        long n = 0;
        for (Layer layer : architecture.getLayers()) {
            n += type == Module.class ? layer.getModules().size() : 0;
        }
        return n;
    }

    List<Line> layerTitle(Layer layer) {
        List<Line> lines = new ArrayList<>();
        lines.add(new Line(RsamlLabels.name(layer), TITLE, true, "title"));
        lines.add(new Line("level " + layer.getLevel() + (layer.getMaxExecTime() > 0
                ? " \u00b7 budget " + RsamlLabels.duration(layer.getMaxExecTime(), layer) + " per module" : ""),
                BODY, false, "timing"));
        lines.addAll(layout.overlayLines(layer));
        return lines;
    }

    ModuleText measure(Module module) {
        List<Line> head = new ArrayList<>();
        double headBadge = layout.titleWithBadge(module, new Line(RsamlLabels.name(module), BODY + 1, true, "title"), head);
        head.add(new Line(RsamlLabels.timingFacts(module), SMALL, false, "timing"));
        head.addAll(layout.overlayLines(module));
        double middle = Math.max(head.get(0).width() + (headBadge > 0 ? headBadge + 4 : 0), width(head.subList(1, head.size())));
        List<Item> items = new ArrayList<>();
        for (Function function : module.getFunctions()) {
            List<Line> lines = new ArrayList<>();
            lines.add(new Line("\u0192 " + RsamlLabels.name(function), BODY, function.getExecType() == ExecutionType.PERIODIC,
                    function.getExecType() == ExecutionType.PERIODIC ? "periodic" : "item"));
            lines.add(new Line(RsamlLabels.timingFacts(function), SMALL, false, "timing"));
            lines.addAll(layout.overlayLines(function));
            double badge = badgeWidth(layout.badgeText(function));
            items.add(new Item(function, lines, badge, 0));
            middle = Math.max(middle, Math.max(lines.get(0).width() + (badge > 0 ? badge + 4 : 0), width(lines.subList(1, lines.size()))) + 8);
            for (Action action : function.getActions()) {
                List<Line> al = new ArrayList<>();
                al.add(new Line(RsamlLabels.name(action) + "  " + RsamlLabels.timingFacts(action), SMALL, false, "action"));
                al.addAll(layout.overlayLines(action));
                double ab = badgeWidth(layout.badgeText(action));
                items.add(new Item(action, al, ab, 1));
                middle = Math.max(middle, width(al) + (ab > 0 ? ab + 4 : 0) + 24);
            }
        }
        double left = 0;
        double right = 0;
        for (Port port : module.getPorts()) {
            double w = TextMetrics.width(RsamlLabels.name(port), SMALL, false) + PORT / 2 + 4;
            String badge = layout.badgeText(port);
            if (badge != null) {
                w += badgeWidth(badge) + 4;
            }
            if (port instanceof EntryPort) {
                left = Math.max(left, w);
            } else {
                right = Math.max(right, w);
            }
        }
        return new ModuleText(head, items, left, middle, right, headBadge);
    }

    static double itemsHeight(List<Item> items) {
        double h = 0;
        for (Item item : items) {
            h += height(item.lines()) + 2;
        }
        return h;
    }

    List<Line> deviceLines(Device device) {
        List<Line> lines = new ArrayList<>();
        lines.add(new Line((device instanceof Sensor ? "sensor " : "actuator ") + RsamlLabels.name(device), BODY, true, "title"));
        List<String> facts = new ArrayList<>();
        if (device.getKind() != null && !device.getKind().isEmpty()) {
            facts.add(device.getKind());
        }
        if (device.getPeriod() > 0) {
            facts.add("T " + RsamlLabels.duration(device.getPeriod(), device));
        }
        if (!facts.isEmpty()) {
            lines.add(new Line(String.join(" \u00b7 ", facts), SMALL, false, "timing"));
        }
        lines.addAll(layout.overlayLines(device));
        return lines;
    }
}
