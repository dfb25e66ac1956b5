/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.IdentityHashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;

/**
 * What one validation has already established about its elements, so that nothing is checked twice.
 * The timing rules need to know, before they analyse, that no element breaks EMF's structural checks
 * or the rules whose errors leave the architecture without a task set (RSA-10, RSA-12, RSA-13,
 * RSA-20); they find that out over the whole architecture when the validation reaches its root,
 * ahead of the diagnostician's own walk, and record here which elements passed EMF's structural checks:
 * the walk gives those no second structural check. A check that failed is run again by the walk,
 * which reports it as it always does. The invariants' results are not recorded: compiled to Java, an
 * invariant costs less to evaluate again than a result costs to remember and look up.
 */
final class ValidationFacts {

    private static final Object KEY = ValidationFacts.class;

    private final Map<EObject, Boolean> structurallySound = new IdentityHashMap<>();

    /** The facts of the validation whose EMF context this is; null without a context (nothing shared). */
    static ValidationFacts of(Map<Object, Object> context) {
        return context == null ? null : (ValidationFacts) context.computeIfAbsent(KEY, k -> new ValidationFacts());
    }

    /** Set by a walk that is to judge the timing rules' prerequisites itself and report the timing rules after it. */
    private boolean deferTiming;
    /** In such a walk: whether an element broke EMF's structure or a timing prerequisite. */
    private boolean taskSetBroken;

    void deferTiming() {
        deferTiming = true;
    }

    boolean timingDeferred() {
        return deferTiming;
    }

    void taskSetBroken() {
        taskSetBroken = true;
    }

    boolean isTaskSetBroken() {
        return taskSetBroken;
    }

    void structurallySound(EObject element) {
        structurallySound.put(element, Boolean.TRUE);
    }

    /** Whether the element passed EMF's structural checks earlier in this validation (false when not known). */
    boolean knownStructurallySound(EObject element) {
        return structurallySound.containsKey(element);
    }
}
