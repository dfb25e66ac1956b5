/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import org.rsaml.analysis.plan.ExecutionPlan;

/** Text every target's templates share, written once: the banner, doc comments, the user-file note. */
public final class Templates {

    private Templates() {
    }

    /** First line (as a comment) of every regenerated file; it carries {@link OutputWriter#MARKER}. */
    public static String banner(ExecutionPlan plan) {
        return OutputWriter.MARKER + " from architecture '" + doc(plan.name()) + "'. Do not edit: regenerated on every run.";
    }

    /** Model text (names, descriptions) safe inside a one-line comment. */
    public static String doc(String text) {
        return Names.comment(text);
    }

    /** ": description" when the element has one, else nothing. */
    public static String described(String description) {
        String d = doc(description);
        return d.isEmpty() ? "" : ": " + d;
    }

    /** What a file of the architect's says about itself. */
    public static final String USER_OWNED = "Yours: created once by RsaML, never overwritten.";
}
