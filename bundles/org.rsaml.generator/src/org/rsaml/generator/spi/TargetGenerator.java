/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.spi;

import org.rsaml.generator.GenerationException;
import org.rsaml.analysis.plan.ExecutionPlan;

/**
 * A code generation target: renders an {@link ExecutionPlan} as the files of a project. Register
 * one with {@link org.rsaml.generator.Target#register(TargetGenerator)}; the shared machinery
 * (validation, planning, the file transaction) needs no change for a new target.
 */
public interface TargetGenerator {

    /** The name users type ({@code cpp}): lower-case letters, digits and dashes. */
    String id();

    /** One line saying what the target produces. */
    String description();

    /**
     * The files of the project and what the architect should know about them.
     *
     * @param output what earlier runs left in the output: kept settings, the architect's files
     * @throws GenerationException the plan cannot be expressed in this target
     */
    GeneratedProject generate(ExecutionPlan plan, OutputContext output) throws GenerationException;
}
