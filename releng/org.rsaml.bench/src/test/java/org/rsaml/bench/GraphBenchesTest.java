/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

/** The RSA-28 and latency-path benchmarks run at small sizes and measure the models they say they measure. */
class GraphBenchesTest {

    private interface Main {
        void run() throws Exception;
    }

    private static String output(Main main) throws Exception {
        PrintStream stdout = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        try {
            main.run();
        } finally {
            System.setOut(stdout);
        }
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void theTopicsBenchFindsTheTopicsItNamesTwice() throws Exception {
        String table = output(() -> TopicsBench.main(new String[] { "200,400" }));
        // one module in 100 names another group's topic: two findings each, and t_0's own two ports
        assertTrue(table.matches("(?s).*\\| 200 \\| 99 \\| [^\\n]* \\| 4 \\|\\n.*"), "200 ports, 4 findings:\n" + table);
        assertTrue(table.matches("(?s).*\\| 400 \\| 199 \\| [^\\n]* \\| 6 \\|\\n.*"), "400 ports, 6 findings:\n" + table);
        assertFalse(table.contains("the validation reported"), "the rule alone and the validation agree:\n" + table);
    }

    @Test
    void theLatencyPathsBenchBoundsEachGraphsPaths() throws Exception {
        String table = output(() -> LatencyPathsBench.main(new String[] { "chain:20,ladder:22,dense:10" }));
        assertTrue(table.matches("(?s).*\\| chain \\| 20 \\| 19 \\| 1 \\| 1 \\| [^\\n]* \\| MEETS \\|\\n.*"), "a chain has one path:\n" + table);
        assertTrue(table.matches("(?s).*\\| ladder \\| 22 \\| 40 \\| 1,024 \\| 1,024 \\| [^\\n]* \\| MEETS \\|\\n.*"),
                "a ladder of 10 layers of two, then the actuator's module, has 2^10 paths, all listed:\n" + table);
        assertTrue(table.matches("(?s).*\\| dense \\| 10 \\| 45 \\| 256 \\| 256 \\| [^\\n]* \\| MEETS \\|\\n.*"),
                "a dense graph of 10 modules has 2^8 paths, all listed:\n" + table);
    }
}
