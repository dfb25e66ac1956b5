/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.rsaml.model.Function;
import org.rsaml.model.support.RsamlLabels;

public final class PlannedFunction {
    final PlannedModule module;
    final Function function;
    final String name;
    final List<PlannedAction> actions = new ArrayList<>();
    boolean timed;
    long periodNs;
    long deadlineNs;
    long costNs;
    long minIntervalNs;

    PlannedFunction(PlannedModule module, Function function) {
        this.module = module;
        this.function = function;
        this.name = RsamlLabels.name(function);
    }

    public PlannedModule module() {
        return module;
    }

    public Function function() {
        return function;
    }

    public String name() {
        return name;
    }

    public String description() {
        return function.getDescription();
    }

    public List<PlannedAction> actions() {
        return Collections.unmodifiableList(actions);
    }

    /** Whether the function is released every {@link #periodNs()}. */
    public boolean timed() {
        return timed;
    }

    public long periodNs() {
        return periodNs;
    }

    /** For a sporadic function run by reactions, the minimum time between two runs (0: none). */
    public long minIntervalNs() {
        return minIntervalNs;
    }

    /** The actions this function runs itself, in order (the others are released on their own). */
    public List<PlannedAction> inlineActions() {
        return actions.stream().filter(a -> !a.standalone).toList();
    }

    /** {@code layer/module.function}. */
    public String label() {
        return module.qualifiedName + "." + name;
    }

    public String timing() {
        return RsamlLabels.timing(function);
    }
}
