/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.internal.Interference;
import org.rsaml.analysis.internal.Interference.Calendar;

/**
 * The calendar the response-time iteration keeps its interference in ({@link Interference}): entries (period T, cost C,
 * jitter J) filed by the largest window their job count ceil((w + J) / T) holds for. What it promises, each against a
 * count from scratch: moving the window on recounts exactly the entries released in between (in any order of their
 * buckets, none early, none missed, ties together, a release at the window itself not yet), the interference equals
 * sum_k ceil((w + J_k) / T_k) C_k at every window (growing, repeated, falling, entries added and costs changed on the
 * way, and continued by a busy period's later jobs), and its work grows with the releases passed, not with the entries
 * times the steps.
 */
class InterferenceCalendarTest {

    private static long jobs(long window, long period, long jitter) {
        long x = window + jitter;
        return x / period + (x % period == 0 ? 0 : 1);
    }

    /** sum_k ceil((w + J_k) / T_k) C_k over the first n entries, from scratch. */
    private static long interference(long window, long[] period, long[] cost, long[] jitter, int n) {
        long sum = 0;
        for (int k = 0; k < n; k++) {
            sum += jobs(window, period[k], jitter[k]) * cost[k];
        }
        return sum;
    }

    /** A calendar of every entry counted at window w and filed, cut for the entries' rate. */
    private static Calendar filed(long w, long[] period, long[] jitter) {
        Calendar c = new Calendar(period.length);
        double rate = 0;
        for (long t : period) {
            rate += 1.0 / t;
        }
        c.cut(Calendar.shiftFor(rate));
        for (int k = 0; k < period.length; k++) {
            c.count(k, w, period, jitter);
            c.file(k);
        }
        return c;
    }

    @Test
    void aCountHoldsUpToItsLimitAndNoFurther() {
        long[] period = { 7, 10, 1_000_003 };
        long[] jitter = { 0, 3, 999 };
        Calendar c = new Calendar(3);
        for (long w : new long[] { 1, 6, 7, 8, 20, 123_456 }) {
            for (int k = 0; k < 3; k++) {
                c.count(k, w, period, jitter);
                long limit = c.limit(k);
                assertEquals(jobs(w, period[k], jitter[k]), c.jobs(k), "entry " + k + " at " + w + ": ceil((w + J) / T) jobs");
                assertTrue(limit >= w, "the limit of entry " + k + " lies at or after the window " + w + ": " + limit);
                assertEquals(c.jobs(k), jobs(limit, period[k], jitter[k]), "entry " + k + "'s count still holds at its limit " + limit);
                assertEquals(c.jobs(k) + 1, jobs(limit + 1, period[k], jitter[k]), "entry " + k + "'s next job comes just after its limit");
            }
        }
    }

    /**
     * Windows moved on by random steps, short and longer than a round of the buckets: after each, every entry's count is
     * its count at the window, the recounted ones are exactly those released in between, and the sum is right.
     */
    @Test
    void movingTheWindowRecountsExactlyTheEntriesReleasedInBetween() {
        Random random = new Random(24);
        for (int set = 0; set < 50; set++) {
            int n = 1 + random.nextInt(200);
            long[] period = new long[n];
            long[] cost = new long[n];
            long[] jitter = new long[n];
            for (int k = 0; k < n; k++) {
                period[k] = 1 + random.nextInt(set % 2 == 0 ? 50 : 100_000);
                cost[k] = 1 + random.nextInt(5);
                jitter[k] = random.nextInt(4) == 0 ? random.nextInt((int) period[k]) : 0;
            }
            long w = 1 + random.nextInt(100);
            Calendar c = filed(w, period, jitter);
            long sum = interference(w, period, cost, jitter, n);
            for (int move = 0; move < 100; move++) {
                long window = w + (random.nextInt(3) == 0 ? random.nextInt(300_000) : random.nextInt(40));
                long released = 0;
                for (int k = 0; k < n; k++) {
                    released += jobs(window, period[k], jitter[k]) != c.jobs(k) ? 1 : 0;
                }
                long before = c.steps();
                sum = c.advance(w, window, period, jitter, cost, sum);
                String where = "set " + set + " (" + n + " entries), from " + w + " to " + window;
                assertEquals(released, c.steps() - before, where + ": the entries recounted are those released in between");
                for (int k = 0; k < n; k++) {
                    assertEquals(jobs(window, period[k], jitter[k]), c.jobs(k), where + ": entry " + k + "'s count");
                    assertTrue(c.limit(k) >= window, where + ": entry " + k + " is filed at or after the window");
                }
                assertEquals(interference(window, period, cost, jitter, n), sum, where + ": the interference");
                w = window;
            }
        }
    }

