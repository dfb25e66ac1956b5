/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.function.Supplier;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlTimes;

/**
 * How the plan and the analysis read a time of the model: exactly, as {@link RsamlTimes} scales it
 * (the number the architect wrote, times a power of ten), rounded to the nearest nanosecond.
 * Every time the plan, the task set and the latency requirements use comes through here.
 */
public final class PlanTimes {

    private PlanTimes() {
    }

    /**
     * The value, in {@code owner}'s unit (milliseconds when none), in whole nanoseconds. For a time
     * that the plan has accepted ({@link #checked}); others are clamped to 0 and
     * {@link ExecutionPlan#MAX_TIME_NS} (not finite counts as 0).
     */
    public static long nanos(double value, TimeScaled owner) {
        long whole = RsamlTimes.wholeNanoseconds(value, owner);
        if (whole != RsamlTimes.NOT_WHOLE) {
            return Math.max(0, Math.min(whole, ExecutionPlan.MAX_TIME_NS));
        }
        BigDecimal ns = RsamlTimes.nanoseconds(value, owner);
        if (ns == null || ns.signum() <= 0) {
            return 0;
        }
        BigDecimal max = RsamlTimes.MAX_NANOSECONDS;
        return ns.compareTo(max) >= 0 ? max.longValueExact() : ns.setScale(0, RoundingMode.HALF_UP).longValueExact();
    }

    /**
     * A time attribute of an element in nanoseconds, refused when the generated code cannot
     * represent it: not finite, negative, longer than {@link ExecutionPlan#MAX_TIME_NS}, or, for a
     * period, shorter than 1 ns. The limits are validation's (RSA-20), so that a model without
     * errors is always planned.
     *
     * @param label the element as messages name it ({@code layer/module.function})
     */
    public static long checked(double value, TimeScaled owner, String attribute, String label, boolean period)
            throws UnplannableException {
        return checked(value, owner, attribute, () -> label, period);
    }

    /** The same, the label worded only when the time is refused. */
    public static long checked(double value, TimeScaled owner, String attribute, Supplier<String> label, boolean period)
            throws UnplannableException {
        if (value == 0) {
            return 0; // the most common time by far (not set), and always representable
        }
        long whole = RsamlTimes.wholeNanoseconds(value, owner);
        if (whole > 0 && whole <= ExecutionPlan.MAX_TIME_NS) {
            return whole; // finite, positive, whole nanoseconds (so at least 1 ns), within the clock: accepted
        }
        return refusedOr(value, owner, attribute, label.get(), period);
    }

    private static long refusedOr(double value, TimeScaled owner, String attribute, String label, boolean period)
            throws UnplannableException {
        TimeUnit unit = RsamlTimes.unit(owner);
        String what = attribute + " " + format(value) + " " + unit.getLiteral() + " of " + label;
        if (!Double.isFinite(value)) {
            throw new UnplannableException((EObject) owner, what + " is not a finite number; give a number of " + unit.getLiteral());
        }
        if (value < 0) {
            throw new UnplannableException((EObject) owner, what + " is negative; give 0 or more");
        }
        if (!RsamlTimes.representable(value, owner)) {
            throw new UnplannableException((EObject) owner, what + " is longer than generated code can count (at most 2^60 ns, "
                    + "about 36 years); give a shorter time");
        }
        if (period && !RsamlTimes.representablePeriod(value, owner)) {
            throw new UnplannableException((EObject) owner, what + " is shorter than 1 ns, the resolution of generated code; "
                    + "give a longer period");
        }
        return nanos(value, owner);
    }

    private static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
