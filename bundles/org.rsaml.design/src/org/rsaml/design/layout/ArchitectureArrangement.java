/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.layout;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.draw2d.IFigure;
import org.eclipse.draw2d.geometry.Dimension;
import org.eclipse.draw2d.geometry.Rectangle;
import org.eclipse.emf.transaction.RecordingCommand;
import org.eclipse.gef.ConnectionEditPart;
import org.eclipse.gef.EditPart;
import org.eclipse.gef.commands.Command;
import org.eclipse.gmf.runtime.common.core.command.CommandResult;
import org.eclipse.gmf.runtime.diagram.ui.commands.ICommandProxy;
import org.eclipse.gmf.runtime.diagram.ui.editparts.DiagramEditPart;
import org.eclipse.gmf.runtime.diagram.ui.editparts.IGraphicalEditPart;
import org.eclipse.gmf.runtime.emf.commands.core.command.AbstractTransactionalCommand;
import org.eclipse.gmf.runtime.notation.LayoutConstraint;
import org.eclipse.gmf.runtime.notation.Location;
import org.eclipse.gmf.runtime.notation.Node;
import org.eclipse.gmf.runtime.notation.Size;
import org.eclipse.sirius.diagram.DNodeListElement;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramBorderNodeEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramContainerEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramElementEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramListEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramNameEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramNodeEditPart;
import org.eclipse.sirius.ext.gmf.runtime.gef.ui.figures.SiriusWrapLabel;
import org.eclipse.swt.widgets.Display;
import org.rsaml.model.Architecture;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;

/**
 * The arrangement of an architecture diagram: the layers stacked as Sirius stacks them, each layer as tall as its
 * tallest module plus a band below it for connection labels; a layer's modules in one row, in the model's order, each
 * module as large as its title and functions need and tall enough for its ports, spaced so that the names of the
 * entry ports (on the left border, named to the left) and of the output ports (on the right border, named to the
 * right) fit between two modules. Sizes come from the figures Sirius draws, so fonts and icons are accounted for.
 */
final class ArchitectureArrangement {

    /** Space around the modules of a layer, between two modules, and below them for connection labels. */
    private static final int MARGIN = 12;
    private static final int GAP = 24;
    private static final int LABEL_BAND = 44;
    /** Space between a port and its name, and between two ports of a side. */
    private static final int LABEL_GAP = 3;
    private static final int PORT_SPACING = 6;
    /** Padding of a module's figure around its title and functions. */
    private static final int MODULE_PADDING = 16;

    private ArchitectureArrangement() {
    }

    static Command command(DiagramEditPart diagram) {
        return new ICommandProxy(new AbstractTransactionalCommand(diagram.getEditingDomain(), "Arrange the architecture", null) {
            @Override
            protected CommandResult doExecuteWithResult(IProgressMonitor monitor, IAdaptable info) throws ExecutionException {
                arrange(diagram);
                Display display = Display.getCurrent();
                if (display != null) {
                    display.asyncExec(() -> settle(diagram, display));
                }
                return CommandResult.newOKCommandResult();
            }
        });
    }

    /**
     * Once the arrangement has reached the figures: the ports are placed again (Sirius places a port on the border of
     * its module as drawn when the port moves, and the modules were still drawn at their former sizes), and when
     * that has reached the figures too, the connection labels are placed on the figures as drawn.
     */
    private static void settle(DiagramEditPart diagram, Display display) {
        if (!diagram.isActive()) {
            return;
        }
        var domain = diagram.getEditingDomain();
        domain.getCommandStack().execute(new RecordingCommand(domain, "Arrange the architecture's ports") {
            @Override
            protected void doExecute() {
                arrange(diagram);
            }
        });
        display.asyncExec(() -> EdgeLabelPlacement.place(diagram));
    }

    private static void arrange(DiagramEditPart diagram) {
        // Sizes are read from the figures: have them laid out first (a diagram opened for the first time is not yet).
        diagram.getFigure().getUpdateManager().performValidation();
        for (IGraphicalEditPart stack : find(diagram, p -> p instanceof IDiagramContainerEditPart && target(p) instanceof Architecture)) {
            int width = 0;
            int height = 0;
            List<IGraphicalEditPart> layers = find(stack, p -> p instanceof IDiagramContainerEditPart && target(p) instanceof Layer);
            for (IGraphicalEditPart layer : layers) {
                Dimension size = arrangeLayer(layer);
                width = Math.max(width, size.width);
                height += size.height;
            }
            int stackTitle = titleBand(stack);
            setBounds(stack, MARGIN, MARGIN, width + 2 * MARGIN, height + stackTitle + MARGIN);
            placeProcessors(diagram, MARGIN + width + 2 * MARGIN + 6 * MARGIN);
        }
    }

