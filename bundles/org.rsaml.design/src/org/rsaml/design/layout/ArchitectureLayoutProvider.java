/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.layout;

import java.util.List;

import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.gef.GraphicalEditPart;
import org.eclipse.gef.commands.Command;
import org.eclipse.gmf.runtime.common.core.service.IOperation;
import org.eclipse.gmf.runtime.diagram.ui.editparts.DiagramEditPart;
import org.eclipse.gmf.runtime.diagram.ui.editparts.IGraphicalEditPart;
import org.eclipse.gmf.runtime.diagram.ui.services.layout.AbstractLayoutEditPartProvider;
import org.eclipse.sirius.diagram.DDiagram;
import org.eclipse.sirius.diagram.ui.tools.api.layout.provider.LayoutProvider;
import org.eclipse.sirius.viewpoint.description.Viewpoint;

/**
 * Arranges RsaML's architecture diagrams (Sirius's <i>Arrange All</i>, also run when a diagram is opened for the
 * first time) so that they read well: {@link ArchitectureArrangement} stacks each layer's modules in a row with room
 * for their ports' names, and then {@link EdgeLabelPlacement} puts each connection's label where it covers nothing.
 * Registered on Sirius's {@code layoutProvider} extension point; other diagrams keep Sirius's layouts.
 */
public final class ArchitectureLayoutProvider implements LayoutProvider {

    /** The viewpoint and the diagram description this provider arranges. */
    static final String VIEWPOINT = "RsaML";
    static final String DIAGRAM = "Architecture";

    @Override
    public boolean provides(IGraphicalEditPart container) {
        return container instanceof DiagramEditPart && isArchitectureDiagram(container);
    }

    static boolean isArchitectureDiagram(IGraphicalEditPart part) {
        if (part.resolveSemanticElement() instanceof DDiagram diagram && diagram.getDescription() != null) {
            return DIAGRAM.equals(diagram.getDescription().getName()) && diagram.getDescription().eContainer() instanceof Viewpoint viewpoint
                    && VIEWPOINT.equals(viewpoint.getName());
        }
        return false;
    }

    @Override
    public AbstractLayoutEditPartProvider getLayoutNodeProvider(IGraphicalEditPart container) {
        return new AbstractLayoutEditPartProvider() {
            @Override
            public Command layoutEditParts(GraphicalEditPart containerEditPart, IAdaptable layoutHint) {
                return ArchitectureArrangement.command((DiagramEditPart) container);
            }

            @Override
            @SuppressWarnings("rawtypes")
            public Command layoutEditParts(List selectedObjects, IAdaptable layoutHint) {
                return ArchitectureArrangement.command((DiagramEditPart) container);
            }

            @Override
            public boolean provides(IOperation operation) {
                // Reached through Sirius's layout service only, never through GMF's.
                return false;
            }
        };
    }

    @Override
    public boolean isDiagramLayoutProvider() {
        return true;
    }
}
