/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.rsaml.design.tests.SiriusSpecifications.get;
import static org.rsaml.design.tests.SiriusSpecifications.is;
import static org.rsaml.design.tests.SiriusSpecifications.list;
import static org.rsaml.design.tests.SiriusSpecifications.ref;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.rsaml.design.services.RsamlServices;
import org.rsaml.model.Architecture;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.NamedElement;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Suppressor;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.ModelLoader;

/**
 * What an architect finds in the RsaML diagrams: the tools, the looks that tell elements apart, the
 * findings. What a diagram shows for an element is computed by evaluating the specification's own
 * expressions on real models ({@link Expressions}), not read from how they are spelled.
 */
class DiagramsTest {

    private static EObject viewpoint;

    /** Loaded once, by the first test; each test is skipped on its own when Sirius's metamodels are absent. */
    private static EObject viewpoint() throws Exception {
        if (viewpoint == null) {
            viewpoint = list(SiriusSpecifications.load(Repository.siriusMetamodels(), Repository.file(Repository.ECORE),
                    Repository.file(Repository.ODESIGN)).group(), "ownedViewpoints").get(0);
        }
        return viewpoint;
    }

    @Test
    void architectureDiagramCreatesLayersModulesPortsAndLinks() throws Exception {
        assertEquals(Map.ofEntries(Map.entry("Layer", "model.Layer in layers"), Map.entry("Module", "model.Module in modules"),
                Map.entry("Real-time module", "model.Module in modules"), Map.entry("Function", "model.Function in functions"),
                Map.entry("Action", "model.Action in actions"), Map.entry("Real-time action", "model.RTAction in actions"),
                Map.entry("Entry port", "model.EntryPort in ports"), Map.entry("Output port", "model.OutputPort in ports"),
                Map.entry("Connection", "model.Connection in connections"), Map.entry("Inhibitor", "model.Inhibitor in inhibitors"),
                Map.entry("Suppressor", "model.Suppressor in suppressors"), Map.entry("Processor", "model.Processor in processors"),
                Map.entry("Allocation", "sets modules")),
                creations(diagram("Architecture")), "the architecture diagram's palette creates each kind of element where it belongs");
        assertEquals("deleteAllocation", get(ref(mapping(diagram("Architecture"), "AllocationEdge"), "deletionDescription"), "name"),
                "deleting an allocation takes the module off the processor and deletes neither");
        assertEquals("deleteLayer", get(ref(mapping(diagram("Architecture"), "LayerRegion"), "deletionDescription"), "name"),
                "deleting a layer goes through the tool that counts it out of declaredLayers");
    }

    @Test
    void missionDiagramCreatesMissionsGoalsPlansActivitiesSupervisorsAndTheirLinks() throws Exception {
        Map<String, String> tools = creations(diagram("Missions"));
        assertEquals(Map.of("Mission", "model.Mission in missions", "Goal", "model.Goal in goals", "Plan", "model.Plan in plans",
                "Activity", "model.Activity in activities", "Supervisor", "model.Supervisor in supervisors",
                "Sub-goal", "sets subGoals", "Achieves", "sets achieves", "Controls", "sets plans"), tools,
                "the missions diagram's palette creates each kind of element where it belongs");
    }

