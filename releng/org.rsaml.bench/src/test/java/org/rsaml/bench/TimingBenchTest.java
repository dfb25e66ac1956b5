/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.Verdict;
import org.rsaml.model.Architecture;

/** The timing benchmark runs at every size docs/benchmarks.md lets a user choose, small ones included. */
class TimingBenchTest {

    @Test
    void tenModulesAsInTheDocumentedShortRun() throws Exception {
        PrintStream stdout = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        try {
            TimingBench.main(new String[] { "10" });
        } finally {
            System.setOut(stdout);
        }
        String table = out.toString(StandardCharsets.UTF_8);
        assertTrue(table.contains("| 10 | 4 | 100 | "), table);
        assertTrue(table.contains("MEETS (100 requirements met)"), table);
    }

    @Test
    void everySmallSizeHasRequirementsWithinTheArchitecture() throws Exception {
        for (int modules = 1; modules <= 12; modules++) {
            Architecture a = TimingBench.architecture(modules, 100);
            assertEquals(modules, a.getLayers().stream().mapToInt(l -> l.getModules().size()).sum(), "the benchmark's architecture has the modules asked for");
            ArchitectureTiming timing = TimingAnalysis.analyse(a);
            assertEquals(modules == 1 ? 0 : 100, timing.latencies().size(), modules + " modules");
            assertEquals(Verdict.MEETS, timing.verdict(), modules + " modules");
        }
    }
}
