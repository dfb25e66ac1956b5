/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.util.List;

import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.generator.spi.OutputContext;

/** Text every target's templates share, written once: the banner, doc comments, the user-file note, the README's link. */
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

    /** The output's README.md: the architect's, created once and never overwritten. */
    public static final String README = "README.md";

    /**
     * The file beside README.md that generating rewrites every time with what it made of the model,
     * which the README links, so that a README written long ago states no stale facts.
     */
    public static final String GENERATED_README = "GENERATED.md";

    /**
     * A warning when the architect's README.md (in {@code output}) does not link GENERATED.md: what it
     * says of {@code facts} (what GENERATED.md tells) is as of when it was written. None when it links it
     * or there is none yet.
     */
    public static List<String> readmeLink(OutputContext output, String facts) {
        return output.userFile(README).filter(text -> !text.contains(GENERATED_README))
                .map(text -> List.of(README + " (yours, kept as it is) does not link " + GENERATED_README + ", which generating rewrites every"
                        + " time with what it made of the model (" + facts + "): what your README says of them is as of when it was written; link "
                        + GENERATED_README + " from it (or delete " + README + " to have it created again)"))
                .orElse(List.of());
    }
}