    /** The processors in a column to the right of the layers, each wide enough for its label. */
    private static void placeProcessors(DiagramEditPart diagram, int x) {
        int y = MARGIN;
        for (IGraphicalEditPart processor : find(diagram, p -> p instanceof IDiagramNodeEditPart && target(p) instanceof Processor)) {
            Dimension label = new Dimension();
            for (IFigure text : texts(processor.getFigure())) {
                label = text.getPreferredSize();
            }
            Dimension size = processor.getFigure().getSize();
            int width = Math.max(size.width, label.width + 2 * MODULE_PADDING);
            int height = Math.max(size.height, label.height + MODULE_PADDING);
            setBounds(processor, x, y, width, height);
            y += height + 2 * MARGIN;
        }
    }

    private static List<IFigure> texts(IFigure figure) {
        List<IFigure> found = new ArrayList<>();
        if (figure instanceof SiriusWrapLabel) {
            found.add(figure);
        }
        for (Object child : figure.getChildren()) {
            found.addAll(texts((IFigure) child));
        }
        return found;
    }

    /** Places a layer's modules and sizes the layer; returns the layer's size. */
    private static Dimension arrangeLayer(IGraphicalEditPart layer) {
        int x = MARGIN;
        int tallest = 0;
        List<IGraphicalEditPart> modules = find(layer, p -> p instanceof IDiagramListEditPart && target(p) instanceof Module);
        int gap = gap(layer, modules);
        // Below the layer's title, wherever Sirius starts the layer's contents.
        int top = titleBand(layer) + MARGIN;
        for (IGraphicalEditPart module : modules) {
            List<IGraphicalEditPart> entries = new ArrayList<>();
            List<IGraphicalEditPart> outputs = new ArrayList<>();
            for (IGraphicalEditPart port : find(module, p -> p instanceof IDiagramBorderNodeEditPart && target(p) instanceof Port)) {
                (target(port) instanceof EntryPort ? entries : outputs).add(port);
            }
            int left = widestName(entries) + portSize(entries).width + LABEL_GAP;
            int right = widestName(outputs) + portSize(outputs).width + LABEL_GAP;
            Dimension content = content(module);
            int title = titleHeight(module);
            int pitch = Math.max(portSize(entries).height, Math.max(portSize(outputs).height, nameHeight(entries, outputs))) + PORT_SPACING;
            int portsHeight = title + PORT_SPACING + Math.max(entries.size(), outputs.size()) * pitch;
            int width = content.width;
            int height = Math.max(content.height, portsHeight);
            x += left;
            setBounds(module, x, top, width, height);
            placePorts(entries, -portSize(entries).width / 2, title + PORT_SPACING, pitch, true);
            placePorts(outputs, width - portSize(outputs).width / 2, title + PORT_SPACING, pitch, false);
            x += width + right + gap;
            tallest = Math.max(tallest, height);
        }
        int width = Math.max(x - gap + MARGIN, preferredTitleWidth(layer) + 2 * MARGIN);
        int height = titleBand(layer) + top + tallest + LABEL_BAND;
        setSize(layer, width, height);
        return new Dimension(width, height);
    }

    /**
     * The space between two modules of a layer: enough for the label of a connection between two of its modules,
     * which runs between their ports' names.
     */
    private static int gap(IGraphicalEditPart layer, List<IGraphicalEditPart> modules) {
        int gap = GAP;
        for (IGraphicalEditPart module : modules) {
            for (IGraphicalEditPart port : find(module, p -> p instanceof IDiagramBorderNodeEditPart)) {
                for (Object connection : port.getSourceConnections()) {
                    if (connection instanceof ConnectionEditPart edge && edge.getTarget() != null && isInside(edge.getTarget(), layer)) {
                        for (Object child : edge.getChildren()) {
                            if (child instanceof IDiagramNameEditPart && child instanceof IGraphicalEditPart label) {
                                gap = Math.max(gap, label.getFigure().getPreferredSize().width + 2 * GAP);
                            }
                        }
                    }
                }
            }
        }
        return gap;
    }

    private static boolean isInside(EditPart part, EditPart ancestor) {
        for (EditPart p = part; p != null; p = p.getParent()) {
            if (p == ancestor) {
                return true;
            }
        }
        return false;
    }

    /** Ports down one side of their module, each with its name outside the module, centred on the port. */
    private static void placePorts(List<IGraphicalEditPart> ports, int x, int top, int pitch, boolean nameOnTheLeft) {
        int y = top;
        for (IGraphicalEditPart port : ports) {
            Dimension size = port.getFigure().getSize();
            setLocation(port, x, y);
            IGraphicalEditPart name = name(port);
            if (name != null) {
                Dimension label = name.getFigure().getPreferredSize();
                int labelX = nameOnTheLeft ? -label.width - LABEL_GAP : size.width + LABEL_GAP;
                setLocation(name, labelX, (size.height - label.height) / 2);
            }
            y += pitch;
        }
    }

