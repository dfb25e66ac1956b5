/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.Map;

/**
 * Evidence that a set of jobs cannot all meet their deadlines under any scheduler: with every task
 * released at 0, the jobs that are both released and due within {@code interval} need {@code demand}
 * of processor time, more than the interval holds.
 *
 * @param interval the length of the interval from 0
 * @param demand   the processor time those jobs need
 * @param jobs     per task, how many of its jobs are due within the interval
 */
public record DemandWitness(long interval, long demand, Map<String, Long> jobs) {

    public DemandWitness {
        jobs = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(jobs));
    }
}
