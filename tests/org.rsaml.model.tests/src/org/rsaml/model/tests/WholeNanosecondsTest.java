/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlTimes;

/**
 * The long arithmetic of times ({@link RsamlTimes#wholeNanoseconds}) gives the exact decimal's
 * nanoseconds ({@link RsamlTimes#decimal} scaled by the unit) or leaves the decision to it: never a
 * different number.
 */
class WholeNanosecondsTest {

    private static Module in(TimeUnit unit) {
        Module m = RsamlFactory.eINSTANCE.createModule();
        m.setTimeUnit(unit);
        return m;
    }

    /** The definition: the shortest decimal of the double, times the unit, when that is a whole number of a long. */
    private static BigDecimal exact(double value, TimeUnit unit) {
        return RsamlTimes.decimal(value).multiply(BigDecimal.valueOf(unit.getValue()));
    }

    private static void agrees(double value, TimeUnit unit) {
        long whole = RsamlTimes.wholeNanoseconds(value, in(unit));
        if (whole != RsamlTimes.NOT_WHOLE) {
            BigDecimal exact = exact(value, unit);
            assertEquals(0, exact.compareTo(BigDecimal.valueOf(whole)),
                    value + " " + unit.getLiteral() + " is " + exact.toPlainString() + " ns, not " + whole);
        }
    }

    @ParameterizedTest(name = "{0} {1} is {2} ns without BigDecimal")
    @CsvSource({ "0, ms, 0", "1, ns, 1", "2.5, ms, 2500000", "0.1, s, 100000000", "0.3, us, 300", "16964.9, s, 16964900000000",
            "123456.789, us, 123456789", "0.000001, ms, 1", "1e-9, s, 1", "-2.5, ms, -2500000", "1e9, s, 1000000000000000000",
            "282879384.806159, s, 282879384806159000" })
    void timesAsModelsWriteThemAreWhole(double value, String unit, long ns) {
        assertEquals(ns, RsamlTimes.wholeNanoseconds(value, in(TimeUnit.get(unit))), value + " " + unit);
    }

    @ParameterizedTest(name = "{0} {1} is left to the exact decimal")
    @CsvSource({ "0.5, ns", "1e-10, s", "1e10, s", "0.1234567890123456, ms", "NaN, ms", "Infinity, s", "-Infinity, us",
            "1e300, ns", "4.9e-324, ms" })
    void timesBeyondALongOrBelowANanosecondAreNotWhole(double value, String unit) {
        assertEquals(RsamlTimes.NOT_WHOLE, RsamlTimes.wholeNanoseconds(value, in(TimeUnit.get(unit))), value + " " + unit);
    }

    @Test
    void randomDecimalsAndDoublesAgreeWithTheExactDecimal() {
        Random random = new Random(20261127);
        int[] unitDigits = { 0, 3, 6, 9 }; // ns, us, ms, s
        for (int i = 0; i < 200_000; i++) {
            int u = random.nextInt(4);
            TimeUnit unit = TimeUnit.VALUES.stream().filter(t -> t.getValue() == (int) Math.pow(10, unitDigits[u])).findFirst().orElseThrow();
            // decimals as people write them (up to 15 digits, up to 12 decimals), their neighbours, and arbitrary doubles
            BigDecimal decimal = BigDecimal.valueOf(random.nextLong() % 1_000_000_000_000_000L, random.nextInt(13));
            double written = Double.parseDouble(decimal.toString());
            double[] values = { written, Math.nextUp(written), Math.nextDown(written), Double.longBitsToDouble(random.nextLong()),
                random.nextDouble() * Math.pow(10, random.nextInt(24) - 12) };
            for (double v : values) {
                agrees(v, unit);
            }
            if (decimal.scale() <= unitDigits[u] && decimal.movePointRight(unitDigits[u]).abs().compareTo(BigDecimal.valueOf(Long.MAX_VALUE)) <= 0) {
                assertNotEquals(RsamlTimes.NOT_WHOLE, RsamlTimes.wholeNanoseconds(written, in(unit)),
                        decimal + " " + unit.getLiteral() + " is a whole number of nanoseconds within a long, told without BigDecimal");
            }
        }
    }

    @Test
    void comparisonsAndLimitsAreTheExactOnes() {
        Module ms = in(TimeUnit.MS);
        Module s = in(TimeUnit.S);
        assertEquals(0, RsamlTimes.compare(1000, ms, 1, s), "1000 ms = 1 s");
        assertEquals(-1, RsamlTimes.compare(999.999999, ms, 1, s), "999.999999 ms < 1 s");
        assertEquals(1, RsamlTimes.compare(1000.000001, ms, 1, s), "1000.000001 ms > 1 s");
        assertTrue(RsamlTimes.representable(1152921504, s), "1,152,921,504 s is below 2^60 ns");
        assertTrue(!RsamlTimes.representable(1152921505, s), "1,152,921,505 s is above 2^60 ns");
        assertTrue(!RsamlTimes.representable(-1152921505, s), "and so is its negative");
        assertTrue(RsamlTimes.representablePeriod(1e-6, ms), "1 ns is a period");
        assertTrue(!RsamlTimes.representablePeriod(1e-7, ms), "0.1 ns is not");
        assertNotEquals(RsamlTimes.NOT_WHOLE, RsamlTimes.wholeNanoseconds(1152921505, s), "decided without BigDecimal");
    }
}
