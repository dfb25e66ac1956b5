/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.sirius.diagram.DDiagram;
import org.eclipse.sirius.diagram.DDiagramElement;
import org.eclipse.sirius.diagram.DDiagramElementContainer;
import org.eclipse.sirius.diagram.DEdge;
import org.eclipse.sirius.diagram.DNode;
import org.eclipse.sirius.diagram.EdgeTarget;
import org.eclipse.sirius.diagram.description.DiagramDescription;
import org.eclipse.sirius.diagram.description.tool.ContainerCreationDescription;
import org.eclipse.sirius.diagram.description.tool.EdgeCreationDescription;
import org.eclipse.sirius.diagram.description.tool.NodeCreationDescription;
import org.eclipse.sirius.diagram.tools.api.command.DiagramCommandFactoryService;
import org.eclipse.sirius.diagram.tools.api.command.IDiagramCommandFactory;
import org.eclipse.sirius.tools.api.command.ui.NoUICallback;
import org.eclipse.sirius.viewpoint.description.tool.AbstractToolDescription;
import org.eclipse.sirius.viewpoint.description.tool.ToolDescription;
import org.rsaml.model.support.RsamlLabels;

/**
 * The tools of a diagram's palette run as Sirius runs the one a user picks (through its command factory, with no
 * dialogue), each checked to be runnable and to add, draw or delete what it should; every change is counted so that
 * {@link #undoAll} can take them back.
 */
final class Palette {

    private final SiriusProject project;
    private final IDiagramCommandFactory factory;
    private int changes;

    Palette(SiriusProject project) {
        this.project = project;
        this.factory = DiagramCommandFactoryService.getInstance().getNewProvider().getCommandFactory(project.domain());
        factory.setUserInterfaceCallBack(new NoUICallback());
    }

    /** Sirius's command factory, for a tool a test builds itself. */
    IDiagramCommandFactory factory() {
        return factory;
    }

    /** Runs a command a tool built, counted for {@link #undoAll}. */
    void execute(Command command) {
        project.execute(command);
        changes++;
    }

    /** Undoes every command run since the last call. */
    void undoAll() {
        for (; changes > 0; changes--) {
            project.undo();
        }
    }

    static AbstractToolDescription tool(DDiagram diagram, String name) {
        DiagramDescription description = diagram.getDescription();
        return description.getDefaultLayer().getToolSections().stream().flatMap(s -> s.getOwnedTools().stream())
                .filter(AbstractToolDescription.class::isInstance).map(AbstractToolDescription.class::cast)
                .filter(t -> t.getName().equals(name)).findFirst()
                .orElseThrow(() -> new AssertionError("the palette has the tool " + name));
    }

    static DDiagramElement drawn(DDiagram diagram, EObject target) {
        return diagram.getDiagramElements().stream().filter(d -> d.getTarget() == target).findFirst()
                .orElseThrow(() -> new AssertionError(RsamlLabels.qualifiedName(target) + " is drawn in " + diagram.getName()));
    }

    static <T> T only(List<T> added, String what) {
        assertEquals(1, added.size(), "the tool adds one " + what + ": " + added);
        return added.get(0);
    }

    /** Runs a creation tool on the element that draws {@code on} (the diagram itself when null) and returns what it added to {@code list}. */
    <T extends EObject> T create(DDiagram diagram, String toolName, EObject on, List<T> list, String what) {
        List<T> before = new ArrayList<>(list);
        AbstractToolDescription tool = tool(diagram, toolName);
        Command command;
        if (on == null && tool instanceof ContainerCreationDescription c) {
            command = factory.buildCreateContainerCommandFromTool(diagram, c);
        } else if (on == null && tool instanceof NodeCreationDescription n) {
            command = factory.buildCreateNodeCommandFromTool(diagram, n);
        } else if (tool instanceof ContainerCreationDescription c) {
            command = factory.buildCreateContainerCommandFromTool((DDiagramElementContainer) drawn(diagram, on), c);
        } else if (drawn(diagram, on) instanceof DNode node) {
            command = factory.buildCreateNodeCommandFromTool(node, (NodeCreationDescription) tool);
        } else {
            command = factory.buildCreateNodeCommandFromTool((DDiagramElementContainer) drawn(diagram, on), (NodeCreationDescription) tool);
        }
        assertTrue(command.canExecute(), toolName + " can run on " + (on == null ? "the diagram" : RsamlLabels.qualifiedName(on)));
        execute(command);
        return added(diagram, list, before, what);
    }

