/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Architecture;
import org.rsaml.model.ElementType;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.NamedElement;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/** Findings name the element, its path and its place in the file, and time values compare across units. */
class FindingsTest {

    @Test
    void findingLocatesItsElementByFragmentAndPosition() throws Exception {
        LoadedModel model = ModelLoader.load(TestRepository.example("exp2-defects.rsaml"), "exp2.rsaml");
        List<Finding> findings = RsamlModelValidator.validate(model);
        assertFalse(findings.isEmpty(), "exp2 has findings");
        for (Finding f : findings) {
            EObject element = model.resource().getEObject(f.uriFragment());
            assertNotNull(element, () -> f + ": its fragment " + f.uriFragment() + " leads to an element");
            assertEquals(f.qualifiedName(), RsamlLabels.qualifiedName(element), () -> f + ": the fragment leads to the element the finding names");
            if (element.eContainer() != null && element instanceof NamedElement named && named.getName() != null) {
                assertTrue(f.uriFragment().contains("[name='"),
                        () -> f + ": reports carry a named element's name-keyed fragment, not an index: " + f.uriFragment());
            }
            assertEquals("exp2.rsaml:" + f.line() + ":" + f.column() + ": " + f.severity().label() + " " + f.ruleId() + ": " + f.message(),
                    f.toString(), "a finding prints in compiler style: file:line:column: severity id: message");
        }
    }

    @Test
    void budgetsCompareAcrossTimeUnits() {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName("robot");
        a.setDeclaredLayers(1);
        Layer layer = f.createLayer();
        layer.setName("control");
        layer.setMaxExecTime(2.0);
        layer.setTimeUnit(TimeUnit.MS);
        a.getLayers().add(layer);
        Module module = f.createModule();
        module.setName("checker");
        module.setTimeUnit(TimeUnit.US);
        module.setExecType(ExecutionType.PERIODIC);
        module.setPeriod(10000);
        module.setExecDuration(1500);
        layer.getModules().add(module);
        assertEquals(List.of(), RsamlModelValidator.validate(a), "1500 us within a 2 ms budget is no finding");

        module.setExecDuration(2500);
        List<Finding> findings = RsamlModelValidator.validate(a);
        assertEquals(1, findings.size(), findings.toString());
        assertEquals("Module 'checker' takes 2500.0 us but layer 'control' allows at most 2.0 ms", findings.get(0).message(), "the finding states the module's duration in its own unit and the layer's budget in its unit");
        assertEquals("robot/control/checker", findings.get(0).qualifiedName(), "the finding names the module by its qualified name");
    }

    @Test
    void realTimeModuleWithoutTimingNamesWhatIsMissing() {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName("robot");
        a.setDeclaredLayers(1);
        Layer layer = f.createLayer();
        layer.setName("functional");
        a.getLayers().add(layer);
        Module module = f.createModule();
        module.setName("motion");
        module.setType(ElementType.REAL_TIME);
        module.setExecType(ExecutionType.PERIODIC);
        module.setPeriod(10);
        layer.getModules().add(module);
        List<Finding> findings = RsamlModelValidator.validate(a);
        assertEquals(List.of("RSA-05"), findings.stream().map(Finding::ruleId).toList(), "a real-time module without a delay gets RSA-05 only");
        assertEquals("Real-time module 'motion' has no delay; a real-time module needs a non-zero period and delay",
                findings.get(0).message(), "RSA-05 says what is missing and what a real-time module needs");
    }
}
