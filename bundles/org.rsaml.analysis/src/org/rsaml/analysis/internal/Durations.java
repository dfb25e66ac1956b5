/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.math.BigDecimal;

/** Nanoseconds in the largest unit that keeps them exact: "2.5 ms", "120 us", "7 ns". */
public final class Durations {

    private static final long[] SCALE = { 1_000_000_000L, 1_000_000L, 1_000L };
    private static final String[] UNIT = { "s", "ms", "us" };

    private Durations() {
    }

    public static String format(long ns) {
        for (int i = 0; i < SCALE.length; i++) {
            if (Math.abs(ns) >= SCALE[i]) {
                BigDecimal v = BigDecimal.valueOf(ns).divide(BigDecimal.valueOf(SCALE[i]));
                return v.stripTrailingZeros().toPlainString() + " " + UNIT[i];
            }
        }
        return ns + " ns";
    }
}
