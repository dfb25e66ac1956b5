/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.design.services.RsamlServices;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Processor;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.ModelLoader;

/**
 * What the diagrams' Java services show for each element of real models: the labels an architect
 * reads, and the findings that decorate an element as errors and warnings. These need no Sirius.
 */
class ServicesTest {

    private final RsamlServices services = new RsamlServices();

    private static Architecture load(Path model) throws Exception {
        return ModelLoader.load(model, model.getFileName().toString()).architecture();
    }

    private static List<EObject> elements(Architecture architecture) {
        List<EObject> all = new ArrayList<>(List.of(architecture));
        architecture.eAllContents().forEachRemaining(all::add);
        return all;
    }

    private Map<String, String> labels(Path model, String... names) throws Exception {
        Map<String, String> labels = new LinkedHashMap<>();
        for (EObject e : elements(load(model))) {
            String name = RsamlLabels.qualifiedName(e);
            if (List.of(names).contains(name)) {
                labels.put(name, services.rsamlLabel(e));
            }
        }
        return labels;
    }

    @Test
    void labelsGiveNameKindAndTiming() throws Exception {
        Map<String, String> expected = new LinkedHashMap<>();
        expected.put("hybridMobileRobot/functional", "functional — level 0, at most 5.0 ms a module");
        expected.put("hybridMobileRobot/decision/temporalExecutive", "temporalExecutive — simple, 120.0 ms");
        expected.put("hybridMobileRobot/functional/m02", "m02 — real-time, 4.0 ms every 20.0 ms");
        expected.put("hybridMobileRobot/functional/m01/f0_m01", "f0_m01 — real-time, RM, 1.0 ms every 10.0 ms");
        // An action is listed in its module, after the functions: its function comes first.
        expected.put("hybridMobileRobot/functional/m01/f0_m01/a1_f0_m01", "f0_m01 › a1_f0_m01 — real-time, 0.4 ms every 10.0 ms");
        expected.put("hybridMobileRobot/inspectionMission/inspectionPlan/scanArea", "scanArea — simple");
        assertEquals(expected, labels(TestRepository.example("exp1-hybrid.rsaml"), expected.keySet().toArray(String[]::new)),
                "each element's diagram label names it and gives its timing");
    }

    @Test
    void processorsShowTheirSchedulingAndCore() throws Exception {
        Map<String, String> expected = new LinkedHashMap<>();
        expected.put("mobileBase/core0", "core0 — fixed priorities, core 0");
        expected.put("mobileBase/core1", "core1 — fixed priorities, core 1");
        assertEquals(expected, labels(TestRepository.example("mobile-base-latency.rsaml"), expected.keySet().toArray(String[]::new)),
                "a processor's label gives its policy and core");
        Processor edf = RsamlFactory.eINSTANCE.createProcessor();
        edf.setName("cpu");
        edf.setSchedPolicy(SchedulingPolicy.EDF);
        assertEquals("cpu — EDF, any core", services.rsamlLabel(edf), "a set policy is named; core -1 is left to the system");
        edf.setHost("arm-board");
        assertEquals("cpu — EDF, any core, on arm-board", services.rsamlLabel(edf), "a processor on another machine names it");
    }

    @Test
    void connectionsShowTheDataTheyCarryAndSuppressorsTheirDuration() throws Exception {
        Map<String, String> expected = new LinkedHashMap<>();
        expected.put("hybridMobileRobot/control/robustnessManager/safeStop", "safeStop, 500.0 ms");
        expected.put("hybridMobileRobot/s0_tempExec -> e0_requestCheck", "alphanumeric");
        expected.put("hybridMobileRobot/s0_m01 -> e0_ressourceCheck", "numeric");
        expected.put("hybridMobileRobot/s1_m01 -> e1_m02", "LaserScan");
        assertEquals(expected, labels(TestRepository.example("exp1-hybrid.rsaml"), expected.keySet().toArray(String[]::new)),
                "a function's label gives its duration, a connection's its data type");
    }

