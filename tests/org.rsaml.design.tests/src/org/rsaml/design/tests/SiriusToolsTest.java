/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.common.command.Command;
import org.eclipse.sirius.diagram.DDiagram;
import org.eclipse.sirius.diagram.DEdge;
import org.eclipse.sirius.diagram.DDiagramElement;
import org.eclipse.sirius.diagram.EdgeTarget;
import org.eclipse.sirius.diagram.description.tool.EdgeCreationDescription;
import org.eclipse.sirius.viewpoint.description.tool.ToolDescription;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.NamedElement;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.RTAction;
import org.rsaml.model.Suppressor;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Severity;

/**
 * The palette of the RsaML diagrams, tool by tool, as Sirius runs a tool the user picks: what each creates
 * is in the model, drawn, named apart from its siblings (twice in a row), and validates as the rules say;
 * deleting it from the diagram removes it from the model (an allocation: the module from the processor). Every change is undone after each test.
 */
class SiriusToolsTest {

    private static final String MODEL = "exp1-hybrid.rsaml";

    private static SiriusProject project;
    private static Architecture architecture;
    private static DDiagram architectureDiagram;
    private static DDiagram missionDiagram;
    private static Palette palette;

    @BeforeAll
    static void diagrams() throws Exception {
        project = SiriusProject.create("rsaml-tools", List.of(MODEL));
        architecture = project.architecture(MODEL);
        architectureDiagram = project.create("Architecture", architecture, "tools architecture");
        missionDiagram = project.create("Missions", architecture, "tools missions");
        palette = new Palette(project);
        assertEquals(Set.of(), findings(), MODEL + " is valid before any tool runs");
    }

    @AfterAll
    static void close() throws Exception {
        if (project != null) {
            project.delete();
        }
    }

    @AfterEach
    void undo() {
        palette.undoAll();
        SiriusProject.flushEvents();
        assertEquals(Set.of(), findings(), "undoing the tools restores the valid model");
    }