    @Test
    void layersAreStackedByLevelAndHoldTheirModules() throws Exception {
        EObject stack = mapping(diagram("Architecture"), "ArchitectureStack");
        assertEquals("VerticalStack", get(stack, "childrenPresentation").toString(), "layers are stacked one above the other");
        EObject layer = mapping(diagram("Architecture"), "LayerRegion");
        assertEquals(stack, layer.eContainer(), "each layer is a region of the stack");
        // Highest level on top, whatever order the file lists the layers in.
        Architecture architecture = model("exp1-hybrid.rsaml");
        architecture.getLayers().move(0, 2);
        assertEquals(List.of("functional", "decision", "control"), names(architecture.getLayers()), "the test reordered the file's layers");
        assertEquals(List.of("decision", "control", "functional"), names(shown(layer, architecture)),
                "the diagram shows the highest level on top, whatever the file's order");

        EObject module = mapping(diagram("Architecture"), "ModuleContainer");
        assertEquals(layer, module.eContainer(), "modules are drawn inside their layer");
        Layer control = architecture.getLayers().stream().filter(l -> l.getName().equals("control")).findFirst().orElseThrow();
        assertEquals(List.of("requestChecker", "resourceChecker", "robustnessManager"), names(shown(module, control)),
                "the control layer shows its own modules");

        List<EObject> borders = list(module, "borderedNodeMappings");
        assertEquals(2, borders.size(), "ports sit on the module's border");
        Module checker = control.getModules().get(0);
        assertEquals(List.of("e0_requestCheck"), names(shown(borders.get(0), checker)), "the module's entry port on its border");
        assertEquals(List.of("s0_requestCheck", "s1_requestCheck"), names(shown(borders.get(1), checker)),
                "the module's output ports on its border");
        assertTrue(checker.getPorts().stream().allMatch(p -> names(shown(borders.get(p instanceof EntryPort ? 0 : 1), checker))
                .contains(p.getName())), "entry ports on one border mapping, output ports on the other");
    }

    @Test
    void connectionsInhibitorsAndSuppressorsLookDifferent() throws Exception {
        List<String> looks = new ArrayList<>();
        for (String edge : List.of("ConnectionEdge", "InhibitorEdge", "SuppressorEdge")) {
            EObject style = ref(mapping(diagram("Architecture"), edge), "style");
            looks.add(get(ref(style, "strokeColor"), "name") + " " + get(style, "lineStyle"));
        }
        assertEquals(List.of("black solid", "red dash", "purple dash_dot"), looks,
                "connections, inhibitors and suppressors are drawn in different colours and line styles");

        // Each edge runs from the module that acts to the port it acts on, and says what it does.
        Architecture brooks = model("subsumption-brooks.rsaml");
        List<String> edges = new ArrayList<>();
        for (String edge : List.of("InhibitorEdge", "SuppressorEdge")) {
            EObject mapping = mapping(diagram("Architecture"), edge);
            for (Object link : (List<?>) shown(mapping, brooks)) {
                EObject l = (EObject) link;
                edges.add(name(Expressions.evaluate(get(mapping, "sourceFinderExpression"), l)) + " -> "
                        + name(Expressions.evaluate(get(mapping, "targetFinderExpression"), l)) + ": "
                        + Expressions.evaluate(get(ref(ref(mapping, "style"), "centerLabelStyleDescription"), "labelExpression"), l));
            }
        }
        assertEquals(expectedSubsumption(brooks), edges,
                "each inhibitor and suppressor runs from its module to the port it acts on, labelled with what it does");
    }

