/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator;

import org.rsaml.model.resource.Located;
import org.rsaml.model.resource.SourceLocation;

/**
 * Code could not be generated: the model cannot be read, or the output cannot be written (not a
 * directory, not writable, a file of the user's where a generated file must go). The message names
 * the file concerned. When it is thrown, the output directory is as it was before.
 */
public class GenerationException extends Exception implements Located {
    private static final long serialVersionUID = 1L;

    private final SourceLocation location;

    public GenerationException(String file, String message) {
        this(file, 0, 0, message, null);
    }

    public GenerationException(String file, String message, Throwable cause) {
        this(file, 0, 0, message, cause);
    }

    public GenerationException(String file, int line, int column, String message, Throwable cause) {
        super(message, cause);
        this.location = new SourceLocation(file, line, column);
    }

    /** Where the problem is: the model or a path in the output, and the line and column when known. */
    @Override
    public SourceLocation location() {
        return location;
    }

    /** Compiler style: {@code file[:line[:column]]: error: message}. */
    @Override
    public String toString() {
        return location.error(getMessage());
    }
}
