/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The timing tests skip their bound check only while another program has real-time threads
 * ({@link PlatformCheck#otherRealtimeThreads}): the look-out must see one, and must not count the
 * test's own programs.
 */
class PlatformCheckTest {

    @Test
    void anotherProgramsRealtimeThreadIsSeenAndTheTestsOwnAreNot(@TempDir Path tmp) throws Exception {
        // Started by a shell that exits at once: the sleeper is no longer this JVM's descendant, as another program's thread.
        Tools.Result started = Tools.run(tmp, 10, "sh", "-c", "chrt -f 1 sleep 2 >/dev/null 2>&1 & echo $!; wait_for=$!; sleep 0.2; kill -0 $wait_for");
        Assumptions.assumeTrue(started.exit() == 0, "SCHED_FIFO not permitted here (chrt -f 1): " + started.output());
        long pid = Long.parseLong(started.output().lines().findFirst().orElseThrow().strip());
        try {
            assertTrue(PlatformCheck.otherRealtimeThreads().contains(pid + " sleep"),
                    "another program's SCHED_FIFO thread (pid " + pid + ") is seen: " + PlatformCheck.otherRealtimeThreads());
        } finally {
            ProcessHandle.of(pid).ifPresent(ProcessHandle::destroy);
        }
        Process own = new ProcessBuilder("chrt", "-f", "1", "sleep", "1").start();
        try {
            Thread.sleep(200);
            assertFalse(PlatformCheck.otherRealtimeThreads().stream().anyMatch(t -> t.startsWith(own.pid() + " ")),
                    "a real-time program the test started itself is not another program's");
        } finally {
            own.destroy();
        }
    }
}
