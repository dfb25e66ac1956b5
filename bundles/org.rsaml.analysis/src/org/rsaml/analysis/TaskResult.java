/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.OptionalLong;

/**
 * The verdict on one task.
 *
 * @param task         the task
 * @param responseTime its worst-case response time in ns when computed and bounded
 * @param verdict      whether its deadline holds
 * @param explanation  one sentence a user can act on, including why when not analysed
 * @param witness      the critical-instant schedule, or null when there is none
 */
public record TaskResult(Task task, OptionalLong responseTime, Verdict verdict, String explanation, Witness witness) {

    /** Deadline minus worst-case response time (negative when missed); empty without a response time. */
    public OptionalLong slack() {
        return responseTime.isPresent() ? OptionalLong.of(task.deadline() - responseTime.getAsLong()) : OptionalLong.empty();
    }
}
