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
 *                    or running (in order of priority; in a summary, the most delaying first)
 * @param blockedBy   the lower-priority task whose job runs first without preemption, or null
 * @param truncated   true when the schedule was too long to keep whole; it then ends early
 * @param unlisted    how many further tasks can delay it beyond those in {@code preemptions} (a
 *                    summary lists only those that delay it most)
 */
public record Witness(String task, long job, long release, long completion, List<Segment> schedule,
        Map<String, Long> preemptions, String blockedBy, boolean truncated, int unlisted) {

    public Witness {
        schedule = List.copyOf(schedule);
        preemptions = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(preemptions));
    }

    /** A witness with its schedule, every task that delays it listed. */
    public Witness(String task, long job, long release, long completion, List<Segment> schedule, Map<String, Long> preemptions,
            String blockedBy, boolean truncated) {
        this(task, job, release, completion, schedule, preemptions, blockedBy, truncated, 0);
    }

    /**
     * Whether this is a summary without a schedule: per processor only the highest-priority task that
     * misses its deadline gets its critical-instant schedule; the others get the jobs of each task that
     * can delay them (released from the critical instant until they complete: at most that many).
     */
    public boolean summary() {
        return schedule.isEmpty();
    }
}
