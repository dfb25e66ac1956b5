/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;

/**
 * What one validation has already established about its elements, so that nothing is checked twice.
 * The timing rules need to know, before they analyse, that no element breaks EMF's structural checks
 * or the rules whose errors leave the architecture without a task set (RSA-10, RSA-12, RSA-13,
 * RSA-20); they find that out over the whole architecture when the validation reaches its root,
 * ahead of the diagnostician's own walk, and record it here. The walk then takes those results
 * instead of evaluating them again: an element found structurally sound gets no second structural
 * check, and an invariant already evaluated on an element is not evaluated again. Only definite
 * results are recorded: a check that failed or could not be evaluated is run again by the walk,
 * which reports it as it always does.
 */
final class ValidationFacts {

    private static final Object KEY = ValidationFacts.class;

    private final Map<EObject, Boolean> structurallySound = new IdentityHashMap<>();
    private final Map<EObject, Map<String, Boolean>> invariants = new IdentityHashMap<>();

    /** The facts of the validation whose EMF context this is; null without a context (nothing shared). */
    static ValidationFacts of(Map<Object, Object> context) {
        return context == null ? null : (ValidationFacts) context.computeIfAbsent(KEY, k -> new ValidationFacts());
    }

    void structurallySound(EObject element) {
        structurallySound.put(element, Boolean.TRUE);
    }

    /** Whether the element passed EMF's structural checks earlier in this validation (false when not known). */
    boolean knownStructurallySound(EObject element) {
        return structurallySound.containsKey(element);
    }

    void invariant(EObject element, String constraint, boolean satisfied) {
        invariants.computeIfAbsent(element, k -> new HashMap<>(4)).put(constraint, satisfied);
    }

    /** The invariant's result on the element, when already evaluated in this validation; else null. */
    Boolean invariant(EObject element, String constraint) {
        Map<String, Boolean> known = invariants.get(element);
        return known == null ? null : known.get(constraint);
    }
}
