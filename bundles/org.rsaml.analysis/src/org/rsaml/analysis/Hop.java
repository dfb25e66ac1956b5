/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

/**
 * One stage of an end-to-end path and what it adds to the latency.
 *
 * @param label      {@code layer/module}, or the connection {@code from -> to}
 * @param activation how the stage picks the data up, in words
 * @param waitNs     the longest the data waits before the stage starts on it (sampling)
 * @param responseNs the stage's worst-case response time once started
 */
public record Hop(String label, String activation, long waitNs, long responseNs) {

    /** What the stage adds: wait plus response. */
    public long totalNs() {
        return waitNs + responseNs;
    }
}
