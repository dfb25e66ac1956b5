/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.function.Supplier;

/**
 * What a walk down the priority levels ({@link PriorityLevels}) did, counted, for the benchmark and
 * the tests that must know which path decided: the quantities the cost of the analysis is stated in
 * (docs/timing.md). Counted only while {@link #during} runs on the analysing thread; otherwise the
 * walk adds its counts to nothing.
 */
public final class AnalysisCounts {

    private static final ThreadLocal<AnalysisCounts> CURRENT = new ThreadLocal<>();

    /** Tasks analysed by the walk (each task's own response time, skipped tasks not counted). */
    public long tasks;
    /** Tasks decided without an iteration: their level uses more than the processor. */
    public long overloaded;
    /** Jobs of the tasks' own busy periods whose windows were found (one per task at least). */
    public long jobs;
    /** Steps of the fixed-point iterations (an interference evaluated at a window). */
    public long iterations;
    /** Entries of the first jobs' interference recounted: their job count changed (or was counted afresh). */
    public long firstJobSteps;
    /** Entries of the later jobs' interference recounted ({@code Interference.Later}). */
    public long laterJobSteps;
    /** Buckets of the interference's calendars passed, and entries looked at in them (recounted or filed back). */
    public long bucketsPassed;
    public long entriesLookedAt;
    /** The largest window (ns) a task's busy period reached: its length, for the last job. */
    public long longestBusyPeriod;
    /** Tasks tied at a shared level whose every window was read from the level's one walk ({@code LevelExcess}). */
    public long tiedDecided;
    /** Tasks tied at a shared level that iterated themselves (the walk had no answer for one of their windows). */
    public long tiedIterated;
    /** Shared levels walked, and the releases their busy periods held. */
    public long levelsWalked;
    public long levelReleases;
    /** Summary witnesses of misses, and the nodes their best-first searches opened. */
    public long summaries;
    public long nodesOpened;

    /** Runs {@code analysis} on this thread with the walks' counts added to this object. */
    public <T> T during(Supplier<T> analysis) {
        AnalysisCounts before = CURRENT.get();
        CURRENT.set(this);
        try {
            return analysis.get();
        } finally {
            CURRENT.set(before);
        }
    }

    /** The counts being taken on this thread, or null. */
    static AnalysisCounts current() {
        return CURRENT.get();
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT,
                "tasks %,d (overloaded %,d), jobs %,d, iterations %,d, entries recounted %,d first + %,d later (buckets passed %,d, entries looked at %,d), longest busy period %,d ns,"
                        + " tied %,d read + %,d iterated (%,d levels, %,d releases), summaries %,d (%,d nodes opened)",
                tasks, overloaded, jobs, iterations, firstJobSteps, laterJobSteps, bucketsPassed, entriesLookedAt, longestBusyPeriod, tiedDecided, tiedIterated,
                levelsWalked, levelReleases, summaries, nodesOpened);
    }
}
