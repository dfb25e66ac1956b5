/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.MatchResult;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAnnotation;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.junit.jupiter.api.Test;
import org.rsaml.model.RsamlPackage;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;
import org.rsaml.validation.internal.OclRules;
import org.rsaml.validation.internal.RuleCatalog;
import org.rsaml.validation.internal.TimingChecks;

/** The rules are defined once, in rsaml.ecore and the catalogue, and a broken definition is caught at start-up. */
class RuleDefinitionTest {

    private static EPackage loadEcoreCopy() {
        ResourceSetImpl set = new ResourceSetImpl();
        set.getResourceFactoryRegistry().getExtensionToFactoryMap().put("ecore", new EcoreResourceFactoryImpl());
        Resource r = set.getResource(URI.createFileURI(
                TestRepository.root().resolve("bundles/org.rsaml.model/model/rsaml.ecore").toString()), true);
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
        assertEquals(constraints, OclRules.instance().size(), "every constraint must be parsed at start-up");
    }

    /**
     * The catalogue binds a constraint to its rule by name, not by how the name is spelt: an invariant
     * renamed in the .ecore is reported twice, as a constraint without a rule and as a catalogue entry
     * naming a constraint the .ecore no longer declares.
     */
    @Test
    void aRenamedConstraintIsReportedOnBothSides() {
        EPackage copy = loadEcoreCopy();
        EClass module = (EClass) copy.getEClassifier("Module");
        EAnnotation declared = module.getEAnnotation(EcorePackage.eNS_URI);
        declared.getDetails().put("constraints",
                declared.getDetails().get("constraints").replace("RSA08_layerExecutionBudget", "RSA08_budgetOfLayer"));
        List<String> problems = new OclRules(copy).problems();
        assertTrue(problems.stream().anyMatch(p -> p.startsWith("RSA-08 is in the rule catalogue but no invariant of model declares the constraint RSA08_layerExecutionBudget")),
                "the catalogue's constraint is missing from the .ecore: " + problems);
        assertTrue(problems.stream().anyMatch(p -> p.contains("(RSA08_budgetOfLayer on Module) has no entry")),
                "the renamed constraint belongs to no rule although its name starts with RSA08: " + problems);
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
        assertEquals(List.of("RSA-03 (RSA03_adjacentLayerCommunication on Connection) has no OCL body"), problems, "a constraint without an OCL body is named with its rule and class");
    }

    @Test
    void aConstraintWithoutCatalogueEntryIsReportedWithItsRuleId() {
        EPackage copy = loadEcoreCopy();
        EClass module = (EClass) copy.getEClassifier("Module");
        EAnnotation constraints = module.getEAnnotation("http://www.eclipse.org/emf/2002/Ecore");
        constraints.getDetails().put("constraints", constraints.getDetails().get("constraints") + " RSA77_somethingNew");
        module.getEAnnotation(OclRules.OCL_URI).getDetails().put("RSA77_somethingNew", "true");
        List<String> problems = new OclRules(copy).problems();
        assertEquals(List.of("unknown rule (RSA77_somethingNew on Module) has no entry with a message in the rule catalogue "
                + RuleCatalog.SOURCE_FILE), problems, "a constraint the catalogue does not know is named, saying what to add");
    }

