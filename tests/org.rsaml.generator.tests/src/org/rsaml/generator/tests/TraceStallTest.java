/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;

/**
 * A generated program whose standard output nobody reads for a while (a pipe to a busy reader, a launcher that stalls)
 * keeps releasing its jobs on time (docs/timing.md, "The trace"): its threads only queue their trace lines, which a
 * writer thread of the default priority writes out; what the full queue cannot take is dropped and said, in a line
 * where it happened and in the summary. Before, a release that traced while the pipe was full waited in the write, with
 * the trace's lock, until the reader came back.
 * <p>
 * The program traces every release, send, arrival and reaction of a producer released every millisecond (some 4 000
 * lines a second, without --quiet); the test reads none of them for {@link #STALL_MS}, more than the pipe and the
 * queue hold, then everything.
 */
class TraceStallTest {

    static final long RUN_MS = 5000;
    static final long STALL_MS = 4000;

    private static final Pattern DROPPED = Pattern.compile("trace dropped (\\d+) lines: its queue of (\\d+) lines \\((\\d+) KiB\\) was"
            + " full, standard output not read in time \\((\\d+) in all\\)");
    private static final Pattern IN_ALL = Pattern.compile("trace dropped (\\d+) lines in all: .*");

    @Test
    void aStalledOutputDoesNotStallTheReleases(@TempDir Path tmp) throws Exception {
        Path model = tmp.resolve("stall.rsaml");
        Files.writeString(model, JobTimingTest.modelText("stall", JobTimingTest.producerAndConsumer(1, 0.2, "1.0", "5.0", "0.1"),
                JobTimingTest.PRODUCER_AND_CONSUMER));
        Path project = tmp.resolve("project");
        new RsamlGenerator().generate(model, Target.CPP, project, false);
        Path exe = Tools.cmakeBuild(project, CppExamplesTest.executableName(project));

        Process p = new ProcessBuilder(exe.toString(), "--run-for-ms", Long.toString(RUN_MS), "--busy-work", "100").directory(project.toFile())
                .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        String output;
        try {
            Thread.sleep(STALL_MS);  // nobody reads: the pipe fills, then the program's queue
            ByteArrayOutputStream read = new ByteArrayOutputStream();
            try (InputStream in = p.getInputStream()) {
                in.transferTo(read);
            }
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the program ends after its run");
            assertEquals(0, p.exitValue(), "the program's status");
            output = read.toString(StandardCharsets.UTF_8);
        } finally {
            p.destroyForcibly();
        }

        RunTrace trace = new RunTrace(output);
        // the drops said where they happened, and in all with the summary
        long dropped = 0;
        long said = 0;
        for (String line : trace.lines) {
            Matcher m = DROPPED.matcher(line);
            if (m.matches()) {
                dropped += Long.parseLong(m.group(1));
                assertEquals(dropped, Long.parseLong(m.group(4)), "each drop line counts the lines dropped so far: " + line);
            }
            Matcher all = IN_ALL.matcher(line);
            if (all.matches()) {
                said = Long.parseLong(all.group(1));
            }
        }
        assertTrue(dropped > 0, "the queue filled while nobody read for " + STALL_MS + " ms, and the lines it dropped are said:\n"
                + Tools.last(output, 3000));
        assertEquals(dropped, said, "the summary says the lines dropped in all:\n" + Tools.last(output, 3000));
        List<String> closing = trace.lines.subList(trace.lines.size() - 4, trace.lines.size());
        assertTrue(IN_ALL.matcher(closing.get(2)).matches() && closing.get(3).startsWith("stop after "),
                "the summary, then the lines dropped in all, then the stop: " + closing);

        // the releases kept their timing: released every period on the grid all along, and none waited for the reader
        Map<String, JobSummary> summaries = JobSummary.of(output);
        JobSummary producer = summaries.get("tasks/producer.f");
        assertNotNull(producer, "the producer's summary, which waits for room rather than be dropped: " + summaries.keySet());
        assertNotNull(summaries.get("tasks/consumer (reaction)"), "the consumer's summary: " + summaries.keySet());
        assertTrue(producer.jobs() >= RUN_MS / 2 && producer.jobs() <= RUN_MS + 500, "about one job a millisecond for " + RUN_MS + " ms: "
                + producer);
        assertEquals((producer.jobs() - 1) * 1_000_000L, producer.lastNs() - producer.firstNs(), 2_000,
                "the producer's jobs on its grid, one every period, none skipped: " + producer);
        assertTrue(producer.worstNs() < STALL_MS * 1_000_000 / 8, "no job of the producer waited for the reader (" + STALL_MS
                + " ms without reading): " + producer);
        if (producer.asAnalysed()) {  // at its real-time priority: its deadlines met, but for the platform's hiccups
            assertTrue(producer.misses() <= producer.jobs() / 20, "the producer missed at most 5 % of its deadlines while its output"
                    + " stalled: " + producer);
        } else {
            PlatformCheck.requireRealtime("TraceStallTest", producer.label(), producer.sched());
        }
        System.out.println("TraceStallTest: " + dropped + " lines dropped while nobody read for " + STALL_MS + " ms; producer " + producer.jobs()
                + " jobs, " + producer.misses() + " misses, worst response " + JobTimingTest.ms(producer.worstNs()) + " (" + producer.sched() + ")");
    }
}
