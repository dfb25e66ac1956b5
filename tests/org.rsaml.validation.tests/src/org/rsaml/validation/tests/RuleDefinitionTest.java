/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAnnotation;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.junit.jupiter.api.Test;
import org.rsaml.model.RsamlPackage;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;
import org.rsaml.validation.RsamlValidationSetup;
import org.rsaml.validation.internal.OclRules;

/** The rules are defined once, in rsaml.ecore, and a broken definition is caught at start-up. */
class RuleDefinitionTest {

    private static EPackage loadEcoreCopy() {
        ResourceSetImpl set = new ResourceSetImpl();
        set.getResourceFactoryRegistry().getExtensionToFactoryMap().put("ecore", new EcoreResourceFactoryImpl());
        Resource r = set.getResource(URI.createFileURI(
                Paths.root().resolve("bundles/org.rsaml.model/model/rsaml.ecore").toString()), true);
        return (EPackage) r.getContents().get(0);
    }

    @Test
    void everyConstraintOfTheEcoreParsesAndBelongsToACatalogedRule() {
        int constraints = 0;
        for (EClassifier c : RsamlPackage.eINSTANCE.getEClassifiers()) {
            if (c instanceof EClass e) {
                for (String name : EcoreUtil.getConstraints(e)) {
                    constraints++;
                    assertTrue(Rules.forConstraint(name).isPresent(), name + " has no rule in the catalog");
                }
            }
        }
        assertTrue(constraints >= 20, "rsaml.ecore declares too few constraints: " + constraints);
        assertEquals(constraints, RsamlValidationSetup.rules().size(), "every constraint must be parsed at start-up");
    }

    @Test
    void aConstraintThatDoesNotParseIsReportedWithItsRuleId() {
        EPackage copy = loadEcoreCopy();
        EClass module = (EClass) copy.getEClassifier("Module");
        EAnnotation ocl = module.getEAnnotation(OclRules.OCL_URI);
        ocl.getDetails().put("RSA08_layerExecutionBudget", "execDuration <= layer.maxExecTime +");
        List<String> problems = new OclRules(copy).problems();
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).startsWith("RSA-08 (RSA08_layerExecutionBudget on Module) does not parse"), problems.get(0));
    }

    @Test
    void aConstraintWithoutBodyIsReportedWithItsRuleId() {
        EPackage copy = loadEcoreCopy();
        EClass connection = (EClass) copy.getEClassifier("Connection");
        connection.getEAnnotation(OclRules.OCL_URI).getDetails().removeKey("RSA03_adjacentLayerCommunication");
        List<String> problems = new OclRules(copy).problems();
        assertEquals(List.of("RSA-03 (RSA03_adjacentLayerCommunication on Connection) has no OCL body"), problems);
    }

    @Test
    void theRulesDocumentListsEveryRuleWithItsSeverity() throws Exception {
        String doc = Files.readString(Paths.root().resolve("docs/rules.md"));
        for (Rule rule : Rules.all()) {
            assertTrue(doc.contains("| " + rule.id() + " | " + rule.name() + " | " + rule.severity().label() + " |"),
                    "docs/rules.md lacks the row of " + rule.id());
        }
    }
}
