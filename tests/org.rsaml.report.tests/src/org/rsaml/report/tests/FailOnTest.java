/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;


import org.junit.jupiter.api.Test;
import org.rsaml.analysis.Verdict;
import org.rsaml.report.FindingFailOn;
import org.rsaml.report.TimingFailOn;
import org.rsaml.validation.Severity;

/** The levels a user writes for {@code --fail-on} and {@code failOn}, and what each makes fail. */
class FailOnTest {

    @Test
    void findingLevelsAreReadInAnyCaseAndMapToTheLowestFailingSeverity() {
        assertEquals(Severity.ERROR, FindingFailOn.parse("error").threshold(), "error: only errors fail");
        assertEquals(Severity.WARNING, FindingFailOn.parse(" Warning ").threshold(), "warning, any case and blanks: warnings fail too");
        assertNull(FindingFailOn.parse("NEVER").threshold(), "never: no severity fails");
        assertEquals("warning", FindingFailOn.WARNING.toString(), "a level prints as the user writes it");
    }

    @Test
    void anUnknownFindingLevelIsRefusedNamingTheValueAndTheLevels() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FindingFailOn.parse("warnings"));
        assertEquals("'warnings' is not a level; it is one of error, warning, never", e.getMessage(),
                "the message says what was written and what can be");
        assertThrows(IllegalArgumentException.class, () -> FindingFailOn.parse(null), "no level is not a level");
    }

    @Test
    void missFailsOnlyAMiss() {
        TimingFailOn miss = TimingFailOn.parse("miss");
        assertTrue(miss.fails(Verdict.MISSES), "a possible miss fails");
        assertFalse(miss.fails(Verdict.NOT_ANALYSED), "what is not analysed does not fail by default");
        assertFalse(miss.fails(Verdict.MEETS), "a proven model passes");
        assertEquals(Severity.ERROR, miss.findingThreshold(), "in SARIF and JUnit, the timing rules' errors (the misses) fail");
    }

    @Test
    void notAnalysedFailsAllButAProvenModel() {
        TimingFailOn strict = TimingFailOn.parse(" Not-Analysed");
        assertTrue(strict.fails(Verdict.MISSES), "a possible miss fails");
        assertTrue(strict.fails(Verdict.NOT_ANALYSED), "what is not analysed fails");
        assertFalse(strict.fails(Verdict.MEETS), "a proven model passes");
        assertEquals(Severity.WARNING, strict.findingThreshold(), "RSA-24, a warning, fails the reports too");
    }

    @Test
    void neverFailsNothingAndUnknownTimingLevelsAreNone() {
        TimingFailOn never = TimingFailOn.parse("never");
        for (Verdict verdict : Verdict.values()) {
            assertFalse(never.fails(verdict), "never fails no verdict, not " + verdict);
        }
        assertNull(never.findingThreshold(), "never: no finding fails the reports");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TimingFailOn.parse("misses"));
        assertEquals("'misses' is not a level; it is one of miss, not-analysed, never", e.getMessage(),
                "a level that does not exist is refused, naming the levels there are");
        assertEquals("not-analysed", TimingFailOn.NOT_ANALYSED.toString(), "a level prints as the user writes it");
    }
}