    /** The size a module's title and functions need. */
    private static Dimension content(IGraphicalEditPart module) {
        IGraphicalEditPart title = name(module);
        Dimension titleSize = title == null ? new Dimension() : title.getFigure().getPreferredSize();
        int width = titleSize.width;
        int height = titleSize.height;
        for (IGraphicalEditPart item : find(module, p -> p instanceof IDiagramNameEditPart && p.resolveSemanticElement() instanceof DNodeListElement)) {
            Dimension size = item.getFigure().getPreferredSize();
            width = Math.max(width, size.width);
            height += size.height;
        }
        return new Dimension(width + 2 * MODULE_PADDING, height + 2 * MODULE_PADDING);
    }

    private static int titleHeight(IGraphicalEditPart module) {
        IGraphicalEditPart title = name(module);
        return (title == null ? 0 : title.getFigure().getPreferredSize().height) + MODULE_PADDING / 2;
    }

    private static int preferredTitleWidth(IGraphicalEditPart container) {
        IGraphicalEditPart title = name(container);
        return title == null ? 0 : title.getFigure().getPreferredSize().width;
    }

    /** Height of the band a container's title takes above its contents, as drawn now. */
    private static int titleBand(IGraphicalEditPart container) {
        IGraphicalEditPart title = name(container);
        if (title == null) {
            return MARGIN;
        }
        Rectangle outer = absolute(container.getFigure(), container.getFigure().getBounds());
        Rectangle label = absolute(title.getFigure(), title.getFigure().getBounds());
        return Math.max(label.bottom() - outer.y, title.getFigure().getPreferredSize().height) + MODULE_PADDING / 2;
    }

    private static int widestName(List<IGraphicalEditPart> ports) {
        int widest = 0;
        for (IGraphicalEditPart port : ports) {
            IGraphicalEditPart name = name(port);
            if (name != null) {
                widest = Math.max(widest, name.getFigure().getPreferredSize().width);
            }
        }
        return widest;
    }

    private static int nameHeight(List<IGraphicalEditPart> entries, List<IGraphicalEditPart> outputs) {
        int tallest = 0;
        for (List<IGraphicalEditPart> side : List.of(entries, outputs)) {
            for (IGraphicalEditPart port : side) {
                IGraphicalEditPart name = name(port);
                if (name != null) {
                    tallest = Math.max(tallest, name.getFigure().getPreferredSize().height);
                }
            }
        }
        return tallest;
    }

    private static Dimension portSize(List<IGraphicalEditPart> ports) {
        return ports.isEmpty() ? new Dimension() : ports.get(0).getFigure().getSize();
    }

    /** The label edit part that draws the name of {@code part} (its title, or a port's name). */
    static IGraphicalEditPart name(IGraphicalEditPart part) {
        for (Object child : part.getChildren()) {
            if (child instanceof IDiagramNameEditPart name && child instanceof IGraphicalEditPart graphical
                    && name.resolveDiagramElement() == ((IDiagramElementEditPart) part).resolveDiagramElement()) {
                return graphical;
            }
        }
        return null;
    }

    static Object target(IGraphicalEditPart part) {
        return part instanceof IDiagramElementEditPart element ? element.resolveTargetSemanticElement() : null;
    }

    /** The edit parts below {@code root} that {@code match}es, not looking inside those found. */
    static List<IGraphicalEditPart> find(EditPart root, Predicate<IGraphicalEditPart> match) {
        List<IGraphicalEditPart> found = new ArrayList<>();
        for (Object child : root.getChildren()) {
            if (child instanceof IGraphicalEditPart part && match.test(part)) {
                found.add(part);
            } else if (child instanceof EditPart part) {
                found.addAll(find(part, match));
            }
        }
        return found;
    }

    static Rectangle absolute(IFigure figure, Rectangle relative) {
        Rectangle result = relative.getCopy();
        figure.translateToAbsolute(result);
        return result;
    }

    private static void setLocation(IGraphicalEditPart part, int x, int y) {
        LayoutConstraint constraint = ((Node) part.getNotationView()).getLayoutConstraint();
        if (constraint instanceof Location location) {
            location.setX(x);
            location.setY(y);
        }
    }

    private static void setSize(IGraphicalEditPart part, int width, int height) {
        LayoutConstraint constraint = ((Node) part.getNotationView()).getLayoutConstraint();
        if (constraint instanceof Size size) {
            size.setWidth(width);
            size.setHeight(height);
        }
    }

    private static void setBounds(IGraphicalEditPart part, int x, int y, int width, int height) {
        setLocation(part, x, y);
        setSize(part, width, height);
    }
}
