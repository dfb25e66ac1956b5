/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import org.rsaml.model.resource.SourceLocation;

/**
 * A model file that cannot be read as an RsaML model: missing, empty, binary, not XML, not RsaML,
 * or with references that do not resolve. Carries the location when there is one.
 */
public class ModelLoadException extends Exception {
    private static final long serialVersionUID = 1L;

    private final SourceLocation location;

    public ModelLoadException(String file, int line, int column, String message, Throwable cause) {
        super(message, cause);
        this.location = new SourceLocation(file, line, column);
    }

    public ModelLoadException(String file, String message) {
        this(file, 0, 0, message, null);
    }

    /** Where the problem is: the file as the user named it, and the line and column when known. */
    public SourceLocation location() {
        return location;
    }

    public String file() {
        return location.file();
    }

    public int line() {
        return location.line();
    }

    public int column() {
        return location.column();
    }

    /** Compiler style: {@code file:line:column: error: message}, without a location it does not have. */
    @Override
    public String toString() {
        return location.error(getMessage());
    }
}
