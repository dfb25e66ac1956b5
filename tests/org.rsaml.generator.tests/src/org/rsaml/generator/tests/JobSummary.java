/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A {@code summary} line of a generated program, the C++ runtime's and the ROS 2 nodes' alike
 * (docs/timing.md, "What the C++ program measures"): one per timed release, and one per reacting
 * module ({@code layer/module (reaction)}). Times in nanoseconds; {@code deadlineNs} 0 when none,
 * {@code firstNs}/{@code lastNs} -1 when no job was released; {@code stallNs} the worst time a job was
 * ready, holding its module's lock, and not running (its wall time minus its CPU time). Where the
 * jobs ran, on CLOCK_MONOTONIC (the platform monitor's clock): {@code worstJob} the worst job's release
 * and completion (null without a job), {@code overBound} how many jobs exceeded the plain bound the
 * program was given, and {@code overBoundJobs} those of them the program listed ({@code over-bound}
 * lines; the worst always among them), each {release, completion}, a deadline thread's {release, completion, start,
 * CPU time, context switches}.
 */
record JobSummary(String label, long jobs, long firstNs, long lastNs, long misses, long overruns, long worstNs, String bound,
        long deadlineNs, long executionNs, long modeledNs, long latencyNs, long stallNs, long[] worstJob, long overBound,
        List<long[]> overBoundJobs, String sched) {

    private static final Pattern LINE = Pattern.compile("summary (\\S+(?: \\(reaction\\))?) jobs (\\d+) released (none|([0-9.]+)\\.\\.([0-9.]+) ms)"
            + " misses (\\d+) overruns (\\d+) worst-response ([0-9.]+) ms bound (none|[0-9.]+ ms) deadline (none|[0-9.]+ ms)"
            + " worst-execution ([0-9.]+) ms modeled ([0-9.]+) ms worst-start-latency ([0-9.]+) ms worst-stall ([0-9.]+) ms"
            + " worst-job (none|(\\d+)\\.\\.(\\d+) ns) over-bound (\\d+) listed (\\d+) sched (.*)");

    /**
     * A job over the plain bound: "over-bound <label> job <release>..<completion> ns", on CLOCK_MONOTONIC; a deadline
     * thread's (the C++ runtime's EDF releases) also "started <instant> ns cpu <CPU time> ns switches <context switches>".
     */
    private static final Pattern OVER = Pattern.compile("over-bound (\\S+(?: \\(reaction\\))?) job (\\d+)\\.\\.(\\d+) ns"
            + "(?: started (\\d+) ns cpu (\\d+) ns switches (\\d+))?");

    /** The jobs over the plain bound the program did not list (beyond its room for them), which only the worst response speaks for. */
    long unlisted() {
        return overBound - overBoundJobs.size();
    }

    /** Scheduled as the analysis assumes: real-time at its rank (0 for reactions), or SCHED_DEADLINE for EDF. */
    boolean asAnalysed() {
        return (sched.startsWith("SCHED_FIFO") || sched.startsWith("SCHED_RR") || sched.startsWith("SCHED_DEADLINE"))
                && !sched.contains("instead of EDF");
    }

    /** The analysis's bound as the program prints it, in nanoseconds; -1 for none. */
    long boundNs() {
        return bound.equals("none") ? -1 : ns(bound.replace(" ms", ""));
    }

    private static final Pattern TRACED = Pattern.compile("\\[\\s*[0-9.]+ ms\\] ((?:summary|over-bound) .*)$");

    /**
     * Every summary line of a program's output, by label: its trace lines ("[  12.345 ms] summary ..."),
     * also behind a prefix (ros2 launch puts the process's name before each line).
     */
    static Map<String, JobSummary> of(String output) {
        Map<String, JobSummary> all = new LinkedHashMap<>();
        Map<String, List<long[]>> over = new HashMap<>();
        for (String raw : output.split("\n")) {
            Matcher t = TRACED.matcher(raw);
            String line = t.find() ? t.group(1) : "";
            if (line.startsWith("over-bound ")) {
                Matcher m = OVER.matcher(line);
                assertTrue(m.matches(), "an over-bound line the test cannot read: " + line);
                over.computeIfAbsent(m.group(1), k -> new ArrayList<>()).add(m.group(4) == null
                        ? new long[] {Long.parseLong(m.group(2)), Long.parseLong(m.group(3))}
                        : new long[] {Long.parseLong(m.group(2)), Long.parseLong(m.group(3)), Long.parseLong(m.group(4)), Long.parseLong(m.group(5)),
                                Long.parseLong(m.group(6))});
            }
        }
        for (String raw : output.split("\n")) {
            Matcher t = TRACED.matcher(raw);
            String line = t.find() ? t.group(1) : "";
            if (line.startsWith("summary ") && !line.contains(" messages ")) {
                Matcher m = LINE.matcher(line);
                assertTrue(m.matches(), "a summary line the test cannot read: " + line);
                boolean released = m.group(4) != null;
                List<long[]> listed = List.copyOf(over.getOrDefault(m.group(1), List.of()));
                assertEquals(Long.parseLong(m.group(19)), listed.size(), "as many over-bound lines of " + m.group(1) + " as its summary lists: " + line);
                // one summary per label: a second (a node started twice) would add its miss lines to the other's summary
                assertFalse(all.containsKey(m.group(1)), "two summaries of " + m.group(1) + " (a node started twice?): " + line);
                all.put(m.group(1), new JobSummary(m.group(1), Long.parseLong(m.group(2)), released ? ns(m.group(4)) : -1,
                        released ? ns(m.group(5)) : -1, Long.parseLong(m.group(6)), Long.parseLong(m.group(7)), ns(m.group(8)), m.group(9),
                        m.group(10).equals("none") ? 0 : ns(m.group(10).replace(" ms", "")), ns(m.group(11)), ns(m.group(12)),
                        ns(m.group(13)), ns(m.group(14)),
                        m.group(16) == null ? null : new long[] {Long.parseLong(m.group(16)), Long.parseLong(m.group(17))},
                        Long.parseLong(m.group(18)), listed, m.group(20)));
            }
        }
        return all;
    }

    private static long ns(String ms) {
        return Math.round(Double.parseDouble(ms) * 1e6);
    }
}
