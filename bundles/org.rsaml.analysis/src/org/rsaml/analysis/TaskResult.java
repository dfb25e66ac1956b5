/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.Objects;
import java.util.OptionalLong;
import java.util.function.Supplier;

/**
 * The verdict on one task: its task, its worst-case response time in ns when computed and bounded,
 * whether its deadline holds, one sentence a user can act on (including why when not analysed), and
 * the critical-instant schedule or null when there is none. A value, compared by these five.
 * <p>
 * The sentence may be worded when it is first asked for: a validation reads it only for the tasks it
 * reports, and an architecture of a million elements has hundreds of thousands of tasks.
 */
public final class TaskResult {

    private final Task task;
    private final OptionalLong responseTime;
    private final Verdict verdict;
    private final Supplier<String> words;
    private final Witness witness;
    /** The sentence once worded (a racy single check: a String is immutable, so any thread sees it whole). */
    private String explanation;

    /**
     * @param task         the task
     * @param responseTime its worst-case response time in ns when computed and bounded
     * @param verdict      whether its deadline holds
     * @param explanation  one sentence a user can act on, including why when not analysed
     * @param witness      the critical-instant schedule, or null when there is none
     */
    public TaskResult(Task task, OptionalLong responseTime, Verdict verdict, String explanation, Witness witness) {
        this(task, responseTime, verdict, () -> explanation, witness);
        this.explanation = explanation;
    }

    /** As the other constructor, the sentence worded by {@code explanation} when first asked for (once). */
    public TaskResult(Task task, OptionalLong responseTime, Verdict verdict, Supplier<String> explanation, Witness witness) {
        this.task = task;
        this.responseTime = responseTime;
        this.verdict = verdict;
        this.words = explanation;
        this.witness = witness;
    }

    public Task task() {
        return task;
    }

    public OptionalLong responseTime() {
        return responseTime;
    }

    public Verdict verdict() {
        return verdict;
    }

    /** One sentence a user can act on, including why when not analysed. */
    public String explanation() {
        String e = explanation;
        if (e == null) {
            e = words.get();
            explanation = e;
        }
        return e;
    }

    public Witness witness() {
        return witness;
    }

    /** Deadline minus worst-case response time (negative when missed); empty without a response time. */
    public OptionalLong slack() {
        return responseTime.isPresent() ? OptionalLong.of(task.deadline() - responseTime.getAsLong()) : OptionalLong.empty();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof TaskResult r && Objects.equals(task, r.task) && Objects.equals(responseTime, r.responseTime) && verdict == r.verdict
                && Objects.equals(explanation(), r.explanation()) && Objects.equals(witness, r.witness);
    }

    @Override
    public int hashCode() {
        return Objects.hash(task, responseTime, verdict, explanation(), witness);
    }

    @Override
    public String toString() {
        return "TaskResult[task=" + task + ", responseTime=" + responseTime + ", verdict=" + verdict + ", explanation=" + explanation()
                + ", witness=" + witness + "]";
    }
}
