/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A {@code summary} line of a generated program, the C++ runtime's and the ROS 2 nodes' alike
 * (docs/timing.md, "What the C++ program measures"): one per timed release, and one per reacting
 * module ({@code layer/module (reaction)}). Times in nanoseconds; {@code deadlineNs} 0 when none,
 * {@code firstNs}/{@code lastNs} -1 when no job was released; {@code stallNs} the worst time a job was
 * ready, holding its module's lock, and not running (its wall time minus its CPU time).
 */
record JobSummary(String label, long jobs, long firstNs, long lastNs, long misses, long overruns, long worstNs, String bound,
        long deadlineNs, long executionNs, long modeledNs, long latencyNs, long stallNs, String sched) {

    private static final Pattern LINE = Pattern.compile("summary (\\S+(?: \\(reaction\\))?) jobs (\\d+) released (none|([0-9.]+)\\.\\.([0-9.]+) ms)"
            + " misses (\\d+) overruns (\\d+) worst-response ([0-9.]+) ms bound (none|[0-9.]+ ms) deadline (none|[0-9.]+ ms)"
            + " worst-execution ([0-9.]+) ms modeled ([0-9.]+) ms worst-start-latency ([0-9.]+) ms worst-stall ([0-9.]+) ms sched (.*)");

    /** Scheduled as the analysis assumes: real-time at its rank (0 for reactions), or SCHED_DEADLINE for EDF. */
    boolean asAnalysed() {
        return (sched.startsWith("SCHED_FIFO") || sched.startsWith("SCHED_RR") || sched.startsWith("SCHED_DEADLINE"))
                && !sched.contains("instead of EDF");
    }

    /** The analysis's bound as the program prints it, in nanoseconds; -1 for none. */
    long boundNs() {
        return bound.equals("none") ? -1 : ns(bound.replace(" ms", ""));
    }

    private static final Pattern TRACED = Pattern.compile("\\[\\s*[0-9.]+ ms\\] (summary .*)$");

    /**
     * Every summary line of a program's output, by label: its trace lines ("[  12.345 ms] summary ..."),
     * also behind a prefix (ros2 launch puts the process's name before each line).
     */
    static Map<String, JobSummary> of(String output) {
        Map<String, JobSummary> all = new LinkedHashMap<>();
        for (String raw : output.split("\n")) {
            Matcher t = TRACED.matcher(raw);
            String line = t.find() ? t.group(1) : "";
            if (line.startsWith("summary ") && !line.contains(" messages ")) {
                Matcher m = LINE.matcher(line);
                assertTrue(m.matches(), "a summary line the test cannot read: " + line);
                boolean released = m.group(4) != null;
                all.put(m.group(1), new JobSummary(m.group(1), Long.parseLong(m.group(2)), released ? ns(m.group(4)) : -1,
                        released ? ns(m.group(5)) : -1, Long.parseLong(m.group(6)), Long.parseLong(m.group(7)), ns(m.group(8)), m.group(9),
                        m.group(10).equals("none") ? 0 : ns(m.group(10).replace(" ms", "")), ns(m.group(11)), ns(m.group(12)),
                        ns(m.group(13)), ns(m.group(14)), m.group(15)));
            }
        }
        return all;
    }

    private static long ns(String ms) {
        return Math.round(Double.parseDouble(ms) * 1e6);
    }
}
