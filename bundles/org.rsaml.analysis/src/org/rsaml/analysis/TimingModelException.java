/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import org.eclipse.emf.ecore.EObject;

/** The deployment or a requirement of the model contradicts itself; the message says how to fix it. */
public class TimingModelException extends Exception {

    private static final long serialVersionUID = 1L;

    private final transient EObject element;

    public TimingModelException(EObject element, String message) {
        super(message);
        this.element = element;
    }

    /** The model element concerned. */
    public EObject element() {
        return element;
    }
}
