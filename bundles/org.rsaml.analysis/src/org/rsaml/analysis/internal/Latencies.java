/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TaskSource;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.support.RsamlTimes;

/**
 * End-to-end latency along every path of connections, under the runtime's communication: a module
 * with timed releases samples the latest value at its next release (it waits up to one period, then
 * takes its worst-case response time); a sporadic reacting module starts on the arrival (it may skip
 * an arrival within its minimum interval, so it waits up to that interval); an aperiodic one has no
 * bound. Delivery between modules is a memory write in one process and counts as 0. The maximum data
 * age adds the period of the last stage, whose output stays in place until replaced. Each module's stage
 * is taken here from the response times of its tasks; each requirement is then checked on its own
 * ({@link LatencyCheck}), its paths followed by {@link PathSearch}.
 */
public final class Latencies {

    private Latencies() {
    }

    /** A stage: how long data can take through a module, or unbounded (hop null) and why. */
    record Stage(Hop hop, long periodNs, String unbounded) {
    }

    /** @param listPaths whether to list each requirement's paths with their bounds (the reports), or only the worst (verdicts) */
    public static List<LatencyResult> analyse(ExecutionPlan plan, List<LatencyRequirement> requirements, List<ProcessorTiming> processors,
            boolean listPaths) {
        if (requirements.isEmpty()) {
            return List.of();
        }
        Map<String, List<TaskResult>> byModule = new HashMap<>();
        Map<String, List<TaskSource>> sourcesByModule = new HashMap<>();
        for (ProcessorTiming p : processors) {
            for (int i = 0; i < p.sources().size(); i++) {
                TaskSource s = p.sources().get(i);
                byModule.computeIfAbsent(s.task().group(), k -> new ArrayList<>()).add(p.result().tasks().get(i));
                sourcesByModule.computeIfAbsent(s.task().group(), k -> new ArrayList<>()).add(s);
            }
        }
        Map<PlannedModule, Stage> stages = new HashMap<>();
        for (PlannedModule m : plan.modules()) {
            stages.put(m, stage(m, byModule.getOrDefault(m.qualifiedName(), List.of()),
                    sourcesByModule.getOrDefault(m.qualifiedName(), List.of())));
        }
        List<LatencyResult> results = new ArrayList<>();
        for (LatencyRequirement r : requirements) {
            results.add(new LatencyCheck(plan, stages, r, listPaths).run());
        }
        return results;
    }

    private static Stage stage(PlannedModule m, List<TaskResult> results, List<TaskSource> sources) {
        Stage best = null;
        for (int i = 0; i < results.size(); i++) {
            TaskResult t = results.get(i);
            boolean reaction = "reaction".equals(sources.get(i).kind());
            if (t.responseTime().isEmpty()) {
                return new Stage(null, 0, m.qualifiedName() + " has no bounded response time (" + t.explanation() + ")");
            }
            long r = t.responseTime().getAsLong();
            long wait = t.task().period();
            String how = reaction
                    ? "reacts to the arrival (may skip arrivals within its minimum interval of " + RsamlTimes.text(wait) + ")"
                    : "samples the latest value at its next release of " + t.task().name() + " (every " + RsamlTimes.text(wait) + ")";
            Stage s = new Stage(new Hop(m.qualifiedName(), m.module(), how, wait, r), t.task().period(), null);
            if (best == null || s.hop().totalNs() > best.hop().totalNs()) {
                best = s;
            }
        }
        if (m.reactive() && m.minIntervalNs() == 0) {
            return new Stage(null, 0, m.qualifiedName() + " reacts aperiodically: its response time has no bound");
        }
        if (best == null) {
            return new Stage(null, 0, m.qualifiedName() + " is never activated");
        }
        return best;
    }
}