    /**
     * Entries released together (the same period, or periods whose releases meet) are recounted in the same step; a
     * release exactly at the window is not yet one (ceil counts it from just past it), and is at the next nanosecond.
     */
    @Test
    void tiedReleasesMoveTogetherAndAReleaseAtTheWindowWaits() {
        long[] period = { 10, 10, 5, 20, 7 };
        long[] cost = { 1, 1, 1, 1, 1 };
        long[] jitter = { 0, 0, 0, 0, 0 };
        Calendar c = filed(1, period, jitter);
        long sum = interference(1, period, cost, jitter, 5);
        long before = c.steps();
        sum = c.advance(1, 20, period, jitter, cost, sum);
        assertEquals(interference(20, period, cost, jitter, 5), sum, "at 20 the jobs released at 0 count: 2 + 2 + 4 + 1 + 3");
        // released at or before 20: the period-10 pair (at 10), the 5 (at 5, 10, 15; recounted once), the 7 (at 7, 14); not the 20
        assertEquals(4, c.steps() - before, "the tied releases at 10 recounted in the step that passes them, the 20 not yet");
        assertEquals(1, c.jobs(3), "the period-20 entry's second job is released at 20, which the window 20 does not yet include");
        before = c.steps();
        sum = c.advance(20, 21, period, jitter, cost, sum);
        assertEquals(interference(21, period, cost, jitter, 5), sum, "one nanosecond later every release at 20 counts");
        assertEquals(4, c.steps() - before, "the four entries released at 20 (10, 10, 5, 20), tied, recounted together; not the 7");
        assertEquals(c.limit(0), c.limit(1), "the tied pair is filed at one limit");
        before = c.steps();
        assertEquals(sum, c.advance(21, 21, period, jitter, cost, sum), "the same window again changes nothing");
        assertEquals(before, c.steps(), "and recounts nothing");
    }

    /**
     * The work of a walk of small steps over many periods grows with the releases passed: entries looked at at most the
     * recounted ones plus each entry once per round of buckets, buckets passed at most one per bucket width plus one per
     * step; recounting every entry at each step, as an iteration without the calendar does, would be n times the steps.
     */
    @Test
    void theWorkGrowsWithTheReleasesPassedNotWithTheEntriesTimesTheSteps() {
        for (int n : new int[] { 1_000, 4_000 }) {
            Random random = new Random(n);
            long[] period = new long[n];
            long[] cost = new long[n];
            long[] jitter = new long[n];
            for (int k = 0; k < n; k++) {
                period[k] = 1_000 + random.nextInt(999_000);
                cost[k] = 1;
            }
            Calendar c = filed(1, period, jitter);
            long sum = interference(1, period, cost, jitter, n);
            long w = 1;
            int moves = 0;
            long horizon = 5_000_000;
            while (w < horizon) {
                long window = w + 1 + random.nextInt(2_000);
                sum = c.advance(w, window, period, jitter, cost, sum);
                w = window;
                moves++;
            }
            assertEquals(interference(w, period, cost, jitter, n), sum, n + " entries: the interference at the end of the walk");
            long released = 0;
            for (int k = 0; k < n; k++) {
                released += jobs(w, period[k], jitter[k]) - 1;
            }
            assertTrue(c.steps() <= released, n + " entries: recounted " + c.steps() + " times, at most once per release (" + released + ")");
            long round = (long) c.buckets() << c.shift();
            long rounds = w / round + 1;
            assertTrue(c.looked() <= c.steps() + n * (rounds + 1), n + " entries over " + rounds + " rounds: looked at " + c.looked()
                    + " entries, more than the " + c.steps() + " recounted and each entry once per round");
            assertTrue(c.passed() <= (w >> c.shift()) + moves + 1, n + " entries: passed " + c.passed() + " buckets in " + moves + " steps");
            assertTrue(c.looked() < (long) n * moves / 4, n + " entries, " + moves + " steps: looked at " + c.looked()
                    + ", near the " + (long) n * moves + " of recounting every entry at every step");
        }
    }

    /** The interference at growing, repeated and falling windows, with entries added and costs changed between them. */
    @Test
    void theInterferenceIsTheSumOfTheJobsAtEveryWindowWhateverHappensBetween() {
        Random random = new Random(25);
        for (int set = 0; set < 30; set++) {
            int size = 2 + random.nextInt(300);
            long[] period = new long[size];
            long[] cost = new long[size];
            long[] jitter = new long[size];
            for (int k = 0; k < size; k++) {
                // later entries shorter, so that adding them makes the releases denser and the buckets are cut again
                period[k] = 1 + random.nextInt((int) Math.max(2, 1_000_000L / (k + 1)));
                cost[k] = random.nextInt(4);
                jitter[k] = random.nextInt(5) == 0 ? random.nextInt((int) period[k]) : 0;
            }
            int n = 1 + random.nextInt(size);
            Interference interference = new Interference(period, cost, jitter, n);
            Interference.Later later = new Interference.Later(interference);
            long window = random.nextInt(1_000);
            for (int move = 0; move < 200; move++) {
                switch (random.nextInt(10)) {
                    case 0 -> window = Math.max(0, window - random.nextInt(5_000)); // falls: counted again
                    case 1 -> {
                    } // the same window
                    default -> window += random.nextInt(random.nextBoolean() ? 100 : 3_000_000);
                }
                if (n < size && random.nextInt(8) == 0) {
                    interference.add(n++);
                }
                if (random.nextInt(8) == 0) {
                    int k = random.nextInt(n);
                    long delta = random.nextInt(3);
                    cost[k] += delta;
                    interference.costChanged(k, delta);
                }
                String where = "set " + set + ", move " + move + ", " + n + " entries, window " + window;
                long expected = interference(window, period, cost, jitter, n);
                assertEquals(expected, interference.at(window), where);
                if (random.nextInt(4) == 0) {
                    // a busy period's later jobs, continued from here without changing the first
                    later.start();
                    long w = window;
                    for (int job = 0; job < 5; job++) {
                        w += random.nextInt(random.nextBoolean() ? 50 : 2_000_000);
                        assertEquals(interference(w, period, cost, jitter, n), later.at(w), where + ", a later job's window " + w);
                    }
                    assertEquals(expected, interference.at(window), where + ": the first is as it was after the later jobs");
                }
            }
        }
    }
}
