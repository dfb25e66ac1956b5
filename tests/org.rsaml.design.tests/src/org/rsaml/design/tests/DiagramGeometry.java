/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.draw2d.IFigure;
import org.eclipse.draw2d.geometry.Rectangle;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.gef.EditPart;
import org.eclipse.gef.GraphicalEditPart;
import org.eclipse.gmf.runtime.diagram.ui.parts.IDiagramWorkbenchPart;
import org.eclipse.sirius.diagram.DDiagramElement;
import org.eclipse.sirius.diagram.DEdge;
import org.eclipse.sirius.diagram.DNode;
import org.eclipse.sirius.diagram.DNodeContainer;
import org.eclipse.sirius.diagram.DNodeList;
import org.eclipse.sirius.diagram.DNodeListElement;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramElementEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramNameEditPart;
import org.eclipse.sirius.ext.gmf.runtime.gef.ui.figures.SiriusWrapLabel;
import org.eclipse.ui.IEditorPart;
import org.rsaml.model.support.RsamlLabels;

/**
 * What a reader sees of a laid-out Sirius diagram, read from the figures of its open editor (the figures the
 * exported image is painted from): every text drawn, with the bounds of the text itself, and every node's box.
 * {@link #overlaps()} lists what makes the diagram hard to read: two texts over each other, a text cut short, a text
 * and a node other than its own element or one containing it over each other (an edge's label on a module, a port's
 * name on another port, a module over its layer's title).
 */
final class DiagramGeometry {

    /** What a drawn text belongs to. */
    enum Kind {
        PORT_LABEL("port label"), EDGE_LABEL("edge label"), TITLE("title"), ITEM("item"), NODE_LABEL("label");

        final String words;

        Kind(String words) {
            this.words = words;
        }
    }

    /** A text as drawn, in absolute diagram coordinates. */
    record Label(Kind kind, String text, DDiagramElement owner, Rectangle bounds, boolean truncated) {
        @Override
        public String toString() {
            return kind.words + " \"" + text + "\" of " + describe(owner) + " at " + box(bounds);
        }
    }

    /** A node's box (a port, a module, a function, a goal, ...), in absolute diagram coordinates. */
    record Box(DDiagramElement element, Rectangle bounds) {
        @Override
        public String toString() {
            return describe(element) + " at " + box(bounds);
        }
    }

    final String diagram;
    final List<Label> labels = new ArrayList<>();
    final List<Box> nodes = new ArrayList<>();

    private DiagramGeometry(String diagram) {
        this.diagram = diagram;
    }

    /** The geometry of the diagram open in {@code editor}, after Sirius has laid it out. */
    static DiagramGeometry of(String diagram, IEditorPart editor) {
        IDiagramWorkbenchPart part = (IDiagramWorkbenchPart) editor;
        var viewer = part.getDiagramGraphicalViewer();
        part.getDiagramEditPart().getFigure().getUpdateManager().performValidation();
        @SuppressWarnings("unchecked")
        Map<IFigure, EditPart> owners = viewer.getVisualPartMap();
        DiagramGeometry geometry = new DiagramGeometry(diagram);
        for (Object registered : viewer.getEditPartRegistry().values()) {
            if (registered instanceof IDiagramElementEditPart editPart && registered instanceof GraphicalEditPart graphical
                    && graphical.getFigure().isShowing()) {
                DDiagramElement element = editPart.resolveDiagramElement();
                if (element == null) {
                    continue;
                }
                if (isNode(element) && owners.get(graphical.getFigure()) == graphical) {
                    // A name edit part of a node shares its element: only the node's own figure is its box.
                    if (!(graphical instanceof IDiagramNameEditPart) || element instanceof DNodeListElement) {
                        geometry.nodes.add(new Box(element, absolute(graphical.getFigure(), graphical.getFigure().getBounds())));
                    }
                }
                geometry.collectTexts(graphical.getFigure(), graphical, element, owners);
            }
        }
        return geometry;
    }

    private static boolean isNode(DDiagramElement element) {
        return element instanceof DNode || element instanceof DNodeList || element instanceof DNodeListElement;
    }

    /** The texts of {@code figure}'s tree that {@code editPart} draws (not those of its children's edit parts). */
    private void collectTexts(IFigure figure, EditPart editPart, DDiagramElement element, Map<IFigure, EditPart> owners) {
        EditPart owner = owners.get(figure);
        if (owner != null && owner != editPart) {
            return;
        }
        if (!figure.isShowing()) {
            return;
        }
        if (figure instanceof SiriusWrapLabel label && label.getText() != null && !label.getText().isBlank()) {
            labels.add(new Label(kind(element), label.getText(), element, absolute(label, label.getTextBounds()), label.isTextTruncated()));
        }
        for (Object child : figure.getChildren()) {
            collectTexts((IFigure) child, editPart, element, owners);
        }
    }

    private static Kind kind(DDiagramElement element) {
        if (element instanceof DEdge) {
            return Kind.EDGE_LABEL;
        }
        if (element instanceof DNode node && isBorderNode(node)) {
            return Kind.PORT_LABEL;
        }
        if (element instanceof DNodeList || element instanceof DNodeContainer) {
            return Kind.TITLE;
        }
        if (element instanceof DNodeListElement) {
            return Kind.ITEM;
        }
        return Kind.NODE_LABEL;
    }

    private static boolean isBorderNode(DNode node) {
        return node.eContainingFeature() != null && node.eContainingFeature().getName().equals("ownedBorderedNodes");
    }

    private static Rectangle absolute(IFigure figure, Rectangle relative) {
        Rectangle result = relative.getCopy();
        figure.translateToAbsolute(result);
        return result;
    }

    /** Overlaps that make the diagram hard to read, each naming both elements; empty when it reads well. */
    List<String> overlaps() {
        List<String> found = new ArrayList<>();
        for (int i = 0; i < labels.size(); i++) {
            Label a = labels.get(i);
            if (a.truncated()) {
                found.add(a + " is cut short");
            }
            for (int j = i + 1; j < labels.size(); j++) {
                Label b = labels.get(j);
                if (overlap(a.bounds(), b.bounds())) {
                    found.add(a + " overlaps " + b);
                }
            }
            for (Box node : nodes) {
                if (overlap(a.bounds(), node.bounds()) && !mayCover(a, node.element())) {
                    found.add(a + " overlaps " + node);
                }
            }
        }
        return found;
    }

    /**
     * A text may lie on its own element and on what contains it (a port's name on its module's border, a function
     * in its module); never on another node: an edge's label on no node at all, a layer's title under none of its
     * modules, a port's name over no other port or module.
     */
    private static boolean mayCover(Label label, DDiagramElement node) {
        for (EObject e = label.owner(); e != null; e = e.eContainer()) {
            if (e == node) {
                return true;
            }
        }
        return false;
    }

    private static boolean overlap(Rectangle a, Rectangle b) {
        Rectangle common = a.getIntersection(b);
        return common.width > 0 && common.height > 0;
    }

    private static String describe(DDiagramElement element) {
        String mapping = element.getDiagramElementMapping() == null ? "?" : element.getDiagramElementMapping().getName();
        return mapping + " " + (element.getTarget() == null ? "?" : RsamlLabels.qualifiedName(element.getTarget()));
    }

    private static String box(Rectangle r) {
        return "(" + r.x + "," + r.y + " " + r.width + "x" + r.height + ")";
    }
}
