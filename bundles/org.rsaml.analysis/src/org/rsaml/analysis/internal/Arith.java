/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

/** Overflow-checked integer arithmetic on nanoseconds; an overflow ends the analysis, it never wraps. */
public final class Arith {

    private Arith() {
    }

    /** ceil(a / b) for a &ge; 0 (a may be negative, giving the mathematical ceiling), b &gt; 0. */
    public static long ceilDiv(long a, long b) {
        return Math.floorDiv(a, b) + (Math.floorMod(a, b) == 0 ? 0 : 1);
    }

    public static long add(long a, long b) {
        return Math.addExact(a, b);
    }

    public static long mul(long a, long b) {
        return Math.multiplyExact(a, b);
    }

    /** Thrown when a computed time leaves the range of 64-bit nanoseconds (about 292 years). */
    public static final class TooLarge extends RuntimeException {
        private static final long serialVersionUID = 1L;

        public TooLarge() {
            super("times exceed 2^63 ns (about 292 years)", null, false, false);
        }
    }
}
