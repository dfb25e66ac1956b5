/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.TreeSet;

import org.rsaml.analysis.Segment;
import org.rsaml.analysis.Task;
import org.rsaml.analysis.Witness;

/**
 * Builds a witness: the schedule from the critical instant, every task that can delay the analysed
 * one released together at 0 (after the blocking job, when there is one), up to the completion of
 * the analysed task's worst job. Ties between equal priorities go against the analysed task, as the
 * analysis assumes: it runs after every equal job ready, or, first in, first out, after those
 * released before or with it.
 */
public final class CriticalInstant {

    /** Longer schedules are cut (the witness then says so). */
    static final int MAX_SEGMENTS = 5_000;
    private static final int MAX_EVENTS = 1_000_000;

    private CriticalInstant() {
    }

    private static final class Job {
        final int task;
        final long index;
        final long release;
        long remaining;

        Job(int task, long index, long release, long remaining) {
            this.task = task;
            this.index = index;
            this.release = release;
            this.remaining = remaining;
        }
    }

    /**
     * @param analysed    the task whose job {@code job} is followed
     * @param interfering tasks that can delay it (higher or equal priority)
     * @param blocker     a lower-priority task whose job holds the processor at 0, or null
     * @param preemptive  whether a released higher-priority job takes the processor at once
     */
    public static Witness schedule(Task analysed, List<Task> interfering, Task blocker, long job, boolean preemptive) {
        return schedule(analysed, interfering, blocker, job, preemptive, false);
    }

    /**
     * @param firstInFirstOut equal priorities run in the order of their releases, the analysed task
     *                        last among jobs released together (else after every equal job ready)
     */
    public static Witness schedule(Task analysed, List<Task> interfering, Task blocker, long job, boolean preemptive,
            boolean firstInFirstOut) {
        List<Task> all = new ArrayList<>(interfering);
        all.add(analysed);
        int self = all.size() - 1;
        Comparator<Job> byPriority = Comparator.<Job>comparingInt(j -> -all.get(j.task).priority());
        Comparator<Job> order = firstInFirstOut
                ? byPriority.thenComparingLong(j -> j.release).thenComparingInt(j -> j.task == self ? 1 : 0)
                        .thenComparingInt(j -> j.task)
                : byPriority.thenComparingInt(j -> j.task == self ? 1 : 0).thenComparingLong(j -> j.release)
                        .thenComparingInt(j -> j.task);
        PriorityQueue<Job> ready = new PriorityQueue<>(order);
        long[] nextRelease = new long[all.size()];
        long[] nextIndex = new long[all.size()];
        // the tasks by their next release: an event looks only at those released by then, not at every task
        PriorityQueue<Integer> releasing = new PriorityQueue<>(Comparator.comparingLong((Integer t) -> nextRelease[t]));
        for (int t = 0; t < all.size(); t++) {
            releasing.add(t);
        }
        List<Segment> segments = new ArrayList<>();
        long targetRelease = Arith.mul(analysed.period(), job);
        long time = 0;
        if (blocker != null && blocker.cost() > 0) {
            segments.add(new Segment(blocker.name(), 0, 0, blocker.cost()));
            time = blocker.cost();
        }
        // releases up to the current time
        long completion = -1;
        boolean truncated = false;
        int events = 0;
        while (completion < 0) {
            if (++events > MAX_EVENTS || segments.size() >= MAX_SEGMENTS) {
                truncated = true;
                break;
            }
            // the ready queue orders jobs totally, so the order they join it in does not matter
            while (nextRelease[releasing.peek()] <= time) {
                int t = releasing.poll();
                while (nextRelease[t] <= time) {
                    ready.add(new Job(t, nextIndex[t], nextRelease[t], all.get(t).cost()));
                    nextIndex[t]++;
                    nextRelease[t] = Arith.add(nextRelease[t], all.get(t).period());
                }
                releasing.add(t);
            }
            Job running = ready.poll();
            long upcoming = nextRelease[releasing.peek()];
            if (running == null) {
                time = upcoming;
                continue;
            }
            long end = preemptive ? Math.min(Arith.add(time, running.remaining), upcoming) : Arith.add(time, running.remaining);
            if (end > time) {
                Task t = all.get(running.task);
                Segment last = segments.isEmpty() ? null : segments.get(segments.size() - 1);
                if (last != null && last.end() == time && last.task().equals(t.name()) && last.job() == running.index) {
                    segments.set(segments.size() - 1, new Segment(t.name(), running.index, last.start(), end));
                } else {
                    segments.add(new Segment(t.name(), running.index, time, end));
                }
            }
            running.remaining -= end - time;
            time = end;
            if (running.remaining > 0) {
                ready.add(running);
            } else if (running.task == self && running.index == job) {
                completion = time;
            }
        }
        long until = completion < 0 ? time : completion;
        Map<String, TreeSet<Long>> ran = new java.util.HashMap<>();
        for (Segment s : segments) {
            if (s.end() > targetRelease && s.start() < until && !(s.task().equals(analysed.name()) && s.job() == job)) {
                ran.computeIfAbsent(s.task(), k -> new TreeSet<>()).add(s.job());
            }
        }
        Map<String, Long> preemptions = new LinkedHashMap<>();
        for (Task t : all) {
            TreeSet<Long> jobs = ran.get(t.name());
            if (jobs != null) {
                preemptions.put(t.name(), (long) jobs.size());
            }
        }
        return new Witness(analysed.name(), job, targetRelease, completion, segments, preemptions,
                blocker == null ? null : blocker.name(), truncated);
    }
}