    /**
     * What rsaml validate finds in the model now, one line each, but for the findings the model states it gives (experiment 1's
     * timing warning, RSA-24, in its {@code <!-- expect: -->} comment): those are found as stated, or shown here if they change.
     */
    private static Set<String> findings() {
        Set<String> stated = new TreeSet<>();
        try {
            for (org.rsaml.tests.support.ExpectedFinding e : org.rsaml.tests.support.ExpectedFinding.of(
                    org.rsaml.tests.support.TestRepository.example(MODEL))) {
                stated.add(e.ruleId() + " " + e.qualifiedName() + ": " + e.message());
            }
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        Set<String> lines = new TreeSet<>();
        for (Finding f : RsamlModelValidator.validate(architecture)) {
            String line = f.ruleId() + " " + f.qualifiedName() + ": " + f.message();
            if (f.severity() != Severity.INFO && !stated.contains(line)) {
                lines.add(line);
            }
        }
        return lines;
    }

    /** Whether the timing finding names the module among the aperiodic reactions it lists ({@code decision/module}). */
    private static boolean named(String finding, Module module) {
        String name = RsamlLabels.qualifiedName(module);
        String label = name.substring(name.indexOf('/') + 1);
        return finding.contains(" " + label + ",") || finding.contains(" " + label + ")");
    }

    /** The allocation edges drawn from the module. */
    private static List<DEdge> allocations(DDiagram diagram, Module module) {
        return diagram.getEdges().stream().filter(e -> ((DDiagramElement) e.getSourceNode()).getTarget() == module)
                .filter(e -> ((DDiagramElement) e.getTargetNode()).getTarget() instanceof Processor).toList();
    }

    /** Draws an allocation edge from the module to the processor with the palette's tool. */
    private void allocate(Module module, Processor processor) {
        Command command = palette.factory().buildCreateEdgeCommandFromTool((EdgeTarget) Palette.drawn(architectureDiagram, module),
                (EdgeTarget) Palette.drawn(architectureDiagram, processor),
                (EdgeCreationDescription) Palette.tool(architectureDiagram, "createAllocation"));
        assertTrue(command.canExecute(), "the allocation tool can run from " + module.getName() + " to " + processor.getName());
        palette.execute(command);
        assertTrue(processor.getModules().contains(module), module.getName() + " is allocated to " + processor.getName());
        List<DEdge> edges = allocations(architectureDiagram, module);
        assertEquals(1, edges.size(), "one allocation edge is drawn from " + module.getName() + ": " + edges);
        assertEquals(processor, ((DDiagramElement) edges.get(0).getTargetNode()).getTarget(), "it points to " + processor.getName());
    }

    private static void namedApart(NamedElement first, NamedElement second) {
        assertNotNull(first.getName(), "the tool names what it creates");
        assertNotEquals(first.getName(), second.getName(), "two elements made by one tool in one place get different names");
    }

    private static Layer layer(int level) {
        return architecture.getLayers().stream().filter(l -> l.getLevel() == level).findFirst().orElseThrow();
    }

    private static Module moduleWith(Layer layer, Class<? extends Port> kind) {
        return layer.getModules().stream().filter(m -> m.getPorts().stream().anyMatch(kind::isInstance)).findFirst()
                .orElseThrow(() -> new AssertionError(layer.getName() + " has a module with an " + kind.getSimpleName()));
    }

    @Test
    void layersAreAddedAboveTheOthersAndCounted() {
        Layer first = palette.create(architectureDiagram, "createLayer", architecture, architecture.getLayers(), "layer");
        Layer second = palette.create(architectureDiagram, "createLayer", architecture, architecture.getLayers(), "layer");
        namedApart(first, second);
        assertEquals(architecture.getLayers().size(), architecture.getDeclaredLayers(), "the declared number of layers follows");
        assertEquals(Set.of(), findings(), "new layers are valid");
        palette.delete(architectureDiagram, second);
        assertEquals(Set.of(), findings(), "deleting a layer leaves a valid model");
    }

    @Test
    void modulesFunctionsAndPortsAreAddedToTheirOwnerAndDeleted() {
        Layer layer = architecture.getLayers().get(0);
        Module first = palette.create(architectureDiagram, "createModule", layer, layer.getModules(), "module");
        Module second = palette.create(architectureDiagram, "createModule", layer, layer.getModules(), "module");
        namedApart(first, second);
        var f1 = palette.create(architectureDiagram, "createFunction", first, first.getFunctions(), "function");
        var f2 = palette.create(architectureDiagram, "createFunction", first, first.getFunctions(), "function");
        namedApart(f1, f2);
        Port in1 = palette.create(architectureDiagram, "createEntryPort", first, first.getPorts(), "entry port");
        Port in2 = palette.create(architectureDiagram, "createEntryPort", first, first.getPorts(), "entry port");
        namedApart(in1, in2);
        assertTrue(in1 instanceof EntryPort, "the entry port tool makes entry ports");
        Port out = palette.create(architectureDiagram, "createOutputPort", first, first.getPorts(), "output port");
        assertTrue(out instanceof OutputPort, "the output port tool makes output ports");
        // A new module has no period and nothing feeds it yet: RSA-19 says so on each (a warning); reacting to data without a
        // period, each is an aperiodic reaction on the default processor, so experiment 1's RSA-24 warning on f0_m01, which
        // names those, names them too; nothing else is found.
        String timing = "RSA-24 hybridMobileRobot/functional/m01/f0_m01";
        Set<String> found = findings();
        assertTrue(found.stream().anyMatch(f -> f.startsWith(timing + ": ") && named(f, first) && named(f, second)),
                "experiment 1's timing warning names the new aperiodic modules: " + found);
        assertEquals(Set.of("RSA-19 " + RsamlLabels.qualifiedName(first), "RSA-19 " + RsamlLabels.qualifiedName(second), timing),
                found.stream().map(f -> f.substring(0, f.indexOf(':'))).collect(java.util.stream.Collectors.toSet()),
                "what rsaml validate finds on the new modules: " + found);
        palette.delete(architectureDiagram, in2);
        palette.delete(architectureDiagram, f2);
        palette.delete(architectureDiagram, second);
        assertTrue(first.eContainer() == layer, "the other module stays");
        assertEquals(Set.of("RSA-19 " + RsamlLabels.qualifiedName(first), timing),
                findings().stream().map(f -> f.substring(0, f.indexOf(':'))).collect(java.util.stream.Collectors.toSet()),
                "deleting the second module removes its finding");
    }

    @Test
    void realTimeModulesArePeriodicWithinTheirLayersBudget() {
        Layer layer = architecture.getLayers().stream().filter(l -> l.getMaxExecTime() > 0).findFirst().orElseThrow();
        Module first = palette.create(architectureDiagram, "createRealTimeModule", layer, layer.getModules(), "real-time module");
        Module second = palette.create(architectureDiagram, "createRealTimeModule", layer, layer.getModules(), "real-time module");
        namedApart(first, second);
        assertEquals(org.rsaml.model.ElementType.REAL_TIME, first.getType(), "the module is real-time");
        assertEquals(org.rsaml.model.ExecutionType.PERIODIC, first.getExecType(), "and periodic, so something activates it");
        assertTrue(first.getPeriod() > 0 && first.getDelay() > 0, "it has a period and a delay, as RSA-05 asks of real-time modules");
        assertTrue(first.getExecDuration() <= layer.getMaxExecTime(), "it takes no more than its layer allows");
        assertEquals(Set.of(), findings(), "new real-time modules are valid");
        palette.delete(architectureDiagram, second);
    }

    @Test
    void aConnectionBetweenPortsOfDifferentDataTypesIsFlaggedAtOnce() {
        OutputPort source = null;
        EntryPort target = null;
        for (Module m : architecture.getLayers().stream().flatMap(l -> l.getModules().stream()).toList()) {
            for (Port p : m.getPorts()) {
                if (p instanceof OutputPort o && source == null) {
                    source = o;
                }
            }
        }
        assertNotNull(source, MODEL + " has an output port");
        final OutputPort from = source;
        for (Module m : architecture.getLayers().stream().flatMap(l -> l.getModules().stream()).toList()) {
            for (Port p : m.getPorts()) {
                if (p instanceof EntryPort e && target == null && e.getModule() != from.getModule()
                        && !RsamlLabels.dataType(e).equals(RsamlLabels.dataType(from))) {
                    target = e;
                }
            }
        }
        assertNotNull(target, MODEL + " has an entry port whose data type differs from " + RsamlLabels.qualifiedName(from) + "'s");
        Connection connection = palette.connect(architectureDiagram, "createConnection", source, target, architecture.getConnections(), "connection");
        assertEquals(source, connection.getSource(), "the connection starts at the output port");
        assertEquals(target, connection.getTarget(), "and ends at the entry port");
        Set<String> found = findings();
        assertEquals(1, found.size(), "the one new finding: " + found);
        assertTrue(found.iterator().next().startsWith("RSA-02 " + RsamlLabels.qualifiedName(connection) + ": "), "RSA-02 on the new connection: " + found);
        DDiagramElement edge = Palette.drawn(architectureDiagram, connection);
        assertFalse(edge.getDecorations().isEmpty() && edge.getTransientDecorations().isEmpty(), "the new connection is decorated at once");
        palette.delete(architectureDiagram, connection);
    }

    @Test
    void inhibitorsAndSuppressorsActOnPortsOfTheLayerBelow() {
        Layer top = architecture.getLayers().stream().max((a, b) -> a.getLevel() - b.getLevel()).orElseThrow();
        Layer below = layer(top.getLevel() - 1);
        Module actor = top.getModules().get(0);
        Module inhibited = moduleWith(below, OutputPort.class);
        OutputPort output = (OutputPort) inhibited.getPorts().stream().filter(OutputPort.class::isInstance).findFirst().orElseThrow();
        Inhibitor i1 = palette.connect(architectureDiagram, "createInhibitor", actor, output, actor.getInhibitors(), "inhibitor");
        Inhibitor i2 = palette.connect(architectureDiagram, "createInhibitor", actor, output, actor.getInhibitors(), "inhibitor");
        namedApart(i1, i2);
        assertEquals(output, i1.getTarget(), "the inhibitor acts on the output port");
        Module suppressed = moduleWith(below, EntryPort.class);
        EntryPort entry = (EntryPort) suppressed.getPorts().stream().filter(EntryPort.class::isInstance).findFirst().orElseThrow();
        Suppressor s = palette.connect(architectureDiagram, "createSuppressor", actor, entry, actor.getSuppressors(), "suppressor");
        assertEquals(entry, s.getTarget(), "the suppressor acts on the entry port");
        assertEquals(Set.of(), findings(), "links to the layer immediately below are valid");
        palette.delete(architectureDiagram, i2);
        palette.delete(architectureDiagram, s);
    }

    @Test
    void actionsAreAddedToTheFunctionClickedAndAPlainOneInARealTimeFunctionIsFlaggedAtOnce() {
        List<Function> functions = new ArrayList<>();
        architecture.eAllContents().forEachRemaining(e -> {
            if (e instanceof Function f) {
                functions.add(f);
            }
        });
        Function simple = functions.stream().filter(f -> f.getType() == ElementType.SIMPLE).findFirst()
                .orElseThrow(() -> new AssertionError(MODEL + " has a simple function"));
        Action a1 = palette.apply(architectureDiagram, "createAction", simple, simple.getActions(), "action");
        Action a2 = palette.apply(architectureDiagram, "createAction", simple, simple.getActions(), "action");
        namedApart(a1, a2);
        assertEquals("Action", a1.eClass().getName(), "the action tool makes plain actions");
        assertEquals(Set.of(), findings(), "plain actions in a simple function are valid");
        assertFalse(palette.factory().buildGenericToolCommandFromTool(Palette.drawn(architectureDiagram, simple.getModule()),
                (ToolDescription) Palette.tool(architectureDiagram, "createAction")).canExecute(), "actions are added to functions, not to modules");

        Function realTime = functions.stream().filter(f -> f.getType() == ElementType.REAL_TIME).findFirst()
                .orElseThrow(() -> new AssertionError(MODEL + " has a real-time function"));
        Action rt = palette.apply(architectureDiagram, "createRealTimeAction", realTime, realTime.getActions(), "real-time action");
        assertTrue(rt instanceof RTAction, "the real-time action tool makes RTActions");
        assertEquals(ElementType.REAL_TIME, rt.getType(), "which are real-time");
        assertEquals(ExecutionType.PERIODIC, rt.getExecType(), "and periodic");
        assertEquals(realTime.getPeriod(), rt.getPeriod(), "with their function's period");
        assertEquals(realTime.getDelay(), rt.getDelay(), "and delay");
        assertEquals(realTime.getTimeUnit(), rt.getTimeUnit(), "in their function's time unit");
        assertEquals(Set.of(), findings(), "a new real-time action in a real-time function is valid");

        Action plain = palette.apply(architectureDiagram, "createAction", realTime, realTime.getActions(), "action");
        Set<String> found = findings();
        assertEquals(1, found.size(), "the one new finding: " + found);
        assertTrue(found.iterator().next().startsWith("RSA-07 " + RsamlLabels.qualifiedName(realTime) + ": "),
                "RSA-07: the real-time function now holds a non-real-time action: " + found);
        palette.delete(architectureDiagram, plain);
        palette.delete(architectureDiagram, a2);
        assertEquals(Set.of(), findings(), "deleting the plain action repairs the function");
    }

    @Test
    void processorsGetCoresOfTheirOwnAndAModuleIsAllocatedToOneAtATime() {
        Processor p1 = palette.create(architectureDiagram, "createProcessor", null, architecture.getProcessors(), "processor");
        Processor p2 = palette.create(architectureDiagram, "createProcessor", null, architecture.getProcessors(), "processor");
        namedApart(p1, p2);
        assertTrue(p1.getCore() >= 0 && p2.getCore() >= 0 && p1.getCore() != p2.getCore(), "each processor has a CPU core of its own: "
                + p1.getCore() + ", " + p2.getCore());
        assertEquals(Set.of(), findings(), "processors without modules are valid");

        Module module = architecture.getLayers().stream().flatMap(l -> l.getModules().stream())
                .filter(m -> m.getType() == ElementType.REAL_TIME).findFirst()
                .orElseThrow(() -> new AssertionError(MODEL + " has a real-time module"));
        allocate(module, p1);
        assertEquals(Set.of(), findings(), module.getName() + " on a core of its own is valid");
        Command again = palette.factory().buildCreateEdgeCommandFromTool((EdgeTarget) Palette.drawn(architectureDiagram, module),
                (EdgeTarget) Palette.drawn(architectureDiagram, p1), (EdgeCreationDescription) Palette.tool(architectureDiagram, "createAllocation"));
        assertFalse(again.canExecute(), "a module is not allocated twice to one processor");

        allocate(module, p2);
        assertFalse(p1.getModules().contains(module), "allocating a module elsewhere moves it: a module runs on one processor");
        assertEquals(Set.of(), findings(), "the moved allocation is valid");

        Command command = palette.factory().buildDeleteDiagramElement(allocations(architectureDiagram, module).get(0));
        assertTrue(command.canExecute(), "deleting the allocation can run");
        palette.execute(command);
        assertEquals(List.of(), p2.getModules(), "deleting the allocation takes the module off the processor");
        assertTrue(module.eContainer() != null && p2.eContainer() == architecture, "and deletes neither the module nor the processor");
        assertEquals(List.of(), allocations(architectureDiagram, module), "the edge is gone");
        palette.delete(architectureDiagram, p1);
        assertEquals(Set.of(), findings(), "deleting a processor leaves a valid model");
    }

    @Test
    void missionLinksAreDeletedWithoutDeletingWhatTheyLink() {
        var mission = palette.create(missionDiagram, "createMission", null, architecture.getMissions(), "mission");
        var goal = palette.create(missionDiagram, "createGoal", mission, mission.getGoals(), "goal");
        var sub = palette.create(missionDiagram, "createGoal", mission, mission.getGoals(), "goal");
        var plan = palette.create(missionDiagram, "createPlan", mission, mission.getPlans(), "plan");
        var supervisor = palette.create(missionDiagram, "createSupervisor", null, architecture.getSupervisors(), "supervisor");

        palette.link(missionDiagram, "createSubGoal", goal, sub);
        assertEquals(List.of(sub), goal.getSubGoals(), "the target goal is a sub-goal of the source");
        palette.unlink(missionDiagram, goal, sub);
        assertEquals(List.of(), goal.getSubGoals(), "deleting the link detaches the sub-goal");
        assertEquals(mission, sub.eContainer(), "which is a goal of its mission again, not deleted");
        assertEquals(mission, goal.eContainer(), "and the parent goal stays");

        palette.link(missionDiagram, "createAchieves", plan, goal);
        assertEquals(List.of(goal), plan.getAchieves(), "the plan achieves the goal");
        palette.unlink(missionDiagram, plan, goal);
        assertEquals(List.of(), plan.getAchieves(), "deleting the link: the plan no longer achieves the goal");
        assertTrue(plan.eContainer() == mission && goal.eContainer() == mission, "both stay");

        palette.link(missionDiagram, "createSupervises", supervisor, plan);
        assertEquals(List.of(plan), supervisor.getPlans(), "the supervisor controls the plan");
        palette.unlink(missionDiagram, supervisor, plan);
        assertEquals(List.of(), supervisor.getPlans(), "deleting the link: the supervisor no longer controls the plan");
        assertTrue(supervisor.eContainer() == architecture && plan.eContainer() == mission, "both stay");
    }

    @Test
    void missionsGoalsPlansActivitiesAndSupervisorsAreAddedAndDeleted() {
        var m1 = palette.create(missionDiagram, "createMission", null, architecture.getMissions(), "mission");
        var m2 = palette.create(missionDiagram, "createMission", null, architecture.getMissions(), "mission");
        namedApart(m1, m2);
        var g1 = palette.create(missionDiagram, "createGoal", m1, m1.getGoals(), "goal");
        var g2 = palette.create(missionDiagram, "createGoal", m1, m1.getGoals(), "goal");
        namedApart(g1, g2);
        var p1 = palette.create(missionDiagram, "createPlan", m1, m1.getPlans(), "plan");
        var a1 = palette.create(missionDiagram, "createActivity", p1, p1.getActivities(), "activity");
        var a2 = palette.create(missionDiagram, "createActivity", p1, p1.getActivities(), "activity");
        namedApart(a1, a2);
        var s1 = palette.create(missionDiagram, "createSupervisor", null, architecture.getSupervisors(), "supervisor");
        var s2 = palette.create(missionDiagram, "createSupervisor", null, architecture.getSupervisors(), "supervisor");
        namedApart(s1, s2);
        Set<String> found = findings();
        palette.delete(missionDiagram, a2);
        palette.delete(missionDiagram, g2);
        palette.delete(missionDiagram, s2);
        palette.delete(missionDiagram, p1);
        palette.delete(missionDiagram, m2);
        assertEquals(Set.of(), found, "new mission elements are valid: " + found);
    }
}