    @Test
    void realTimeModulesAndPeriodicFunctionsStandOut() throws Exception {
        Architecture architecture = model("exp1-hybrid.rsaml");
        EObject module = mapping(diagram("Architecture"), "ModuleContainer");
        EObject realTime = list(module, "conditionnalStyles").get(0);
        assertNotEquals(get(ref(ref(module, "style"), "backgroundColor"), "name"),
                get(ref(ref(realTime, "style"), "backgroundColor"), "name"), "a real-time module has a background of its own");
        Map<String, String> modules = new TreeMap<>();
        for (Layer layer : architecture.getLayers()) {
            for (Module m : layer.getModules()) {
                EObject style = Boolean.TRUE.equals(Expressions.evaluate(get(realTime, "predicateExpression"), m)) ? realTime : module;
                modules.put(m.getName(), get(ref(ref(style, "style"), "backgroundColor"), "name") + " "
                        + Expressions.evaluate(get(ref(style, "style"), "labelExpression"), m));
            }
        }
        String plain = get(ref(ref(module, "style"), "backgroundColor"), "name").toString();
        String highlighted = get(ref(ref(realTime, "style"), "backgroundColor"), "name").toString();
        assertEquals(Map.of("temporalExecutive", plain + " temporalExecutive — simple, 120.0 ms",
                "operatorMissionSupervisor", plain + " operatorMissionSupervisor — simple, 50.0 ms",
                "requestChecker", plain + " requestChecker — simple, 1.0 ms",
                "resourceChecker", plain + " resourceChecker — simple, 1.5 ms",
                "robustnessManager", plain + " robustnessManager — simple, 1.8 ms",
                "m01", plain + " m01 — simple, 3.0 ms",
                "m02", highlighted + " m02 — real-time, 4.0 ms every 20.0 ms"), modules, "only the real-time module stands out");

        EObject function = mapping(diagram("Architecture"), "FunctionItem");
        EObject periodic = list(function, "conditionnalStyles").get(0);
        assertNotEquals(get(ref(ref(function, "style"), "labelColor"), "name"), get(ref(ref(periodic, "style"), "labelColor"), "name"),
                "a periodic function's label has a colour of its own");
        Map<String, String> functions = new TreeMap<>();
        Module m01 = architecture.getLayers().get(2).getModules().get(0);
        for (Object f : (List<?>) shown(function, m01)) {
            EObject style = Boolean.TRUE.equals(Expressions.evaluate(get(periodic, "predicateExpression"), (EObject) f)) ? periodic : function;
            functions.put(name(f), get(ref(ref(style, "style"), "labelColor"), "name") + " "
                    + Expressions.evaluate(get(ref(style, "style"), "labelExpression"), (EObject) f));
        }
        assertEquals(Map.of("f0_m01", get(ref(ref(periodic, "style"), "labelColor"), "name") + " f0_m01 — real-time, RM, 1.0 ms every 10.0 ms",
                "f1_m01", get(ref(ref(function, "style"), "labelColor"), "name") + " f1_m01 — simple, FIFO, 2.0 ms"), functions,
                "the periodic function stands out, and both labels give the timing");
    }

    @Test
    void findingsOfRsamlRulesDecorateTheirElementsAsErrorsAndWarnings() throws Exception {
        // One channel: the specification has no validation rules of its own; its decorations show RsaML's findings.
        for (String name : List.of("Architecture", "Missions")) {
            assertEquals(null, ref(diagram(name), "validationSet"), name + " has no validation rules besides RsaML's");
        }
        // What the decorations show on experiment 2: each decoration's precondition holds on an element with
        // findings of its severity, and its tooltip lists them.
        Architecture architecture = model("exp2-defects.rsaml");
        List<EObject> elements = new ArrayList<>(List.of(architecture));
        architecture.eAllContents().forEachRemaining(elements::add);
        List<String> shown = new ArrayList<>();
        EObject decorations = ref(ref(diagram("Architecture"), "defaultLayer"), "decorationDescriptionsSet");
        for (EObject decoration : list(decorations, "decorationDescriptions")) {
            assertTrue(is(decoration, "SemanticBasedDecoration"), get(decoration, "name").toString());
            String target = get(decoration, "domainClass").toString();
            String severity = get(decoration, "name").toString().endsWith("Errors") ? "error" : "warning";
            for (EObject element : elements) {
                if (!element.eClass().getEAllSuperTypes().stream().anyMatch(c -> ("model." + c.getName()).equals(target))
                        && !("model." + element.eClass().getName()).equals(target)) {
                    continue;
                }
                if (Boolean.TRUE.equals(Expressions.evaluate(get(decoration, "preconditionExpression"), element))) {
                    for (String line : Expressions.evaluate(get(decoration, "tooltipExpression"), element).toString().split("\n")) {
                        shown.add(severity + " " + RsamlLabels.qualifiedName(element) + ": " + line);
                    }
                }
            }
        }
        List<String> expected = new ArrayList<>();
        for (ExpectedFinding f : ExpectedFinding.of(TestRepository.example("exp2-defects.rsaml"))) {
            expected.add(f.severity() + " " + f.qualifiedName() + ": " + f.ruleId() + ": " + f.message());
        }
        shown.sort(null);
        expected.sort(null);
        assertEquals(expected, shown, "the decorations of exp2's architecture diagram are its stated findings, each once");
        assertEquals(list(decorations, "decorationDescriptions").stream().filter(d -> get(d, "domainClass").equals("model.NamedElement"))
                .map(d -> get(d, "tooltipExpression")).toList(),
                list(ref(ref(diagram("Missions"), "defaultLayer"), "decorationDescriptionsSet"), "decorationDescriptions").stream()
                        .map(d -> get(d, "tooltipExpression")).toList(),
                "mission diagrams decorate their elements alike");
    }

