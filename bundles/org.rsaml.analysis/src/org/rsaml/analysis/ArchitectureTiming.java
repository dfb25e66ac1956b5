/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.List;

/**
 * The timing of an architecture as the generated runtime runs it: schedulability per processor,
 * the work no analysis can bound, and the end-to-end latency requirements.
 */
public record ArchitectureTiming(String architecture, List<ProcessorTiming> processors, List<Exclusion> excluded,
        List<LatencyResult> latencies) {

    public ArchitectureTiming {
        processors = List.copyOf(processors);
        excluded = List.copyOf(excluded);
        latencies = List.copyOf(latencies);
    }

    /** MISSES when a deadline or a requirement can be missed; NOT_ANALYSED when something could not be decided. */
    public Verdict verdict() {
        Verdict v = Verdict.MEETS;
        for (ProcessorTiming p : processors) {
            v = v.and(p.result().verdict());
        }
        for (LatencyResult l : latencies) {
            v = v.and(l.verdict());
        }
        return v;
    }
}
