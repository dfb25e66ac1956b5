/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.layout;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.draw2d.Connection;
import org.eclipse.draw2d.IFigure;
import org.eclipse.draw2d.geometry.Dimension;
import org.eclipse.draw2d.geometry.Point;
import org.eclipse.draw2d.geometry.PointList;
import org.eclipse.draw2d.geometry.Rectangle;
import org.eclipse.emf.transaction.RecordingCommand;
import org.eclipse.gef.EditPart;
import org.eclipse.gmf.runtime.diagram.ui.editparts.DiagramEditPart;
import org.eclipse.gmf.runtime.diagram.ui.editparts.IBorderItemEditPart;
import org.eclipse.gmf.runtime.diagram.ui.editparts.IGraphicalEditPart;
import org.eclipse.gmf.runtime.diagram.ui.figures.IBorderItemLocator;
import org.eclipse.gmf.runtime.draw2d.ui.geometry.PointListUtilities;
import org.eclipse.gmf.runtime.notation.Location;
import org.eclipse.gmf.runtime.notation.Node;
import org.eclipse.sirius.diagram.DDiagramElement;
import org.eclipse.sirius.diagram.DNode;
import org.eclipse.sirius.diagram.DNodeList;
import org.eclipse.sirius.diagram.DNodeListElement;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramBorderNodeEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramEdgeEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramElementEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramNameEditPart;
import org.eclipse.sirius.diagram.ui.internal.edit.parts.locator.EdgeLabelQuery;
import org.eclipse.sirius.ext.gmf.runtime.gef.ui.figures.SiriusWrapLabel;

/**
 * Puts each connection's label on its line where it covers no node (module, function, port) and no other text:
 * the first free spot going outwards from the middle of the line, on the line or just beside it. Works on the
 * figures as drawn, and stores the result as the label's offset in the diagram, as moving the label by hand would.
 */
final class EdgeLabelPlacement {

    /** Fractions of the line's length tried, from its middle outwards. */
    private static final int STEPS = 18;

    private EdgeLabelPlacement() {
    }

    static void place(DiagramEditPart diagram) {
        if (!diagram.isActive() || diagram.getViewer() == null) {
            return;
        }
        diagram.getFigure().getUpdateManager().performValidation();
        relocatePorts(diagram);
        List<Rectangle> obstacles = new ArrayList<>();
        List<IGraphicalEditPart> labels = new ArrayList<>();
        collect(diagram, obstacles, labels);
        Map<IGraphicalEditPart, Point> offsets = new LinkedHashMap<>();
        for (IGraphicalEditPart label : labels) {
            Connection line = (Connection) ((IGraphicalEditPart) label.getParent()).getFigure();
            Dimension size = label.getFigure().getPreferredSize();
            Rectangle free = freeSpot(line, size, obstacles);
            if (free != null) {
                obstacles.add(free);
                PointList points = line.getPoints().getCopy();
                Point center = free.getCenter();
                line.translateToRelative(center);
                Point reference = PointListUtilities.calculatePointRelativeToLine(points, 0, 50, true);
                offsets.put(label, EdgeLabelQuery.offsetFromRelativeCoordinate(center, points, reference));
            } else {
                obstacles.add(ArchitectureArrangement.absolute(label.getFigure(), label.getFigure().getBounds()));
            }
        }
        if (offsets.isEmpty()) {
            return;
        }
        var domain = diagram.getEditingDomain();
        domain.getCommandStack().execute(new RecordingCommand(domain, "Place the connection labels") {
            @Override
            protected void doExecute() {
                offsets.forEach((label, offset) -> {
                    if (((Node) label.getNotationView()).getLayoutConstraint() instanceof Location location) {
                        location.setX(offset.x);
                        location.setY(offset.y);
                    }
                });
            }
        });
    }

    /**
     * Places the ports again where the arrangement put them. Sirius places each port on its module's border away from
     * the other ports as they were drawn at that moment, and a port moved by the arrangement may still have been drawn
     * where another one goes; once all are drawn at their new places, each one's own place is free.
     */
    private static void relocatePorts(DiagramEditPart diagram) {
        // Twice: a port that had to step aside in the first round finds its place free in the second.
        for (int round = 0; round < 2; round++) {
            relocatePortsOnce(diagram);
        }
    }

