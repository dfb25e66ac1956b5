/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlTimes;

/** Times as the analysis, the diagrams, the hover and the generated comments print them, from one place. */
class TimesAsTextTest {

    @ParameterizedTest(name = "{0} ns is {1}")
    @CsvSource({
            "7, 7 ns",
            "999, 999 ns",
            "1000, 1 us",
            "120000, 120 us",
            "2500000, 2.5 ms",
            "2000001, 2.000001 ms",
            "20000000, 20 ms",
            "1500000000, 1.5 s",
            "3000000000, 3 s",
            "-2500000, -2.5 ms",
            "0, 0 ns" })
    void nanosecondsInTheLargestUnitThatKeepsThemExact(long ns, String text) {
        assertEquals(text, RsamlTimes.text(ns), ns + " ns, exactly, in the largest unit");
    }

    @ParameterizedTest(name = "{0} ns is {1}")
    @CsvSource({
            "20000000, 20 ms",
            "250000, 0.25 ms",
            "1, 0.000001 ms",
            "1500000000, 1500 ms",
            "0, 0 ms" })
    void nanosecondsInMilliseconds(long ns, String text) {
        assertEquals(text, RsamlTimes.milliseconds(ns), ns + " ns in milliseconds, without trailing zeros");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({ "S", "MS", "US", "NS" })
    void anElementsTimeUnitIsItsOwnAndMillisecondsWithoutOne(TimeUnit unit) {
        org.rsaml.model.Module module = RsamlFactory.eINSTANCE.createModule();
        module.setTimeUnit(unit);
        assertEquals(unit, RsamlTimes.unit(module), "the unit the element states");
        assertEquals(TimeUnit.MS, RsamlTimes.unit(null), "no element: milliseconds");
    }
}
