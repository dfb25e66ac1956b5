/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;

/**
 * Exact arithmetic on time values written in different units. A value is read as the shortest
 * decimal that parses to the same double ({@link #decimal(double)}), which is the number the
 * architect wrote whenever it has at most 15 significant digits, and scaled to nanoseconds by a
 * power of ten: no rounding, no tolerance.
 */
public final class RsamlTimes {

    /**
     * The longest time the generated code holds, 2^60 ns (about 36.5 years): it counts time in
     * signed 64-bit nanoseconds ({@code std::chrono::nanoseconds}, ROS 2's {@code rcl} timers) and
     * adds a period and an offset to the clock's current value without overflow.
     */
    public static final BigDecimal MAX_NANOSECONDS = BigDecimal.valueOf(1L << 60);

    private RsamlTimes() {
    }

    /** The unit of an element's time values; milliseconds when not set. */
    public static TimeUnit unit(TimeScaled owner) {
        return owner == null || owner.getTimeUnit() == null ? TimeUnit.MS : owner.getTimeUnit();
    }

    /** The value in nanoseconds, exactly; {@code null} for NaN and infinities. */
    public static BigDecimal nanoseconds(double value, TimeScaled owner) {
        if (Double.isNaN(value) || Double.isInfinite(value)) {
            return null;
        }
        return decimal(value).multiply(BigDecimal.valueOf(unit(owner).getValue()));
    }

    /**
     * The shortest decimal that parses back to {@code value}. Not {@link BigDecimal#valueOf(double)}:
     * before Java 19, {@link Double#toString(double)} sometimes gives a longer decimal (2e23 prints
     * as 1.9999999999999998E23).
     */
    public static BigDecimal decimal(double value) {
        if (value == 0) {
            return BigDecimal.ZERO;
        }
        // Java's decimal when it has at most 15 significant digits: no other decimal that short parses to the same
        // normal double (15 digits always survive a round trip), so it is the shortest; the search below is 10x slower.
        if (Math.abs(value) >= Double.MIN_NORMAL) {
            BigDecimal printed = new BigDecimal(Double.toString(value)).stripTrailingZeros();
            if (printed.precision() <= 15) {
                return printed;
            }
        }
        BigDecimal exact = new BigDecimal(value);
        for (int digits = 1; digits < 17; digits++) {
            BigDecimal shorter = exact.round(new MathContext(digits, RoundingMode.HALF_EVEN));
            if (shorter.doubleValue() == value) {
                return shorter;
            }
        }
        return exact.round(new MathContext(17, RoundingMode.HALF_EVEN));
    }

    /**
     * Compares {@code value} in {@code owner}'s unit with {@code otherValue} in {@code other}'s
     * unit, exactly: negative, zero or positive as the first is shorter, equal or longer. Values
     * that are not finite compare as doubles.
     */
    public static int compare(double value, TimeScaled owner, double otherValue, TimeScaled other) {
        BigDecimal a = nanoseconds(value, owner);
        BigDecimal b = nanoseconds(otherValue, other);
        if (a == null || b == null) {
            return Double.compare(value * unit(owner).getValue(), otherValue * unit(other).getValue());
        }
        return Integer.signum(a.compareTo(b));
    }

    /** Whether the generated code can hold the value: finite, and at most {@link #MAX_NANOSECONDS} in magnitude. */
    public static boolean representable(double value, TimeScaled owner) {
        BigDecimal ns = nanoseconds(value, owner);
        return ns != null && ns.abs().compareTo(MAX_NANOSECONDS) <= 0;
    }

    /**
     * Whether the generated code can hold the value as a period: {@link #representable representable},
     * and 0 (no period) or at least 1 ns, the resolution of its timers (a shorter one would become 0).
     */
    public static boolean representablePeriod(double value, TimeScaled owner) {
        return representable(value, owner) && (value <= 0 || nanoseconds(value, owner).compareTo(BigDecimal.ONE) >= 0);
    }

    private static final long[] SCALE = { 1_000_000_000L, 1_000_000L, 1_000L };
    private static final int[] DIGITS = { 9, 6, 3 };
    private static final String[] SCALE_UNIT = { "s", "ms", "us" };

    /**
     * Nanoseconds as people read them, in the largest unit that keeps them exact: {@code 2.5 ms},
     * {@code 120 us}, {@code 7 ns} (how the analysis, its timelines and the diagrams print times).
     */
    public static String text(long ns) {
        for (int i = 0; i < SCALE.length; i++) {
            if (Math.abs(ns) >= SCALE[i]) {
                // in whole numbers (every response and hop is printed: no BigDecimal division)
                long whole = ns / SCALE[i];
                long fraction = Math.abs(ns % SCALE[i]);
                if (fraction == 0) {
                    return whole + " " + SCALE_UNIT[i];
                }
                StringBuilder digits = new StringBuilder(Long.toString(fraction));
                while (digits.length() < DIGITS[i]) {
                    digits.insert(0, '0');
                }
                int end = digits.length();
                while (digits.charAt(end - 1) == '0') {
                    end--;
                }
                return whole + "." + digits.substring(0, end) + " " + SCALE_UNIT[i];
            }
        }
        return ns + " ns";
    }

    /** Nanoseconds in milliseconds, exactly, without trailing zeros: {@code 20 ms}, {@code 0.25 ms}. */
    public static String milliseconds(long ns) {
        return BigDecimal.valueOf(ns, 6).stripTrailingZeros().toPlainString() + " ms";
    }
}
