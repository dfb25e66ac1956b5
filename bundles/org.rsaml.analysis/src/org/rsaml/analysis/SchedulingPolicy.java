/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

/** How a processor picks the next job, as far as the analysis is concerned. */
public enum SchedulingPolicy {
    /** Preemptive fixed priorities (rate or deadline monotonic, or any given order). */
    FIXED_PRIORITY("preemptive fixed priority"),
    /** Fixed priorities, each job running to completion once started (first-in first-out run to completion). */
    FIXED_PRIORITY_NON_PREEMPTIVE("non-preemptive fixed priority"),
    /** Preemptive earliest deadline first. */
    EDF("earliest deadline first"),
    /** Least laxity first. */
    LLF("least laxity first"),
    /** Round robin time slicing. */
    ROUND_ROBIN("round robin"),
    /** Shortest job first. */
    SJF("shortest job first"),
    /** A policy the analysis knows nothing of. */
    OTHER("unspecified policy");

    private final String label;

    SchedulingPolicy(String label) {
        this.label = label;
    }

    /** The policy's name in prose. */
    public String label() {
        return label;
    }
}
