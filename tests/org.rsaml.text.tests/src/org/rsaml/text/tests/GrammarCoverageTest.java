/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.ParserRule;
import org.eclipse.xtext.AbstractRule;
import org.junit.jupiter.api.Test;
import org.rsaml.model.RsamlPackage;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.text.RsamlTextStandaloneSetup;
import org.rsaml.text.services.RsamlTextGrammarAccess;

/**
 * The grammar writes every concept, attribute and reference of rsaml.ecore (those a file stores:
 * not the containers' back references), and the language reference documents every word of it.
 */
class GrammarCoverageTest {

    private final RsamlTextGrammarAccess grammar = RsamlTextStandaloneSetup.injector().getInstance(RsamlTextGrammarAccess.class);

    @Test
    void everyStoredFeatureOfEveryConceptHasSyntax() {
        Set<String> written = new TreeSet<>();
        for (AbstractRule rule : grammar.getGrammar().getRules()) {
            if (rule instanceof ParserRule parserRule) {
                for (Assignment assignment : GrammarUtil.containedAssignments(parserRule)) {
                    written.add(assignment.getFeature());
                }
            }
        }
        List<String> missing = new ArrayList<>();
        for (EClassifier classifier : RsamlPackage.eINSTANCE.getEClassifiers()) {
            if (classifier instanceof EClass eClass && !eClass.isAbstract()) {
                for (EStructuralFeature feature : eClass.getEAllStructuralFeatures()) {
                    boolean stored = !feature.isTransient() && !feature.isDerived()
                            && !(feature instanceof EReference r && r.isContainer());
                    if (stored && !written.contains(feature.getName())) {
                        missing.add(eClass.getName() + "." + feature.getName());
                    }
                }
            }
        }
        assertEquals(List.of(), missing, "features of rsaml.ecore without syntax in RsamlText.xtext");
    }

    @Test
    void theLanguageReferenceNamesEveryWord() throws Exception {
        String page = Files.readString(TestRepository.root().resolve("docs/textual-syntax.md"));
        List<String> missing = new ArrayList<>();
        for (String keyword : new TreeSet<>(GrammarUtil.getAllKeywords(grammar.getGrammar()))) {
            if (keyword.matches("[A-Za-z]+") && !page.contains("`" + keyword + "`")) {
                missing.add(keyword);
            }
        }
        assertEquals(List.of(), missing, "words of the grammar that docs/textual-syntax.md does not name");
    }
}
