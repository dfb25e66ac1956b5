/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.List;

import org.rsaml.analysis.Rational;
import org.rsaml.analysis.Task;

/**
 * The sum of cost / period. Compared with 1 in floating point where it is clearly away from 1, and
 * with exact fractions near 1 (exact sums of thousands of fractions with unrelated periods have
 * denominators of thousands of digits, so they are computed only when they decide something).
 */
public final class Utilisation {

    private static final double MARGIN = 1e-9;

    public final double value;
    private final List<Task> tasks;
    private Rational exact;

    public Utilisation(List<Task> tasks) {
        this.tasks = tasks;
        double u = 0;
        for (Task t : tasks) {
            u += (double) t.cost() / t.period();
        }
        this.value = u;
    }

    /** The exact sum. */
    public Rational exact() {
        if (exact == null) {
            Rational r = Rational.ZERO;
            for (Task t : tasks) {
                r = r.plus(Rational.of(t.cost(), t.period()));
            }
            exact = r;
        }
        return exact;
    }

    /** The sign of U - 1, exact. */
    public int versusOne() {
        if (value > 1 + MARGIN) {
            return 1;
        }
        if (value < 1 - MARGIN) {
            return -1;
        }
        return exact().compareTo(Rational.ONE);
    }

    /** Clearly below 1, so that 1 / (1 - U) in floating point is safe. */
    public boolean clearlyBelowOne() {
        return value < 1 - 1e-6;
    }
}
