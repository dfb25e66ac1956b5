/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.ArrayList;
import java.util.List;

import org.rsaml.model.resource.Located;
import org.rsaml.model.resource.SourceLocation;

/**
 * A model file that cannot be read as an RsaML model: missing, empty, binary, not XML, not RsaML,
 * or with references that do not resolve. Carries the location when there is one, and every
 * problem the file has, not only the first: a user fixes them all in one go.
 */
public class ModelLoadException extends Exception implements Located {
    private static final long serialVersionUID = 1L;

    /** One reason the file cannot be read, where it is. */
    public record Problem(SourceLocation location, String message) {

        /** Compiler style: {@code file:line:column: error: message}. */
        @Override
        public String toString() {
            return location.error(message);
        }
    }

    private final SourceLocation location;

    private final List<Problem> problems;

    public ModelLoadException(String file, int line, int column, String message, Throwable cause) {
        this(file, line, column, message, List.of(), cause);
    }

    /**
     * @param more the problems after the first, in the order of the file
     */
    public ModelLoadException(String file, int line, int column, String message, List<Problem> more, Throwable cause) {
        super(message, cause);
        this.location = new SourceLocation(file, line, column);
        List<Problem> all = new ArrayList<>(1 + more.size());
        all.add(new Problem(location, message));
        all.addAll(more);
        this.problems = List.copyOf(all);
    }

    public ModelLoadException(String file, String message) {
        this(file, 0, 0, message, null);
    }

    /** Where the first problem is: the file as the user named it, and the line and column when known. */
    @Override
    public SourceLocation location() {
        return location;
    }

    /** Every problem of the file, the first ({@link #getMessage()}, {@link #location()}) included. */
    public List<Problem> problems() {
        return problems;
    }

    /** Compiler style, a line per problem: {@code file:line:column: error: message}, without a location it does not have. */
    @Override
    public String toString() {
        return String.join("\n", problems.stream().map(Problem::toString).toList());
    }
}