    private static void relocatePortsOnce(DiagramEditPart diagram) {
        for (IGraphicalEditPart port : ArchitectureArrangement.find(diagram, p -> p instanceof IDiagramBorderNodeEditPart)) {
            IBorderItemLocator locator = ((IBorderItemEditPart) port).getBorderItemLocator();
            if (locator != null) {
                locator.relocate(port.getFigure());
            }
            IGraphicalEditPart name = ArchitectureArrangement.name(port);
            if (name instanceof IBorderItemEditPart label && label.getBorderItemLocator() != null) {
                label.getBorderItemLocator().relocate(name.getFigure());
            }
        }
        diagram.getFigure().getUpdateManager().performValidation();
    }

    /** The first spot along {@code line}, in absolute coordinates, where a label of {@code size} covers nothing. */
    private static Rectangle freeSpot(Connection line, Dimension size, List<Rectangle> obstacles) {
        PointList points = line.getPoints().getCopy();
        line.translateToAbsolute(points);
        for (int step = 0; step <= STEPS; step++) {
            for (int sign : new int[] { 1, -1 }) {
                int percent = 50 + sign * step * 45 / STEPS;
                Point on = PointListUtilities.calculatePointRelativeToLine(points, 0, percent, true);
                for (int beside : new int[] { 0, -size.height / 2 - 2, size.height / 2 + 2 }) {
                    Rectangle candidate = new Rectangle(on.x - size.width / 2, on.y - size.height / 2 + beside, size.width, size.height);
                    if (obstacles.stream().noneMatch(o -> overlap(o, candidate))) {
                        return candidate;
                    }
                }
                if (step == 0) {
                    break;
                }
            }
        }
        return null;
    }

    private static void collect(EditPart part, List<Rectangle> obstacles, List<IGraphicalEditPart> edgeLabels) {
        for (Object child : part.getChildren()) {
            inspect((EditPart) child, obstacles, edgeLabels);
        }
        if (part instanceof DiagramEditPart diagram) {
            for (Object connection : diagram.getConnections()) {
                inspect((EditPart) connection, obstacles, edgeLabels);
            }
        }
    }

    private static void inspect(EditPart part, List<Rectangle> obstacles, List<IGraphicalEditPart> edgeLabels) {
        if (part instanceof IGraphicalEditPart graphical && graphical.getFigure().isShowing()) {
            DDiagramElement element = part instanceof IDiagramElementEditPart e ? e.resolveDiagramElement() : null;
            IFigure figure = graphical.getFigure();
            if (part instanceof IDiagramNameEditPart && part.getParent() instanceof IDiagramEdgeEditPart) {
                edgeLabels.add(graphical);
                return;
            }
            boolean isNode = element instanceof DNode || element instanceof DNodeList || element instanceof DNodeListElement;
            if (isNode && !(part instanceof IDiagramNameEditPart && !(element instanceof DNodeListElement))) {
                obstacles.add(ArchitectureArrangement.absolute(figure, figure.getBounds()));
            } else if (figure instanceof SiriusWrapLabel label && label.getText() != null && !label.getText().isBlank()) {
                obstacles.add(ArchitectureArrangement.absolute(label, label.getTextBounds()));
            }
            texts(figure, obstacles, graphical);
        }
        collect(part, obstacles, edgeLabels);
    }

    /** The texts a part draws inside its own figure (a layer's title, say). */
    private static void texts(IFigure figure, List<Rectangle> obstacles, IGraphicalEditPart owner) {
        for (Object child : figure.getChildren()) {
            IFigure c = (IFigure) child;
            Object registered = owner.getViewer().getVisualPartMap().get(c);
            if (registered != null && registered != owner) {
                continue;
            }
            if (c instanceof SiriusWrapLabel label && label.isShowing() && label.getText() != null && !label.getText().isBlank()) {
                obstacles.add(ArchitectureArrangement.absolute(label, label.getTextBounds()));
            }
            texts(c, obstacles, owner);
        }
    }

    private static boolean overlap(Rectangle a, Rectangle b) {
        Rectangle common = a.getIntersection(b);
        return common.width > 0 && common.height > 0;
    }
}
