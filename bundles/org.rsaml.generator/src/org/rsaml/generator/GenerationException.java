/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator;

/**
 * Code could not be generated: the model cannot be read, or the output cannot be written (not a
 * directory, not writable, a file of the user's where a generated file must go). The message names
 * the file concerned. When it is thrown, the output directory is as it was before.
 */
public class GenerationException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String file;
    private final int line;
    private final int column;

    public GenerationException(String file, String message) {
        this(file, 0, 0, message, null);
    }

    public GenerationException(String file, String message, Throwable cause) {
        this(file, 0, 0, message, cause);
    }

    public GenerationException(String file, int line, int column, String message, Throwable cause) {
        super(message, cause);
        this.file = file;
        this.line = line;
        this.column = column;
    }

    /** The file the problem is about (the model, or a path in the output). */
    public String file() {
        return file;
    }

    /** 1-based line in {@link #file()}, or 0. */
    public int line() {
        return line;
    }

    /** 1-based column in {@link #file()}, or 0. */
    public int column() {
        return column;
    }

    /** Compiler style: {@code file[:line[:column]]: error: message}. */
    @Override
    public String toString() {
        return file + (line > 0 ? ":" + line + (column > 0 ? ":" + column : "") : "") + ": error: " + getMessage();
    }
}
