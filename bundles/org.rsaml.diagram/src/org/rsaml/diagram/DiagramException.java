/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

/** A diagram could not be drawn or written; the message names the file and says what to do. */
public class DiagramException extends Exception {

    private static final long serialVersionUID = 1L;

    public DiagramException(String message, Throwable cause) {
        super(message, cause);
    }

    public DiagramException(String message) {
        super(message);
    }
}
