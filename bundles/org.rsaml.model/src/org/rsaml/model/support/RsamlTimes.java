/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

import org.rsaml.model.RsamlPackage;
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

    private static final long MAX_WHOLE_NANOSECONDS = 1L << 60;

    private RsamlTimes() {
    }

    /** The unit of time values whose element names none: the metamodel's default of {@code timeUnit} (milliseconds). */
    public static final TimeUnit DEFAULT_UNIT = (TimeUnit) RsamlPackage.Literals.TIME_SCALED__TIME_UNIT.getDefaultValue();

    /** The unit of an element's time values; {@link #DEFAULT_UNIT} when not set. */
    public static TimeUnit unit(TimeScaled owner) {
        return owner == null || owner.getTimeUnit() == null ? DEFAULT_UNIT : owner.getTimeUnit();
    }

    /** The value in nanoseconds, exactly; {@code null} for NaN and infinities. */
    public static BigDecimal nanoseconds(double value, TimeScaled owner) {
        if (Double.isNaN(value) || Double.isInfinite(value)) {
            return null;
        }
        long whole = wholeNanoseconds(value, owner);
        if (whole != NOT_WHOLE) {
            return BigDecimal.valueOf(whole);
        }
        return decimal(value).multiply(BigDecimal.valueOf(unit(owner).getValue()));
    }

    /** What {@link #wholeNanoseconds} returns when it cannot tell the value in nanoseconds as a {@code long}. */
    public static final long NOT_WHOLE = Long.MIN_VALUE;

    /** 10^k for k = 0 to 9, as doubles (exact) and as longs. */
    private static final double[] POWERS = { 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9 };
    private static final long[] LONG_POWERS = { 1L, 10L, 100L, 1_000L, 10_000L, 100_000L, 1_000_000L, 10_000_000L, 100_000_000L,
        1_000_000_000L };

    /**
     * {@link #nanoseconds} without a {@code BigDecimal}, for the times models hold (a whole number of
     * nanoseconds, within a {@code long}): the same number, or {@link #NOT_WHOLE} when the value is not
     * finite, not a whole number of nanoseconds, has more than 15 significant digits or does not fit, and
     * {@link #nanoseconds} must decide. The decimal L × 10^-k (|L| &lt; 10^15, at most as many decimals as
     * the unit has digits below the second) is the value's when L / 10^k, correctly rounded, gives the value
     * back: no two decimals of at most 15 significant digits parse to the same double, so it is the one
     * {@link #decimal} finds, and in nanoseconds it is L × 10^(unit digits - k), whole.
     */
    public static long wholeNanoseconds(double value, TimeScaled owner) {
        int unitDigits = switch (unit(owner)) {
            case NS -> 0;
            case US -> 3;
            case MS -> 6;
            case S -> 9;
        };
        for (int k = 0; k <= unitDigits; k++) {
            double scaled = value * POWERS[k];
            if (!(Math.abs(scaled) < 1e15)) {
                return NOT_WHOLE; // too many digits, or not finite
            }
            long l = (long) Math.rint(scaled);
            if (l / POWERS[k] == value) {
                long factor = LONG_POWERS[unitDigits - k];
                return Math.abs(l) <= Long.MAX_VALUE / factor ? l * factor : NOT_WHOLE;
            }
        }
        return NOT_WHOLE;
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
        long wholeA = wholeNanoseconds(value, owner);
        long wholeB = wholeA == NOT_WHOLE ? NOT_WHOLE : wholeNanoseconds(otherValue, other);
        if (wholeB != NOT_WHOLE) {
            return Long.compare(wholeA, wholeB);
        }
        BigDecimal a = nanoseconds(value, owner);
        BigDecimal b = nanoseconds(otherValue, other);
        if (a == null || b == null) {
            return Double.compare(value * unit(owner).getValue(), otherValue * unit(other).getValue());
        }
        return Integer.signum(a.compareTo(b));
    }

    /** Whether the generated code can hold the value: finite, and at most {@link #MAX_NANOSECONDS} in magnitude. */
    public static boolean representable(double value, TimeScaled owner) {
        long whole = wholeNanoseconds(value, owner);
        if (whole != NOT_WHOLE) {
            return Math.abs(whole) <= MAX_WHOLE_NANOSECONDS;
        }
        BigDecimal ns = nanoseconds(value, owner);
        return ns != null && ns.abs().compareTo(MAX_NANOSECONDS) <= 0;
    }

    /**
     * Whether the generated code can hold the value as a period: {@link #representable representable},
     * and 0 (no period) or at least 1 ns, the resolution of its timers (a shorter one would become 0).
     */
    public static boolean representablePeriod(double value, TimeScaled owner) {
        long whole = wholeNanoseconds(value, owner);
        if (whole != NOT_WHOLE) {
            return Math.abs(whole) <= MAX_WHOLE_NANOSECONDS && (value <= 0 || whole >= 1);
        }
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
