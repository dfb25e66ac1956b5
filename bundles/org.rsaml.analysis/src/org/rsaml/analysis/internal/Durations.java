/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

/** Nanoseconds in the largest unit that keeps them exact: "2.5 ms", "120 us", "7 ns". */
public final class Durations {

    private static final long[] SCALE = { 1_000_000_000L, 1_000_000L, 1_000L };
    private static final int[] DIGITS = { 9, 6, 3 };
    private static final String[] UNIT = { "s", "ms", "us" };

    private Durations() {
    }

    public static String format(long ns) {
        for (int i = 0; i < SCALE.length; i++) {
            if (Math.abs(ns) >= SCALE[i]) {
                // in whole numbers (every response and hop is formatted: no BigDecimal division)
                long whole = ns / SCALE[i];
                long fraction = Math.abs(ns % SCALE[i]);
                if (fraction == 0) {
                    return whole + " " + UNIT[i];
                }
                StringBuilder digits = new StringBuilder(Long.toString(fraction));
                while (digits.length() < DIGITS[i]) {
                    digits.insert(0, '0');
                }
                int end = digits.length();
                while (digits.charAt(end - 1) == '0') {
                    end--;
                }
                return whole + "." + digits.substring(0, end) + " " + UNIT[i];
            }
        }
        return ns + " ns";
    }
}
