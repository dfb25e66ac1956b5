/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What both runtimes record of where their jobs ran ({@code rsaml_jobs::record_instant} in
 * runtime/cxx/rsaml/jobs.hpp, the one piece of code for both), as the timing tests read it back
 * ({@link JobSummary}): the worst job, every job over the plain bound counted, the first 1023 listed and
 * the worst of the rest in the last place, none within the bound. A small program of the header alone,
 * built with the C++ compiler the tests build the generated programs with; no real-time thread.
 */
class JobInstantsTest {

    @Test
    void theJobsOverThePlainBoundAreCountedAndListedTheWorstAlways(@TempDir Path tmp) throws Exception {
        // 2100 jobs every 10 ms from 5 s on CLOCK_MONOTONIC, bound 3 ms: job k responds in 2 ms, and every odd one from the 21st in
        // 3.5 ms (1040 over the bound) but job 2091 in 9 ms, the worst; 3 ms exactly (job 10) is within the bound.
        String program = """
                #include <cstdio>
                #include "rsaml/jobs.hpp"
                int main() {
                  rsaml_jobs::Observed o;
                  o.label = "tasks/a.f";
                  o.bound_ns = 3000000;
                  o.listed.reserve(rsaml_jobs::LISTED);
                  for (int k = 1; k <= 2100; ++k) {
                    const std::int64_t release = 5000000000LL + k * 10000000LL;
                    std::int64_t response = k == 2091 ? 9000000 : k == 10 ? 3000000 : k > 20 && k % 2 == 1 ? 3500000 : 2000000;
                    rsaml_jobs::record_instant(release, release + response, o.bound_ns, o.worst_job, o.over_bound, o.listed);
                    ++o.jobs;
                    o.worst_response_ns = response > o.worst_response_ns ? response : o.worst_response_ns;
                  }
                  o.sched = "SCHED_FIFO rank 1";
                  for (const std::string& line : rsaml_jobs::over_bound_lines(o)) {
                    std::printf("[     1.000 ms] %s\\n", line.c_str());
                  }
                  std::printf("[     1.000 ms] %s\\n", rsaml_jobs::line(o).c_str());
                  return 0;
                }
                """;
        Files.writeString(tmp.resolve("instants.cpp"), program);
        Tools.ok(tmp, 120, "g++", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-I" + CppRuntimeTest.shared(), "-o",
                tmp.resolve("instants").toString(), tmp.resolve("instants.cpp").toString());
        String out = Tools.ok(tmp, 30, tmp.resolve("instants").toString());
        Map<String, JobSummary> read = JobSummary.of(out);
        JobSummary s = read.get("tasks/a.f");
        assertEquals(1040, s.overBound(), "every odd job from the 21st is over the bound (job 2091 among them), job 10 at the bound is not");
        assertEquals(1024, s.overBoundJobs().size(), "1024 listed");
        assertArrayEquals(new long[] {25_910_000_000L, 25_919_000_000L}, s.worstJob(), "the worst job, on CLOCK_MONOTONIC");
        for (int i = 0; i < 1023; i++) {
            long release = 5_000_000_000L + (21 + 2L * i) * 10_000_000L;
            assertEquals(release, s.overBoundJobs().get(i)[0], "the first 1023 over the bound listed in order");
        }
        assertArrayEquals(new long[] {25_910_000_000L, 25_919_000_000L}, s.overBoundJobs().get(1023),
                "the last place: the worst of the rest (job 2091, after the first 1023), so the worst is always listed");
        assertEquals(16, s.unlisted(), "the others counted, not listed");
        assertTrue(s.overBoundJobs().stream().noneMatch(j -> j[1] - j[0] <= 3_000_000), "no job within the bound is listed");
    }
}
