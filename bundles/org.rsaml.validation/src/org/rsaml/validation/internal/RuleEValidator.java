/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.DiagnosticChain;
import org.eclipse.emf.ecore.EAnnotation;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EDataType;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.EValidator;
import org.eclipse.emf.ecore.util.EObjectValidator;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.rsaml.model.Architecture;
import org.rsaml.model.Module;
import org.rsaml.model.Port;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlTopics;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * RsaML's validator, the only one of the RsaML package: EMF's structural checks, every OCL invariant
 * of rsaml.ecore reported with its rule's id, severity and the catalogue's message naming elements and
 * values, and the timing rules. The generated package registers no validator (the code generator runs
 * with EMF's {@code EMF_NO_CONSTRAINTS}, and the package names no validation delegate), so nothing
 * else judges RsaML's rules; {@link RsamlValidationSetup} registers this one in EMF's validator
 * registry (the bundle's component does inside OSGi), so that every EMF client — the stock
 * {@code Diagnostician}, the editors, Sirius — reports what {@code rsaml validate} reports.
 *
 * <p>Each element gets EMF's structural checks and then the invariants of its class and its supertypes,
 * in the order EMF's generated validators use (supertypes first, each class's invariants in the order
 * the {@code .ecore} declares them), read from the package: a new invariant needs no code here.
 */
public class RuleEValidator extends EObjectValidator {

    public static final String SOURCE = "org.rsaml.validation";

    /** Creates the validator on first use: parsing the rules is left until something is validated. */
    public static final EValidator.Descriptor DESCRIPTOR = new EValidator.Descriptor() {
        private volatile RuleEValidator validator;

        @Override
        public EValidator getEValidator() {
            if (validator == null) {
                validator = new RuleEValidator(OclRules.instance());
            }
            return validator;
        }
    };

    /**
     * An invariant as an element meets it: its name, the class that declares it, its OCL text, its evaluator, and
     * whether it is RSA-19's, which validation decides by one traversal ({@link ModuleActivation}), and whether its rule is a
     * timing prerequisite.
     */
    private record Invariant(String constraint, EClass declaredOn, String expression, OclRules.Evaluator evaluator, boolean activation,
            boolean prerequisite) {
    }

    /**
     * How EMF's structural findings (RSA-00) name elements and features, whichever client validates (the
     * command line, the stock {@code Diagnostician} of Sirius's Validate): {@code Connection 'robot/c1'}.
     */
    public static final EValidator.SubstitutionLabelProvider LABELS = new EValidator.SubstitutionLabelProvider() {
        @Override
        public String getObjectLabel(EObject eObject) {
            return eObject.eClass().getName() + " '" + RsamlLabels.qualifiedName(eObject) + "'";
        }

        @Override
        public String getFeatureLabel(EStructuralFeature feature) {
            return feature.getName();
        }

        @Override
        public String getValueLabel(EDataType eDataType, Object value) {
            return EcoreUtil.convertToString(eDataType, value);
        }
    };

    private final OclRules rules;
    private final Map<EClass, List<Invariant>> invariants = new ConcurrentHashMap<>();

    public RuleEValidator(OclRules rules) {
        this.rules = rules;
    }

    @Override
    protected EPackage getEPackage() {
        return RsamlPackage.eINSTANCE;
    }

    /**
     * EMF's checks and the OCL invariants, then the timing rules (the catalogue's rules of source {@code timing analysis}).
     * EMF's own findings are reported as RSA-00, in RsaML's words ({@link #LABELS}), whichever client asked.
     */
    @Override
    protected boolean validate(int classifierID, Object value, DiagnosticChain diagnostics, Map<Object, Object> context) {
        if (!(value instanceof EObject eObject)) {
            return true; // RsaML's data types and enumerations declare no constraint
        }
        EClassifier classifier = getEPackage().getEClassifiers().get(classifierID);
        BasicDiagnostic found = diagnostics == null ? null : new BasicDiagnostic();
        // RsaML's labels for EMF's messages, unless the validation already uses them (RsamlModelValidator's does throughout)
        Object clientLabels = context == null ? null : context.get(EValidator.SubstitutionLabelProvider.class);
        boolean ours = clientLabels == LABELS;
        if (context != null && !ours) {
            context.put(EValidator.SubstitutionLabelProvider.class, LABELS);
        }
        ValidationFacts facts = ValidationFacts.of(context);
        boolean result;
        try {
            result = validateElement((EClass) classifier, eObject, found, context, facts);
        } finally {
            if (context != null && !ours) {
                if (clientLabels == null) {
                    context.remove(EValidator.SubstitutionLabelProvider.class);
                } else {
                    context.put(EValidator.SubstitutionLabelProvider.class, clientLabels);
                }
            }
        }
        if (found != null) {
            for (Diagnostic d : found.getChildren()) {
                diagnostics.add(SOURCE.equals(d.getSource()) ? d : structural(d));
            }
        }
        if ((result || diagnostics != null) && TimingChecks.concerns(eObject) && !(facts != null && facts.timingDeferred())) {
            for (TimingChecks.Found f : TimingChecks.on(eObject, context, rules)) {
                result = false;
                if (diagnostics == null) {
                    break;
                }
                diagnostics.add(TimingChecks.diagnostic(f));
            }
        }
        return result;
    }

    private boolean validateElement(EClass eClass, EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context,
            ValidationFacts facts) {
        List<Invariant> applicable = invariants.get(eClass);
        if (applicable == null) {
            applicable = invariants.computeIfAbsent(eClass, this::invariantsOf);
        }
        boolean judging = facts != null && facts.timingDeferred(); // this walk decides the timing rules' prerequisites
        boolean result;
        if (facts != null && facts.knownStructurallySound(eObject)) {
            result = true; // the timing rules' prerequisite pass found it sound in this validation
        } else if (applicable.isEmpty()) {
            result = validate_EveryDefaultConstraint(eObject, diagnostics, context);
            if (!result && judging) {
                facts.taskSetBroken();
            }
            return result;
        } else if (!validate_NoCircularContainment(eObject, diagnostics, context)) {
            if (judging) {
                facts.taskSetBroken();
            }
            return false;
        } else {
            result = validate_EveryMultiplicityConforms(eObject, diagnostics, context);
            if (result || diagnostics != null) {
                result &= validate_EveryDataValueConforms(eObject, diagnostics, context);
            }
            if (result || diagnostics != null) {
                result &= validate_EveryReferenceIsContained(eObject, diagnostics, context);
            }
            if (result || diagnostics != null) {
                result &= validate_EveryBidirectionalReferenceIsPaired(eObject, diagnostics, context);
            }
            if (result || diagnostics != null) {
                result &= validate_EveryProxyResolves(eObject, diagnostics, context);
            }
            if (result || diagnostics != null) {
                result &= validate_UniqueID(eObject, diagnostics, context);
            }
            if (result || diagnostics != null) {
                result &= validate_EveryKeyUnique(eObject, diagnostics, context);
            }
            if (result || diagnostics != null) {
                result &= validate_EveryMapEntryUnique(eObject, diagnostics, context);
            }
        }
        if (!result && judging) {
            facts.taskSetBroken();
        }
        for (Invariant invariant : applicable) {
            if (result || diagnostics != null || judging && invariant.prerequisite()) {
                boolean satisfied = check(invariant, eObject, diagnostics, context);
                result &= satisfied;
                if (!satisfied && judging && invariant.prerequisite()) {
                    facts.taskSetBroken();
                }
            }
        }
        return result;
    }

    /**
     * The invariants an element of {@code eClass} must satisfy: those of its supertypes, then its own;
     * a class that redeclares a supertype's constraint name replaces it in place.
     */
    private List<Invariant> invariantsOf(EClass eClass) {
        List<EClass> classes = new ArrayList<>(eClass.getEAllSuperTypes());
        classes.add(eClass);
        Map<String, Invariant> byName = new LinkedHashMap<>();
        for (EClass c : classes) {
            EAnnotation bodies = c.getEAnnotation(OclRules.OCL_URI);
            for (String constraint : EcoreUtil.getConstraints(c)) {
                byName.put(constraint, new Invariant(constraint, c, bodies == null ? null : bodies.getDetails().get(constraint),
                        rules.evaluator(c, constraint), ModuleActivation.CONSTRAINT.equals(constraint),
                        Rules.forConstraint(constraint).map(r -> TimingChecks.prerequisite(r.id())).orElse(false)));
            }
        }
        return List.copyOf(byName.values());
    }

    /** Evaluates the invariant of rsaml.ecore named {@code constraint} with RsaML's rules, not a global delegate registry. */
    @Override
    public boolean validate(EClass eClass, EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context,
            String validationDelegate, String constraint, String expression, int severity, String source, int code) {
        return check(new Invariant(constraint, eClass, expression, rules.evaluator(eClass, constraint),
                ModuleActivation.CONSTRAINT.equals(constraint), false), eObject, diagnostics, context);
    }

    /** RSA-28's constraint, as named in rsaml.ecore. */
    private static final String TOPICS = "RSA28_topicNameUsable";

    /**
     * What makes the topic a port names unusable ({@code Port.topicProblem()}), from its architecture's table, read once per
     * validation and only if a port needs it (one that names a topic, or whose default topic may be too long).
     */
    private static String topicProblem(Map<Object, Object> context, Port port) {
        if (context == null) {
            return port.topicProblem();
        }
        return RsamlTopics.problem(port, architecture -> {
            @SuppressWarnings("unchecked")
            Map<Architecture, RsamlTopics.Table> tables = (Map<Architecture, RsamlTopics.Table>) context.computeIfAbsent(RsamlTopics.Table.class,
                    k -> new IdentityHashMap<Architecture, RsamlTopics.Table>());
            return tables.computeIfAbsent(architecture, RsamlTopics::table);
        });
    }

    private boolean check(Invariant invariant, EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        EClass eClass = invariant.declaredOn();
        String constraint = invariant.constraint();
        Boolean satisfied;
        try {
            // RSA-19's fixpoint once per validation, not one OCL closure per module (same set; see ModuleActivation).
            if (invariant.activation() && eObject instanceof Module module) {
                satisfied = ModuleActivation.of(context).isActivated(module);
            } else if (TOPICS.equals(constraint) && eObject instanceof Port port) {
                // RSA-28's topic table once per validation, not a pass over every port per port (same answers; see RsamlTopics).
                satisfied = topicProblem(context, port) == null;
            } else if (invariant.evaluator() != null) {
                satisfied = OclRules.evaluate(invariant.evaluator(), eObject);
            } else {
                satisfied = rules.check(eClass, constraint, eObject); // says there is no such invariant
            }
        } catch (RuntimeException e) {
            if (diagnostics != null) {
                reportConstraintDelegateException(eClass, eObject, diagnostics, context, constraint, Diagnostic.ERROR, SOURCE, 0, e);
            }
            return false;
        }
        if (satisfied == null) {
            if (diagnostics != null) {
                reportConstraintDelegateException(eClass, eObject, diagnostics, context, constraint, Diagnostic.ERROR, SOURCE, 0,
                        new IllegalStateException("the expression is invalid for this element"));
            }
            return false;
        }
        if (!satisfied && diagnostics != null) {
            reportConstraintDelegateViolation(eClass, eObject, diagnostics, context, constraint, Diagnostic.ERROR, SOURCE, 0);
        }
        return satisfied;
    }

    @Override
    protected void reportConstraintDelegateViolation(EClass eClass, EObject eObject, DiagnosticChain diagnostics,
            Map<Object, Object> context, String constraint, int severity, String source, int code) {
        Rule rule = Rules.forConstraint(constraint).orElse(Rules.STRUCTURE);
        String message;
        try {
            message = TOPICS.equals(constraint) && eObject instanceof Port port
                    ? MessageParameters.render(rule.message(), eObject, Map.of("topicProblem", String.valueOf(topicProblem(context, port))))
                    : MessageParameters.render(rule.message(), eObject);
        } catch (RuntimeException e) {
            // The finding stands; its message template does not fit this element, and the text says so.
            message = MessageParameters.capitalized(MessageParameters.element(eObject)) + " violates " + rule.id()
                    + " (" + rule.description() + "); its message could not be written: " + e;
        }
        diagnostics.add(new BasicDiagnostic(rule.severity().diagnosticSeverity(), SOURCE, code,
                rule.text(message), new Object[] { eObject, rule, message }));
    }

    @Override
    protected void reportConstraintDelegateException(EClass eClass, EObject eObject, DiagnosticChain diagnostics,
            Map<Object, Object> context, String constraint, int severity, String source, int code, Throwable throwable) {
        Rule rule = Rules.forConstraint(constraint).orElse(Rules.STRUCTURE);
        String message = "Rule " + rule.id() + " could not be evaluated on " + MessageParameters.element(eObject) + ": "
                + throwable.getLocalizedMessage();
        diagnostics.add(new BasicDiagnostic(Diagnostic.ERROR, SOURCE, code, rule.text(message), new Object[] { eObject, rule, message }));
    }

    /** One of EMF's structural findings as RSA-00 reports it: {@code "RSA-00: The required feature ..."}. */
    private static Diagnostic structural(Diagnostic emf) {
        if (emf.getData().isEmpty() || !(emf.getData().get(0) instanceof EObject element)) {
            return emf;
        }
        BasicDiagnostic result = new BasicDiagnostic(emf.getSeverity(), SOURCE, emf.getCode(), Rules.STRUCTURE.text(emf.getMessage()),
                new Object[] { element, Rules.STRUCTURE, emf.getMessage() });
        result.addAll(emf);
        return result;
    }

    /** RSA-09 reports duplicate names with a clearer message than EMF's duplicate-key check. */
    @Override
    public boolean validate_EveryKeyUnique(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return true;
    }
}
