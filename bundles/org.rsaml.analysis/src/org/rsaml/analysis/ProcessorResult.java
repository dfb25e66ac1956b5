/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.List;

/**
 * Schedulability of the tasks of one processor.
 *
 * @param processor   the processor's name
 * @param policy      its scheduling policy
 * @param tasks       the verdict per task, in the order given
 * @param utilisation the sum of cost / period (decisions against 1 are made exactly)
 * @param bounds      utilisation bounds, each marked sufficient or necessary
 * @param verdict     MEETS when every deadline is proven to hold
 * @param explanation what decided the verdict
 * @param demand      for a failed processor-demand test, the overloaded interval; else null
 */
public record ProcessorResult(String processor, SchedulingPolicy policy, List<TaskResult> tasks, double utilisation,
        List<BoundCheck> bounds, Verdict verdict, String explanation, DemandWitness demand) {

    public ProcessorResult {
        tasks = List.copyOf(tasks);
        bounds = List.copyOf(bounds);
    }

    /** The utilisation with four decimals, e.g. "0.9583". */
    public String utilisationText() {
        return String.format(java.util.Locale.ROOT, "%.4f", utilisation);
    }
}
