/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import org.eclipse.emf.ecore.xmi.XMIException;

/**
 * One reason a {@code .rsaml} file could not be read, as {@link RsamlResource#getErrors()} holds
 * it: a sentence saying what is wrong and what to do, the line and column (0 when unknown), and
 * EMF's or the parser's exception as cause.
 */
public final class LoadProblem extends XMIException {
    private static final long serialVersionUID = 1L;

    private final String sentence;

    LoadProblem(String sentence, Exception cause, String location, int line, int column) {
        super(sentence, cause, location, line, column);
        this.sentence = sentence;
    }

    public LoadProblem(String sentence, String location, int line, int column) {
        this(sentence, null, location, line, column);
    }

    /** The sentence alone: the location is in {@link #getLine()} and {@link #getColumn()}, not repeated here. */
    @Override
    public String getMessage() {
        return sentence;
    }
}