    <T extends EObject> T connect(DDiagram diagram, String toolName, EObject source, EObject target, List<T> list, String what) {
        List<T> before = new ArrayList<>(list);
        Command command = factory.buildCreateEdgeCommandFromTool((EdgeTarget) drawn(diagram, source), (EdgeTarget) drawn(diagram, target),
                (EdgeCreationDescription) tool(diagram, toolName));
        assertTrue(command.canExecute(), toolName + " can run from " + RsamlLabels.qualifiedName(source) + " to " + RsamlLabels.qualifiedName(target));
        execute(command);
        return added(diagram, list, before, what);
    }

    void delete(DDiagram diagram, EObject element) {
        Command command = factory.buildDeleteDiagramElement(drawn(diagram, element));
        assertTrue(command.canExecute(), "deleting " + RsamlLabels.qualifiedName(element) + " can run");
        execute(command);
        assertEquals(null, element.eContainer(), RsamlLabels.qualifiedName(element) + " is deleted from the model");
        assertTrue(diagram.getDiagramElements().stream().noneMatch(d -> d.getTarget() == element), "and from the diagram");
    }

    /** Runs a tool the user applies by clicking an element (a function, for actions) and returns what it added to {@code list}. */
    <T extends EObject> T apply(DDiagram diagram, String toolName, EObject on, List<T> list, String what) {
        List<T> before = new ArrayList<>(list);
        Command command = factory.buildGenericToolCommandFromTool(drawn(diagram, on), (ToolDescription) tool(diagram, toolName));
        assertTrue(command.canExecute(), toolName + " can run on " + RsamlLabels.qualifiedName(on));
        execute(command);
        return added(diagram, list, before, what);
    }

    /** The edges drawn from the element that draws {@code source} to the one that draws {@code target}. */
    static List<DEdge> edges(DDiagram diagram, EObject source, EObject target) {
        return diagram.getEdges().stream().filter(e -> ((DDiagramElement) e.getSourceNode()).getTarget() == source)
                .filter(e -> ((DDiagramElement) e.getTargetNode()).getTarget() == target).toList();
    }

    /** Draws a link with an edge tool and returns its one edge. */
    DEdge link(DDiagram diagram, String toolName, EObject source, EObject target) {
        Command command = factory.buildCreateEdgeCommandFromTool((EdgeTarget) drawn(diagram, source), (EdgeTarget) drawn(diagram, target),
                (EdgeCreationDescription) tool(diagram, toolName));
        assertTrue(command.canExecute(), toolName + " can run from " + RsamlLabels.qualifiedName(source) + " to " + RsamlLabels.qualifiedName(target));
        execute(command);
        List<DEdge> drawnEdges = edges(diagram, source, target);
        assertEquals(1, drawnEdges.size(), toolName + " draws one edge: " + drawnEdges);
        return drawnEdges.get(0);
    }

    /** Deletes a link's edge from the diagram. */
    void unlink(DDiagram diagram, EObject source, EObject target) {
        Command command = factory.buildDeleteDiagramElement(edges(diagram, source, target).get(0));
        assertTrue(command.canExecute(), "deleting the link can run");
        execute(command);
        assertEquals(List.of(), edges(diagram, source, target), "the link is no longer drawn");
    }

    /** The one element the command added to {@code list} (which held {@code before}), drawn in the diagram. */
    private static <T extends EObject> T added(DDiagram diagram, List<T> list, List<T> before, String what) {
        List<T> added = new ArrayList<>(list);
        added.removeAll(before);
        T created = only(added, what);
        drawn(diagram, created);
        return created;
    }
}
