/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

/**
 * A model file that cannot be read as an RsaML model: missing, empty, binary, not XML, not RsaML,
 * or with references that do not resolve. Carries the location when there is one.
 */
public class ModelLoadException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String file;
    private final int line;
    private final int column;

    public ModelLoadException(String file, int line, int column, String message, Throwable cause) {
        super(message, cause);
        this.file = file;
        this.line = line;
        this.column = column;
    }

    public ModelLoadException(String file, String message) {
        this(file, 0, 0, message, null);
    }

    public String file() {
        return file;
    }

    public int line() {
        return line;
    }

    public int column() {
        return column;
    }

    /** Compiler style: {@code file:line:column: error: message}, without a location it does not have. */
    @Override
    public String toString() {
        return file + (line > 0 ? ":" + line + (column > 0 ? ":" + column : "") : "") + ": error: " + getMessage();
    }
}
