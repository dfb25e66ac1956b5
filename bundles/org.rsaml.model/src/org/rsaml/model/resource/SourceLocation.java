/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

/**
 * A place in a file, as compilers print it: the file as the user named it, and a 1-based line and
 * column, each 0 when unknown. Load errors, generation errors and findings all point with it.
 */
public record SourceLocation(String file, int line, int column) {

    public SourceLocation {
        line = Math.max(0, line);
        column = line == 0 ? 0 : Math.max(0, column);
    }

    /** The same place in a file named otherwise (the display name instead of a URI, say). */
    public SourceLocation inFile(String otherFile) {
        return new SourceLocation(otherFile, line, column);
    }

    /** {@code file:line:column}, without the parts that are not known. */
    @Override
    public String toString() {
        return file + (line > 0 ? ":" + line + (column > 0 ? ":" + column : "") : "");
    }

    /** Compiler style: {@code file:line:column: error: message}. */
    public String error(String message) {
        return this + ": error: " + message;
    }
}
