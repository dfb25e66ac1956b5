/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.DiagnosticChain;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EValidator;
import org.rsaml.model.Module;
import org.rsaml.model.util.RsamlValidator;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * The generated validator with RsaML's voice: a violated OCL invariant is reported with its rule's
 * id, severity and the catalogue's message naming elements and values, instead of EMF's generic
 * error. {@link RsamlValidationSetup} registers it for the RsaML package in EMF's validator
 * registry (and the bundle's component does inside OSGi), so that every EMF client — the stock
 * {@code Diagnostician}, the editors, Sirius — reports what {@code rsaml validate} reports.
 */
public class RuleEValidator extends RsamlValidator {

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

    private final OclRules rules;

    public RuleEValidator(OclRules rules) {
        this.rules = rules;
    }

    /** Evaluates the invariant's text from rsaml.ecore with RsaML's parsed rules, not a global delegate registry. */
    @Override
    public boolean validate(EClass eClass, EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context,
            String validationDelegate, String constraint, String expression, int severity, String source, int code) {
        Boolean satisfied;
        try {
            // RSA-19's fixpoint once per validation, not one OCL closure per module (same set; see ModuleActivation).
            ValidationFacts facts = ValidationFacts.of(context);
            Boolean known = facts == null ? null : facts.invariant(eObject, constraint);
            satisfied = known != null ? known
                    : ModuleActivation.CONSTRAINT.equals(constraint) && eObject instanceof Module module
                            ? ModuleActivation.of(context).isActivated(module)
                            : rules.check(eClass, constraint, eObject);
        } catch (RuntimeException e) {
            if (diagnostics != null) {
                reportConstraintDelegateException(eClass, eObject, diagnostics, context, constraint, severity, source, code, e);
            }
            return false;
        }
        if (satisfied == null) {
            if (diagnostics != null) {
                reportConstraintDelegateException(eClass, eObject, diagnostics, context, constraint, severity, source, code,
                        new IllegalStateException("the expression is invalid for this element"));
            }
            return false;
        }
        if (!satisfied && diagnostics != null) {
            reportConstraintDelegateViolation(eClass, eObject, diagnostics, context, constraint, severity, source, code);
        }
        return satisfied;
    }

    @Override
    protected void reportConstraintDelegateViolation(EClass eClass, EObject eObject, DiagnosticChain diagnostics,
            Map<Object, Object> context, String constraint, int severity, String source, int code) {
        Rule rule = Rules.forConstraint(constraint).orElse(Rules.STRUCTURE);
        String message;
        try {
            message = MessageParameters.render(rule.message(), eObject);
        } catch (RuntimeException e) {
            // The finding stands; its message template does not fit this element, and the text says so.
            message = MessageParameters.capitalized(MessageParameters.element(eObject)) + " violates " + rule.id()
                    + " (" + rule.description() + "); its message could not be written: " + e;
        }
        diagnostics.add(new BasicDiagnostic(rule.severity().diagnosticSeverity(), SOURCE, code,
                message + " (" + rule.id() + ")", new Object[] { eObject, rule, message }));
    }

    @Override
    protected void reportConstraintDelegateException(EClass eClass, EObject eObject, DiagnosticChain diagnostics,
            Map<Object, Object> context, String constraint, int severity, String source, int code, Throwable throwable) {
        Rule rule = Rules.forConstraint(constraint).orElse(Rules.STRUCTURE);
        String message = "Rule " + rule.id() + " could not be evaluated on " + MessageParameters.element(eObject) + ": "
                + throwable.getLocalizedMessage();
        diagnostics.add(new BasicDiagnostic(Diagnostic.ERROR, SOURCE, code, message, new Object[] { eObject, rule, message }));
    }

    /** The OCL invariants and EMF's checks of the generated validator, then the timing rules (RSA-22 to RSA-25). */
    @Override
    protected boolean validate(int classifierID, Object value, DiagnosticChain diagnostics, Map<Object, Object> context) {
        boolean result = super.validate(classifierID, value, diagnostics, context);
        if ((result || diagnostics != null) && value instanceof EObject eObject && TimingChecks.concerns(eObject)) {
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

    /*
     * EMF's structural checks, skipped on an element the timing rules' prerequisite pass already found
     * sound in this validation (see ValidationFacts): they would find nothing.
     */

    private static boolean knownSound(EObject eObject, Map<Object, Object> context) {
        ValidationFacts facts = ValidationFacts.of(context);
        return facts != null && facts.knownStructurallySound(eObject);
    }

    @Override
    public boolean validate_EveryMultiplicityConforms(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return knownSound(eObject, context) || super.validate_EveryMultiplicityConforms(eObject, diagnostics, context);
    }

    @Override
    public boolean validate_EveryDataValueConforms(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return knownSound(eObject, context) || super.validate_EveryDataValueConforms(eObject, diagnostics, context);
    }

    @Override
    public boolean validate_EveryReferenceIsContained(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return knownSound(eObject, context) || super.validate_EveryReferenceIsContained(eObject, diagnostics, context);
    }

    @Override
    public boolean validate_EveryBidirectionalReferenceIsPaired(EObject eObject, DiagnosticChain diagnostics,
            Map<Object, Object> context) {
        return knownSound(eObject, context) || super.validate_EveryBidirectionalReferenceIsPaired(eObject, diagnostics, context);
    }

    @Override
    public boolean validate_EveryProxyResolves(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return knownSound(eObject, context) || super.validate_EveryProxyResolves(eObject, diagnostics, context);
    }

    @Override
    public boolean validate_UniqueID(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return knownSound(eObject, context) || super.validate_UniqueID(eObject, diagnostics, context);
    }

    @Override
    public boolean validate_EveryMapEntryUnique(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return knownSound(eObject, context) || super.validate_EveryMapEntryUnique(eObject, diagnostics, context);
    }

    /** RSA-09 reports duplicate names with a clearer message than EMF's duplicate-key check. */
    @Override
    public boolean validate_EveryKeyUnique(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
        return true;
    }
}
