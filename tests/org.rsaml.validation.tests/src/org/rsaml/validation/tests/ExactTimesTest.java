/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.rsaml.model.Architecture;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlTimes;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;

/** RSA-08 compares a module's execution duration with its layer's budget exactly, in any pair of units. */
class ExactTimesTest {

    private static List<String> budgetFindings(String exec, String execUnit, String budget, String budgetUnit) {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName("robot");
        a.setDeclaredLayers(1);
        Layer layer = f.createLayer();
        layer.setName("control");
        layer.setTimeUnit(TimeUnit.get(budgetUnit));
        layer.setMaxExecTime(Double.parseDouble(budget));
        Module m = f.createModule();
        m.setName("checker");
        m.setTimeUnit(TimeUnit.get(execUnit));
        m.setExecDuration(Double.parseDouble(exec));
        // a periodic function activates the module (RSA-19) without a time of its own to compare
        org.rsaml.model.Function step = f.createFunction();
        step.setName("step");
        step.setExecType(ExecutionType.PERIODIC);
        step.setPeriod(1);
        m.getFunctions().add(step);
        layer.getModules().add(m);
        a.getLayers().add(layer);
        return RsamlModelValidator.validate(a).stream().map(Finding::ruleId).collect(Collectors.toList());
    }

    @ParameterizedTest(name = "{0} {1} within {2} {3}")
    @CsvSource({
            "2000, us, 2, ms", "2, ms, 2000, us", "1, s, 1000, ms", "1000, ms, 1, s", "1, ns, 0.000001, ms",
            "0.000001, ms, 1, ns", "16964.9, s, 16964900, ms", "16964900, ms, 16964.9, s", "1e9, s, 1e12, ms",
            "1e12, ms, 1e9, s", "1e9, s, 1e18, ns", "0.1, s, 100, ms", "100, ms, 0.1, s", "0.3, us, 300, ns",
            "1.1, ms, 1100000, ns", "1e-6, s, 1, us", "1, us, 1e-6, s", "2.5, ms, 0.0025, s", "123456.789, us, 0.123456789, s",
            "0.0000005, us, 0.0005, ns", "282879384806159000, ns, 282879384.806159, s" })
    void equalDurationsInDifferentUnitsAreWithinBudget(String exec, String execUnit, String budget, String budgetUnit) {
        assertEquals(List.of(), budgetFindings(exec, execUnit, budget, budgetUnit), exec + " " + execUnit + " is within a budget of " + budget + " " + budgetUnit + ": no finding");
    }

    @ParameterizedTest(name = "{0} {1} exceeds {2} {3}")
    @CsvSource({
            "2001, us, 2, ms", "2.001, ms, 2000, us", "1.001, s, 1000, ms", "1001, ms, 1, s", "2, ns, 0.000001, ms",
            "0.000002, ms, 1, ns", "16964.9000001, s, 16964900, ms", "16964900.0001, ms, 16964.9, s",
            "1000000000.000001, s, 1e12, ms", "1e12, ms, 999999999.9999, s", "0.1000001, s, 100, ms",
            "1.0000000000001, s, 1000, ms", "0.0000015, us, 0.0005, ns", "1100001, ns, 1.1, ms",
            "2000.0000001, us, 2, ms", "123456.7891, us, 0.123456789, s" })
    void anExcessOfOneUnitInTheLastWrittenDigitIsAFinding(String exec, String execUnit, String budget, String budgetUnit) {
        assertEquals(List.of("RSA-08"), budgetFindings(exec, execUnit, budget, budgetUnit), exec + " " + execUnit + " exceeds a budget of " + budget + " " + budgetUnit + ": RSA-08");
    }

    @Test
    void everyPairOfUnitsIsComparedExactly() {
        String[] units = { "ns", "us", "ms", "s" };
        long[] ns = { 1, 1_000, 1_000_000, 1_000_000_000 };
        for (int i = 0; i < units.length; i++) {
            for (int j = 0; j < units.length; j++) {
                // 7 of unit j written in unit i: 7 * ns[j] / ns[i]
                java.math.BigDecimal written = java.math.BigDecimal.valueOf(7 * ns[j])
                        .divide(java.math.BigDecimal.valueOf(ns[i])).stripTrailingZeros();
                java.math.BigDecimal more = written.add(java.math.BigDecimal.ONE.movePointLeft(Math.max(written.scale(), 0) + 1));
                assertEquals(List.of(), budgetFindings(written.toPlainString(), units[i], "7", units[j]),
                        written + " " + units[i] + " vs 7 " + units[j]);
                assertEquals(List.of("RSA-08"), budgetFindings(more.toPlainString(), units[i], "7", units[j]),
                        more + " " + units[i] + " vs 7 " + units[j]);
            }
        }
    }

    /** Java 17 prints some doubles with more digits than were written (2.82879384806159E17 as ...159008E17). */
    @Test
    void valuesAreReadAsWrittenWhereJavaPrintsMoreDigits() {
        assertEquals("2.82879384806159E+17", RsamlTimes.decimal(2.82879384806159E17).toString(), "a large time is kept exactly, not rounded");
        assertEquals("2E+23", RsamlTimes.decimal(2e23).toString(), "a huge time is kept exactly");
        assertEquals("0.1", RsamlTimes.decimal(0.1).toString(), "0.1 is read as written, not as its binary approximation");
    }

    /** The shortest decimal as its definition finds it (fewest significant digits that parse back), against the fast path. */
    @Test
    void everyValueIsReadAsTheShortestDecimalThatParsesBack() {
        java.util.Random random = new java.util.Random(20261127L);
        List<Double> values = new java.util.ArrayList<>(List.of(0.1, 0.2, 0.3, 2.5, 10.0, 1e23, 2e23, 5e-324, Double.MAX_VALUE,
                Double.MIN_NORMAL, 2.82879384806159E17, 123456789012345.0, 1234567890123456.0, 0.001, 1e-9, 999.999, -7.25));
        for (int i = 0; i < 20_000; i++) {
            values.add(switch (i % 4) {
            case 0 -> Double.longBitsToDouble(random.nextLong() & 0x7fefffffffffffffL);
            case 1 -> Math.round(random.nextDouble() * 1e6) / 1e3;
            case 2 -> (double) random.nextInt(1_000_000);
            default -> Double.parseDouble(random.nextInt(1000) + "." + random.nextInt(1_000_000) + "e" + (random.nextInt(40) - 20));
            });
        }
        for (double v : values) {
            assertEquals(shortest(v), RsamlTimes.decimal(v), () -> "decimal(" + v + ")");
        }
    }

    private static java.math.BigDecimal shortest(double value) {
        java.math.BigDecimal exact = new java.math.BigDecimal(value);
        for (int digits = 1; digits < 17; digits++) {
            java.math.BigDecimal shorter = exact.round(new java.math.MathContext(digits, java.math.RoundingMode.HALF_EVEN));
            if (shorter.doubleValue() == value) {
                return shorter;
            }
        }
        return exact.round(new java.math.MathContext(17, java.math.RoundingMode.HALF_EVEN));
    }
}
