/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** The trace a generated C++ program prints: {@code [  12.345 ms] send layer/module.port #3}. */
final class RunTrace {
    private static final Pattern LINE = Pattern.compile("^\\[\\s*([0-9.]+) ms\\] (.*)$");
    private static final Pattern RECV = Pattern.compile("recv (\\S+) <- (\\S+) #(\\d+)( by \\S+)?");
    private static final Pattern SEND = Pattern.compile("send (\\S+) #(\\d+)");
    private static final Pattern STOP = Pattern.compile("stop after (\\d+) ms");

    final List<String> lines = new ArrayList<>();
    final List<Double> times = new ArrayList<>();
    final String output;

    private static final Pattern DROPPED = Pattern.compile("\\] (trace dropped \\d+ lines in all[^\\n]*)");

    /**
     * Fails, saying why, when the program's trace queue dropped lines (its output was not read in time: the
     * runtimes say so after the summary, docs/timing.md, "The trace"): its miss and overrun lines then cannot be
     * counted against its summary. Called before any such count.
     */
    static void assertNoneDropped(String what, String output) {
        Matcher m = DROPPED.matcher(output);
        if (m.find()) {
            fail(what + ": the program's output was not read in time, so its miss and overrun lines cannot be counted against"
                    + " its summary: " + m.group(1));
        }
    }

    RunTrace(String output) {
        this.output = output;
        for (String raw : output.split("\n")) {
            Matcher m = LINE.matcher(raw);
            if (m.matches()) {
                times.add(Double.parseDouble(m.group(1)));
                lines.add(m.group(2));
            }
        }
    }

    /** How long the run lasted, from its last line. */
    long durationMs() {
        for (int i = lines.size() - 1; i >= 0; i--) {
            Matcher m = STOP.matcher(lines.get(i));
            if (m.matches()) {
                return Long.parseLong(m.group(1));
            }
        }
        fail("the run did not stop cleanly (no 'stop after' line):\n" + Tools.last(output, 3000));
        return 0;
    }

    long count(String line) {
        return lines.stream().filter(line::equals).count();
    }

    List<String> matching(String prefix) {
        return lines.stream().filter(l -> l.startsWith(prefix)).toList();
    }

    /** Messages from source received by target, as sequence numbers, each checked to follow its send. */
    List<Long> received(String target, String source, boolean replacing) {
        Map<Long, Integer> sentAt = new HashMap<>();
        List<Long> received = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            Matcher s = SEND.matcher(lines.get(i));
            if (s.matches() && s.group(1).equals(source)) {
                sentAt.put(Long.parseLong(s.group(2)), i);
            }
            Matcher r = RECV.matcher(lines.get(i));
            if (r.matches() && r.group(1).equals(target) && r.group(2).equals(source) && (r.group(4) != null) == replacing) {
                long n = Long.parseLong(r.group(3));
                Integer sent = sentAt.get(n);
                assertTrue(sent != null && sent < i, "line " + (i + 1) + " '" + lines.get(i) + "' has no earlier 'send " + source + " #" + n + "'");
                received.add(n);
            }
        }
        return received;
    }

    long sends(String source) {
        return lines.stream().filter(l -> SEND.matcher(l).matches() && l.startsWith("send " + source + " #")).count();
    }
}
