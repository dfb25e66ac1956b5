/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import org.eclipse.emf.ecore.EObject;

/**
 * A model element has a time that executing code cannot represent (not finite, negative, a period
 * below 1 ns, or beyond {@link ExecutionPlan#MAX_TIME_NS}). The message names the element, the
 * attribute and its value, and what to give instead.
 */
public class UnplannableException extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient EObject element;

    public UnplannableException(EObject element, String message) {
        super(message);
        this.element = element;
    }

    /** The model element concerned. */
    public EObject element() {
        return element;
    }
}
