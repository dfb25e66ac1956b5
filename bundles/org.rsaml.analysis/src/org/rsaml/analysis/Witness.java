/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.List;
import java.util.Map;

/**
 * Evidence for a task's worst-case response time: the schedule from the critical instant (every task
 * that can delay it released together at 0, after the blocking job if any) up to the completion of
 * its worst job.
 *
 * @param task        the task analysed
 * @param job         which of its jobs in the busy period has the worst response time (0 is the first)
 * @param release     when that job is released
 * @param completion  when it completes in this schedule, or -1 when the schedule was cut short
 * @param schedule    what runs when, from 0 to {@code completion}
 * @param preemptions per interfering task, how many of its jobs ran while the analysed job was waiting
 *                    or running (in order of priority)
 * @param blockedBy   the lower-priority task whose job runs first without preemption, or null
 * @param truncated   true when the schedule was too long to keep whole; it then ends early
 */
public record Witness(String task, long job, long release, long completion, List<Segment> schedule,
        Map<String, Long> preemptions, String blockedBy, boolean truncated) {

    public Witness {
        schedule = List.copyOf(schedule);
        preemptions = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(preemptions));
    }
}
