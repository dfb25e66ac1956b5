/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design;

import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.gef.GraphicalEditPart;
import org.eclipse.gmf.runtime.diagram.ui.services.decorator.IDecorator;
import org.eclipse.gmf.runtime.diagram.ui.services.decorator.IDecoratorTarget;
import org.eclipse.sirius.business.api.session.Session;
import org.eclipse.sirius.diagram.DDiagram;
import org.eclipse.sirius.diagram.DDiagramElement;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramElementEditPart;
import org.eclipse.sirius.diagram.ui.tools.api.decoration.DecorationDescriptor;
import org.eclipse.sirius.diagram.ui.tools.api.decoration.SiriusDecorationDescriptorProvider;
import org.eclipse.sirius.diagram.ui.tools.api.decoration.SiriusDecorationProviderRegistry;

/**
 * One verdict on RsaML's diagrams: the findings are shown by the viewpoint's own decorations (rsaml.odesign's
 * {@code rsamlErrors()}/{@code rsamlWarnings()}, kept up to date with every model change), so Sirius's decoration of
 * the markers its <i>Diagram &gt; Validate</i> leaves (the same findings, in the same words) is not drawn on the
 * elements of RsaML's diagrams: every finding appears once on its element. The markers themselves stay (Problems
 * view, navigation to the element); other viewpoints' diagrams keep Sirius's marker decoration.
 */
final class MarkerDecorations implements SiriusDecorationDescriptorProvider {

    /** Sirius's provider that decorates diagram elements with the markers of <i>Diagram &gt; Validate</i>. */
    private static final String SIRIUS_VALIDATION_PROVIDER = "org.eclipse.sirius.diagram.ui.tools.internal.decoration.ValidationDecorationDescriptorProvider";

    private final SiriusDecorationDescriptorProvider sirius;

    private MarkerDecorations(SiriusDecorationDescriptorProvider sirius) {
        this.sirius = sirius;
    }

    /** Puts Sirius's marker decoration behind one that leaves RsaML's diagrams alone; returns what to undo, or null. */
    static MarkerDecorations install() {
        SiriusDecorationProviderRegistry registry = SiriusDecorationProviderRegistry.INSTANCE;
        for (SiriusDecorationDescriptorProvider provider : List.copyOf(registry.getDecorationDescriptorProviders())) {
            if (provider.getClass().getName().equals(SIRIUS_VALIDATION_PROVIDER)) {
                MarkerDecorations wrapper = new MarkerDecorations(provider);
                registry.removeSiriusDecorationDescriptorProvider(provider);
                registry.addSiriusDecorationDescriptorProvider(wrapper);
                return wrapper;
            }
        }
        return null;
    }

    /** Gives Sirius its own provider back. */
    void uninstall() {
        SiriusDecorationProviderRegistry registry = SiriusDecorationProviderRegistry.INSTANCE;
        if (registry.getDecorationDescriptorProviders().remove(this)) {
            registry.addSiriusDecorationDescriptorProvider(sirius);
        }
    }

    /** Whether the element is drawn on a diagram of the RsaML viewpoint (description/rsaml.odesign of this bundle). */
    static boolean onRsamlDiagram(IDiagramElementEditPart editPart) {
        DDiagramElement element = editPart.resolveDiagramElement();
        DDiagram diagram = element == null ? null : element.getParentDiagram();
        EObject description = diagram == null ? null : diagram.getDescription();
        URI uri = description == null || description.eResource() == null ? null : description.eResource().getURI();
        return uri != null && uri.isPlatformPlugin() && uri.segmentCount() > 1 && Activator.PLUGIN_ID.equals(uri.segment(1));
    }

    @Override
    public boolean provides(IDiagramElementEditPart editPart) {
        return !onRsamlDiagram(editPart) && sirius.provides(editPart);
    }

    @Override
    public List<DecorationDescriptor> getDecorationDescriptors(IDiagramElementEditPart editPart, Session session) {
        return onRsamlDiagram(editPart) ? List.of() : sirius.getDecorationDescriptors(editPart, session);
    }

    @Override
    public void activate(IDecoratorTarget decoratorTarget, IDecorator decorator, GraphicalEditPart editPart) {
        sirius.activate(decoratorTarget, decorator, editPart);
    }

    @Override
    public void deactivate(IDecorator decorator, GraphicalEditPart editPart) {
        sirius.deactivate(decorator, editPart);
    }
}
