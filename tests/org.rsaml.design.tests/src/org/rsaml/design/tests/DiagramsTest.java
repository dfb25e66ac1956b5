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

/** What an architect finds in the RsaML diagrams: the tools, the looks that tell elements apart, the findings. */
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
        assertEquals(Map.of("Layer", "model.Layer in layers", "Module", "model.Module in modules",
                "Function", "model.Function in functions", "Entry port", "model.EntryPort in ports",
                "Output port", "model.OutputPort in ports", "Connection", "model.Connection in connections",
                "Inhibitor", "model.Inhibitor in inhibitors", "Suppressor", "model.Suppressor in suppressors"),
                creations(diagram("Architecture")));
    }

    @Test
    void missionDiagramCreatesMissionsGoalsPlansActivitiesSupervisorsAndTheirLinks() throws Exception {
        Map<String, String> tools = creations(diagram("Missions"));
        assertEquals(Map.of("Mission", "model.Mission in missions", "Goal", "model.Goal in goals", "Plan", "model.Plan in plans",
                "Activity", "model.Activity in activities", "Supervisor", "model.Supervisor in supervisors",
                "Sub-goal", "sets subGoals", "Achieves", "sets achieves", "Controls", "sets plans"), tools);
    }

    @Test
    void layersAreStackedByLevelAndHoldTheirModules() throws Exception {
        EObject stack = mapping(diagram("Architecture"), "ArchitectureStack");
        assertEquals("VerticalStack", get(stack, "childrenPresentation").toString());
        EObject layer = mapping(diagram("Architecture"), "LayerRegion");
        assertEquals(stack, layer.eContainer());
        assertEquals("aql:self.layers->sortedBy(l | l.level)->reverse()", get(layer, "semanticCandidatesExpression"),
                "highest level on top");
        EObject module = mapping(diagram("Architecture"), "ModuleContainer");
        assertEquals(layer, module.eContainer());
        assertEquals(List.of("EntryPortNode", "OutputPortNode"),
                list(module, "borderedNodeMappings").stream().map(m -> get(m, "name")).toList(), "ports sit on the module's border");
    }

    @Test
    void connectionsInhibitorsAndSuppressorsLookDifferent() throws Exception {
        List<String> looks = new ArrayList<>();
        for (String edge : List.of("ConnectionEdge", "InhibitorEdge", "SuppressorEdge")) {
            EObject style = ref(mapping(diagram("Architecture"), edge), "style");
            looks.add(get(ref(style, "strokeColor"), "name") + " " + get(style, "lineStyle"));
        }
        assertEquals(List.of("black solid", "red dash", "purple dash_dot"), looks);
        assertEquals("feature:target", get(mapping(diagram("Architecture"), "InhibitorEdge"), "targetFinderExpression"));
    }

    @Test
    void realTimeModulesAndPeriodicFunctionsStandOut() throws Exception {
        EObject module = mapping(diagram("Architecture"), "ModuleContainer");
        EObject realTime = list(module, "conditionnalStyles").get(0);
        assertEquals("aql:self.type = model::ElementType::realTime", get(realTime, "predicateExpression"));
        assertNotEquals(get(ref(ref(module, "style"), "backgroundColor"), "name"),
                get(ref(ref(realTime, "style"), "backgroundColor"), "name"));

        EObject function = mapping(diagram("Architecture"), "FunctionItem");
        EObject periodic = list(function, "conditionnalStyles").get(0);
        assertEquals("aql:self.execType = model::ExecutionType::periodic", get(periodic, "predicateExpression"));
        assertNotEquals(get(ref(ref(function, "style"), "labelColor"), "name"), get(ref(ref(periodic, "style"), "labelColor"), "name"));
        // The label gives the timing: "localisation — real-time, 1.0 ms every 20.0 ms".
        assertEquals("aql:self.rsamlLabel()", get(ref(periodic, "style"), "labelExpression"));
        assertEquals("aql:self.rsamlLabel()", get(ref(module, "style"), "labelExpression"));
    }

    @Test
    void findingsOfRsamlRulesAreShownAsErrorsAndWarnings() throws Exception {
        EObject rules = ref(diagram("Architecture"), "validationSet");
        List<String> shown = new ArrayList<>();
        for (EObject rule : list(rules, "ownedRules")) {
            assertTrue(is(rule, "SemanticValidationRule"), get(rule, "name").toString());
            shown.add(get(rule, "level") + " on " + get(rule, "targetClass") + " unless " + get(list(rule, "audits").get(0), "auditExpression")
                    + ", saying " + get(rule, "message"));
        }
        assertEquals(List.of("ERROR on model.NamedElement unless aql:self.rsamlErrors() = '', saying aql:self.rsamlErrors()",
                "WARNING on model.NamedElement unless aql:self.rsamlWarnings() = '', saying aql:self.rsamlWarnings()",
                "ERROR on model.Connection unless aql:self.rsamlErrors() = '', saying aql:self.rsamlErrors()"), shown);
        assertEquals(list(rules, "ownedRules").subList(0, 2), list(ref(diagram("Missions"), "validationSet"), "reusedRules"));
    }

    @Test
    void designBundleRegistersTheSpecificationAndItsServices() throws Exception {
        assertEquals(List.of("org.rsaml.design.services.RsamlServices"),
                list(viewpoint(), "ownedJavaExtensions").stream().map(e -> get(e, "qualifiedClassName")).toList());
        assertTrue(Files.isRegularFile(Repository.file(Repository.SERVICES)));
        String pluginXml = Files.readString(Repository.file(Repository.DESIGN + "plugin.xml"));
        assertTrue(pluginXml.contains("point=\"org.eclipse.sirius.componentization\"")
                && pluginXml.contains("class=\"org.rsaml.design.Activator\""), pluginXml);
        String activator = Files.readString(Repository.file(Repository.DESIGN + "src/org/rsaml/design/Activator.java"));
        assertTrue(activator.contains("\"/description/rsaml.odesign\""), "the activator registers rsaml.odesign");
        String build = Files.readString(Repository.file(Repository.DESIGN + "build.properties"));
        assertTrue(build.contains("description/"), "rsaml.odesign is packaged: " + build);
    }

    // ---------------------------------------------------------------- helpers

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