    @Test
    void designBundleRegistersTheSpecificationAndItsServices() throws Exception {
        assertEquals(List.of(RsamlServices.class.getName()),
                list(viewpoint(), "ownedJavaExtensions").stream().map(e -> get(e, "qualifiedClassName")).toList(),
                "the viewpoint's expressions call RsaML's services class");
        // That Sirius loads the specification through the bundle's registration: SiriusLoadsSpecificationTest.
        String build = Files.readString(Repository.file(Repository.DESIGN + "build.properties"));
        assertTrue(build.contains("description/"), "rsaml.odesign is packaged: " + build);
    }

    // ---------------------------------------------------------------- helpers

    private static Architecture model(String example) throws Exception {
        return ModelLoader.load(TestRepository.example(example), example).architecture();
    }

    /** The elements a mapping shows inside the view of {@code container}: its candidates, evaluated. */
    private static Object shown(EObject mapping, EObject container) {
        return Expressions.evaluate(get(mapping, "semanticCandidatesExpression"), container);
    }

    private static String name(Object element) {
        return element instanceof NamedElement n ? n.getName() : String.valueOf(element);
    }

    private static List<String> names(Object elements) {
        return ((List<?>) elements).stream().map(DiagramsTest::name).toList();
    }

    /** The subsumption links of a model as the diagram should draw them: module -> port: what it does, for how long. */
    private static List<String> expectedSubsumption(Architecture architecture) {
        List<String> links = new ArrayList<>();
        for (String kind : List.of("inhibits", "suppresses")) {
            architecture.eAllContents().forEachRemaining(e -> {
                if (e instanceof SubsumptionLink link && (link instanceof Inhibitor) == kind.equals("inhibits")) {
                    NamedElement target = link instanceof Inhibitor i ? i.getTarget() : ((Suppressor) link).getTarget();
                    links.add(((NamedElement) link.eContainer()).getName() + " -> " + target.getName() + ": " + kind + ": "
                            + link.getName() + (link.getDuration() > 0 ? ", " + RsamlLabels.duration(link.getDuration(), link) : ""));
                }
            });
        }
        return links;
    }

    private static EObject diagram(String name) throws Exception {
        return list(viewpoint(), "ownedRepresentations").stream().filter(r -> name.equals(get(r, "name"))).findFirst().orElseThrow();
    }

    private static EObject mapping(EObject diagram, String name) {
        for (EObject e : (Iterable<EObject>) diagram::eAllContents) {
            if ((is(e, "DiagramElementMapping")) && name.equals(get(e, "name"))) {
                return e;
            }
        }
        throw new AssertionError("no mapping " + name);
    }

    /** Each tool's label, with what it creates ("model.Layer in layers") or, for a link, the reference it sets. */
    private static Map<String, String> creations(EObject diagram) {
        Map<String, String> tools = new TreeMap<>();
        for (EObject section : list(ref(diagram, "defaultLayer"), "toolSections")) {
            for (EObject tool : list(section, "ownedTools")) {
                if (is(tool, "DeleteElementDescription")) {
                    continue;
                }
                String what = null;
                for (EObject operation : (Iterable<EObject>) tool::eAllContents) {
                    if (is(operation, "CreateInstance")) {
                        what = get(operation, "typeName") + " in " + get(operation, "referenceName");
                        break;
                    }
                    if (is(operation, "SetValue") && what == null) {
                        what = "sets " + get(operation, "featureName");
                    }
                }
                tools.put(get(tool, "label").toString(), what);
            }
        }
        return tools;
    }
}
