/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator;

import java.util.List;

import org.rsaml.validation.Finding;
import org.rsaml.validation.Severity;

/**
 * The model has error findings, so no code was generated (nothing in the output directory was
 * touched). Fix the findings, or generate with {@code force}.
 */
public class GenerationRefusedException extends GenerationException {
    private static final long serialVersionUID = 1L;

    private final transient List<Finding> findings;

    public GenerationRefusedException(String file, List<Finding> findings) {
        super(file, message(findings));
        this.findings = List.copyOf(findings);
    }

    /** Every finding of the model, errors first as they appear in the file. */
    public List<Finding> findings() {
        return findings;
    }

    /** The findings of severity error, the reason for the refusal. */
    public List<Finding> errors() {
        return findings.stream().filter(f -> f.severity() == Severity.ERROR).toList();
    }

    private static String message(List<Finding> findings) {
        long errors = findings.stream().filter(f -> f.severity() == Severity.ERROR).count();
        return "no code generated: the model has " + errors + (errors == 1 ? " error" : " errors")
                + " (fix " + (errors == 1 ? "it" : "them") + ", or force generation)";
    }
}
