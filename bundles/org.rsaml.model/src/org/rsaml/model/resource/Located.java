/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

/**
 * A problem that happened at a {@link SourceLocation}: a load error, a generation error. The parts
 * of the location are read through it, so each kind of problem states only where it is.
 */
public interface Located {

    /** Where the problem is: the file as the user named it, and the line and column when known. */
    SourceLocation location();

    /** The file the problem is about, as the user named it. */
    default String file() {
        return location().file();
    }

    /** 1-based line in {@link #file()}, or 0 when unknown. */
    default int line() {
        return location().line();
    }

    /** 1-based column in {@link #file()}, or 0 when unknown. */
    default int column() {
        return location().column();
    }
}