    @Test
    void aCatalogueEntryWithoutInvariantIsReported() {
        EPackage copy = loadEcoreCopy();
        EClass port = (EClass) copy.getEClassifier("Port");
        port.getEAnnotation("http://www.eclipse.org/emf/2002/Ecore").getDetails().put("constraints", "RSA28_topicNameUsable");
        List<String> problems = new OclRules(copy).problems();
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).startsWith("RSA-18 is in the rule catalogue but no invariant"), problems.get(0));
    }

    @Test
    void anIncompleteCatalogueEntryIsReportedWithItsRuleId() throws Exception {
        List<String> problems = new ArrayList<>();
        RuleCatalog.parse(new StringReader("""
                RSA-42.name = new-rule
                RSA-42.severity = warning
                RSA-42.source = RsaML
                RSA-42.context = Module
                RSA-42.description = Something holds.
                RSA-42.scope = Every module.
                RSA-43.name = other-rule
                RSA-43.severity = fatal
                RSA-43.source = RsaML
                RSA-43.context = Module
                RSA-43.description = Something else holds.
                RSA-43.scope = Every module.
                RSA-43.message = {Element} is {notAParameter}
                RSA-43.remediation = Fix it.
                RSA-43.colour = red
                """), problems);
        assertEquals(List.of("rule catalogue: unknown key RSA-43.colour",
                "RSA-42 has no remediation, no message in the rule catalogue",
                "RSA-43 has an unknown severity 'fatal' (error, warning or info)"), problems, "unknown catalogue keys are each named");

        problems.clear();
        RuleCatalog.parse(new StringReader("""
                RSA-43.name = other-rule
                RSA-43.severity = error
                RSA-43.source = RsaML
                RSA-43.context = Module
                RSA-43.description = Something else holds.
                RSA-43.scope = Every module.
                RSA-43.message = {Element} is {notAParameter}
                RSA-43.remediation = Fix it.
                """), problems);
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).startsWith("RSA-43's message names an unknown parameter {notAParameter}; known: "), problems.get(0));
    }

    /**
     * The catalogue binds by data: every invariant of rsaml.ecore (the source file, not only the
     * generated package) is named by exactly one rule, every verdict of the timing analysis too, and
     * every rule names something that implements it.
     */
    @Test
    void everyInvariantAndVerdictIsBoundToExactlyOneRuleAndEveryRuleIsImplemented() {
        Map<String, List<String>> invariants = new TreeMap<>();
        for (EClassifier c : loadEcoreCopy().getEClassifiers()) {
            if (c instanceof EClass e) {
                for (String name : EcoreUtil.getConstraints(e)) {
                    invariants.computeIfAbsent(name, k -> new ArrayList<>()).add(e.getName());
                }
            }
        }
        assertFalse(invariants.isEmpty(), "rsaml.ecore declares no invariant");
        for (String invariant : invariants.keySet()) {
            List<String> rules = Rules.all().stream().filter(r -> r.constraints().contains(invariant)).map(Rule::id).toList();
            assertEquals(1, rules.size(), "the invariant " + invariant + " (on " + invariants.get(invariant)
                    + ") must be named by exactly one rule's constraints in " + RuleCatalog.SOURCE_FILE + ", is by " + rules);
        }
        for (String verdict : TimingChecks.VERDICTS) {
            List<String> rules = Rules.all().stream().filter(r -> r.verdicts().contains(verdict)).map(Rule::id).toList();
            assertEquals(1, rules.size(), "the timing analysis' verdict " + verdict + " must be named by exactly one rule's verdicts in "
                    + RuleCatalog.SOURCE_FILE + ", is by " + rules);
        }
        for (Rule rule : Rules.all()) {
            boolean emf = rule == Rules.STRUCTURE;
            boolean ocl = !rule.constraints().isEmpty() && invariants.keySet().containsAll(rule.constraints());
            boolean timing = rule.isTiming() && !rule.verdicts().isEmpty() && TimingChecks.VERDICTS.containsAll(rule.verdicts());
            assertEquals(1, (emf ? 1 : 0) + (ocl ? 1 : 0) + (timing ? 1 : 0), rule.id() + " must be implemented by exactly one of"
                    + " EMF's structural checks, invariants of rsaml.ecore " + rule.constraints() + " or verdicts of the timing analysis "
                    + rule.verdicts() + " (declared invariants: " + invariants.keySet() + "; verdicts: " + TimingChecks.VERDICTS + ")");
        }
    }

    /**
     * The rules whose errors stop the timing analysis are marked once, by {@code timingPrerequisite}; the
     * scopes that tell users which rules those are (RSA-22's, RSA-24's) name the same rules.
     */
    @Test
    void theScopesNameTheTimingPrerequisitesTheCatalogueMarks() {
        List<String> marked = Rules.timingPrerequisites().stream().map(Rule::id).sorted().toList();
        assertFalse(marked.isEmpty(), "no rule is marked timingPrerequisite in " + RuleCatalog.SOURCE_FILE);
        Pattern list = Pattern.compile("errors? of (RSA-\\d\\d(?:, RSA-\\d\\d)*(?:,? or RSA-\\d\\d)?)");
        int lists = 0;
        for (Rule rule : Rules.all()) {
            Matcher m = list.matcher(rule.scope());
            while (m.find()) {
                lists++;
                List<String> named = Pattern.compile("RSA-\\d\\d").matcher(m.group(1)).results().map(MatchResult::group).sorted().toList();
                assertEquals(marked, named, rule.id() + "'s scope names other rules than those marked timingPrerequisite in "
                        + RuleCatalog.SOURCE_FILE + ": " + rule.scope());
            }
        }
        assertTrue(lists >= 2, "RSA-22's and RSA-24's scopes no longer name the rules that stop the timing analysis");
    }

    @Test
    void aVerdictOfTheTimingAnalysisThatNoRuleReportsIsNamed() throws Exception {
        List<String> problems = new ArrayList<>();
        List<Rule> catalogue = RuleCatalog.parse(new StringReader("""
                RSA-90.name = only-deadlines
                RSA-90.severity = error
                RSA-90.source = timing analysis
                RSA-90.verdicts = task-misses-deadline analysis-failed latency-exceeded task-not-analysed latency-not-analysed no-such-verdict
                RSA-90.context = Module
                RSA-90.description = Something holds.
                RSA-90.scope = Every module.
                RSA-90.message = {Element} misses: {reason}
                RSA-90.remediation = Fix it.
                RSA-91.name = twice
                RSA-91.severity = error
                RSA-91.source = RsaML
                RSA-91.verdicts = task-misses-deadline
                RSA-91.context = Module
                RSA-91.description = Something holds.
                RSA-91.scope = Every module.
                RSA-91.message = {Element} misses
                RSA-91.remediation = Fix it.
                """), problems);
        assertEquals(List.of("RSA-91 and RSA-90 both name task-misses-deadline under verdicts in the rule catalogue; a verdict is reported as one rule",
                "RSA-91 names verdicts of the timing analysis but its source is 'RsaML', not 'timing analysis'"), problems,
                "a verdict bound twice, or to a rule that is not the timing analysis', is refused");
        assertEquals(List.of("the timing analysis' verdict inconsistent-deployment is reported as no rule: name it under the verdicts key"
                + " of a rule of source 'timing analysis' in " + RuleCatalog.SOURCE_FILE,
                "RSA-90 names the verdict no-such-verdict, which the timing analysis does not report; known: "
                        + String.join(", ", TimingChecks.VERDICTS)),
                TimingChecks.bindingProblems(catalogue.subList(0, 1)), "the unbound and the unknown verdict are both named");
    }

    @Test
    void everyRuleHasItsTextsInTheCatalogue() {
        for (Rule rule : Rules.all()) {
            for (String text : new String[] { rule.name(), rule.context(), rule.description(), rule.scope(), rule.remediation() }) {
                assertTrue(text != null && !text.isBlank(), rule.id() + " lacks a text");
            }
            assertEquals(rule.id().equals("RSA-00"), rule.message() == null, rule.id() + "'s message");
        }
    }
}