    static Stream<Path> models() throws Exception {
        try (Stream<Path> rules = Files.list(TestRepository.resource("org.rsaml.validation.tests", "rules"))) {
            return Stream.concat(Stream.of(TestRepository.example("exp2-defects.rsaml")),
                    rules.filter(p -> p.toString().endsWith(".rsaml")).sorted().toList().stream());
        }
    }

    /**
     * Each drawn element shows exactly the findings its model states for it and for what it contains
     * that no diagram draws (a function its actions'): errors as errors, warnings as warnings, each as
     * {@code RSA-08: ...}; every other element shows none, so the diagram decorates nothing else.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("models")
    void everyElementShowsExactlyItsOwnFindings(Path model) throws Exception {
        List<ExpectedFinding> stated = ExpectedFinding.of(model);
        Map<String, String> expected = new LinkedHashMap<>();
        Map<String, String> shown = new LinkedHashMap<>();
        List<EObject> all = elements(load(model));
        // Where each stated finding is shown: on its element, or on the nearest drawn element that contains it.
        Map<String, String> shownOn = new LinkedHashMap<>();
        for (EObject e : all) {
            shownOn.put(RsamlLabels.qualifiedName(e), RsamlLabels.qualifiedName(RsamlServices.shownOn(e)));
        }
        for (EObject e : all.stream().filter(e -> RsamlServices.shownOn(e) == e).toList()) {
            String name = RsamlLabels.qualifiedName(e);
            for (String severity : List.of("error", "warning")) {
                String text = String.join("\n", stated.stream()
                        .filter(f -> name.equals(shownOn.getOrDefault(f.qualifiedName(), f.qualifiedName())) && f.severity().equals(severity))
                        .map(f -> f.message() == null ? f.ruleId() : f.ruleId() + ": " + f.message()).sorted().toList());
                String seen = severity.equals("error") ? services.rsamlErrors(e) : services.rsamlWarnings(e);
                if (!text.isEmpty() || !seen.isEmpty()) {
                    expected.put(severity + " " + name, text);
                    // Only the rule ids when the model does not state the wording.
                    shown.put(severity + " " + name, String.join("\n", (stated.stream().anyMatch(f -> f.message() == null)
                            ? seen.lines().map(l -> l.substring(0, l.indexOf(':'))) : seen.lines()).sorted().toList()));
                }
            }
        }
        assertEquals(expected, shown, "each element with stated findings shows them, and no other element shows any");
        assertEquals(stated.stream().filter(f -> !f.severity().equals("info")).count(),
                expected.values().stream().mapToLong(v -> v.lines().count()).sum(), "every stated finding is on an element of the model");
    }

    @Test
    void aFixedDefectNoLongerDecoratesItsElement() throws Exception {
        Architecture architecture = load(TestRepository.example("exp2-defects.rsaml"));
        // exp2's module over its layer's budget, as the model's expect comment states it.
        ExpectedFinding overBudget = ExpectedFinding.of(TestRepository.example("exp2-defects.rsaml")).stream()
                .filter(e -> e.ruleId().equals("RSA-08")).findFirst().orElseThrow(() -> new AssertionError("exp2 states an RSA-08 finding"));
        EObject checker = elements(architecture).stream()
                .filter(e -> RsamlLabels.qualifiedName(e).equals(overBudget.qualifiedName())).findFirst().orElseThrow();
        assertEquals(overBudget.diagnosticMessage(), services.rsamlErrors(checker), "the module's decoration says the stated finding");
        Layer control = (Layer) checker.eContainer();
        control.setMaxExecTime(3.0);
        assertEquals("", services.rsamlErrors(checker), "the finding goes with the change that fixes it");
        assertEquals("control — level 1, at most 3.0 ms a module", services.rsamlLabel(control),
                "the layer's label shows its new budget");
        assertFalse(services.rsamlErrors(architecture).isEmpty(), "the other defects are still shown");
    }
}
