/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Layer;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rule;

/** What Eclipse shows for a model (the tree editor's Validate action, Sirius's decorations): RsaML's findings, rule id first. */
class DiagnoseTest {

    private static final Path EXP2 = TestRepository.example("exp2-defects.rsaml");
    private static final String CONTROL = "hybridMobileRobotWithDefects/control";
    /** The element of exp2's budget finding, whose expectation the model states. */
    private static final String CHECKER = CONTROL + "/resourceChecker";

    @Test
    void everyFindingBecomesAChildDiagnosticNamedByItsRule() throws Exception {
        LoadedModel model = ModelLoader.load(EXP2, "exp2.rsaml");
        Diagnostic diagnostic = RsamlModelValidator.diagnose(model.architecture());

        assertEquals(Diagnostic.ERROR, diagnostic.getSeverity(), "experiment 2 has errors");
        List<Finding> findings = RsamlModelValidator.validate(model);
        assertEquals(findings.stream().map(f -> f.ruleId() + ": " + f.message()).sorted().collect(Collectors.toList()),
                diagnostic.getChildren().stream().map(Diagnostic::getMessage).sorted().collect(Collectors.toList()),
                "a child diagnostic per finding, worded as the finding");

        ExpectedFinding expected = ExpectedFinding.on(EXP2, CHECKER);
        Diagnostic budget = diagnostic.getChildren().stream().filter(d -> d.getMessage().equals(expected.diagnosticMessage()))
                .findFirst().orElseThrow(() -> new AssertionError("no diagnostic " + expected.diagnosticMessage() + " among "
                        + messages(diagnostic)));
        assertSame(model.resource().getEObject("//@layers[name='control']/@modules[name='resourceChecker']"),
                budget.getData().get(0), "the finding's element comes first, for markers and selection");
        assertEquals(expected.ruleId(), ((Rule) budget.getData().get(1)).id(), "the rule travels with the diagnostic");
    }

    @Test
    void anElementIsDiagnosedWithWhatItContainsOnly() throws Exception {
        LoadedModel model = ModelLoader.load(EXP2, "exp2.rsaml");
        Layer control = model.architecture().getLayers().stream().filter(l -> l.getName().equals("control"))
                .findFirst().orElseThrow();
        List<String> messages = messages(RsamlModelValidator.diagnose(control));
        List<String> expected = ExpectedFinding.of(EXP2).stream().filter(e -> e.qualifiedName().startsWith(CONTROL + "/"))
                .map(ExpectedFinding::diagnosticMessage).toList();
        assertEquals(expected, messages, "RSA-01 of the architecture and the other layers' findings are not the control layer's");
    }

    @Test
    void aCleanModelIsOk() throws Exception {
        // experiment 3 states no finding (experiment 1 has a timing warning)
        assertEquals(List.of(), ExpectedFinding.of(TestRepository.example("exp3-task-interpreter.rsaml")), "exp3 is a clean model");
        EObject root = ModelLoader.load(TestRepository.example("exp3-task-interpreter.rsaml"), "exp3.rsaml").architecture();
        Diagnostic diagnostic = RsamlModelValidator.diagnose(root);
        assertEquals(Diagnostic.OK, diagnostic.getSeverity(), messages(diagnostic).toString());
        assertEquals(List.of(root), diagnostic.getData(), "the diagnostic is about the model it was asked for");
    }

    private static List<String> messages(Diagnostic diagnostic) {
        return diagnostic.getChildren().stream().map(Diagnostic::getMessage).collect(Collectors.toList());
    }
}
