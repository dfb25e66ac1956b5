/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.math.BigDecimal;

import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;
import org.rsaml.model.support.RsamlTimes;

/**
 * A time a node holds as a parameter (a period, a minimum interval, a link's duration), in the time
 * unit of the model element it comes from, so that the parameters file reads as the model does:
 * {@code detect.period_ms: 20.0}. The unit is part of the name; the value is a double (ROS 2's
 * parameter files and {@code ros2 param set} type it from its decimal point).
 *
 * @param name      the parameter's name, the unit's suffix included ({@code detect.period_ms})
 * @param ns        the model's value in nanoseconds
 * @param unit      the unit the parameter is expressed in
 */
public record Ros2TimeParameter(String name, long ns, TimeUnit unit) {

    /** The parameter {@code stem + "_" + unit} for the time {@code ns} of {@code element}, in its unit. */
    public static Ros2TimeParameter of(String stem, long ns, TimeScaled element) {
        TimeUnit unit = RsamlTimes.unit(element);
        return new Ros2TimeParameter(stem + "_" + unit.getLiteral(), ns, unit);
    }

    /** The model's value in the parameter's unit, exactly, as a decimal number with a point ({@code 20.0}, {@code 0.5}). */
    public String value() {
        String text = BigDecimal.valueOf(ns).divide(BigDecimal.valueOf(unit.getValue())).stripTrailingZeros().toPlainString();
        return text.contains(".") ? text : text + ".0";
    }

    /** Nanoseconds per unit, as a C++ double literal. */
    public String nanosPerUnit() {
        return unit.getValue() + ".0";
    }
}
