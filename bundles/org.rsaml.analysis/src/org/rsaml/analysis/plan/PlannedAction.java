/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import org.rsaml.model.Action;
import org.rsaml.model.support.RsamlLabels;

public final class PlannedAction {
    final PlannedFunction function;
    final Action action;
    final String name;
    boolean standalone;
    long periodNs;
    long startNs;
    long offsetNs;
    long deadlineNs;
    long costNs;

    PlannedAction(PlannedFunction function, Action action) {
        this.function = function;
        this.action = action;
        this.name = RsamlLabels.name(action);
    }

    public PlannedFunction function() {
        return function;
    }

    public Action action() {
        return action;
    }

    public String name() {
        return name;
    }

    public String description() {
        return action.getDescription();
    }

    /** Whether it is released on its own rather than run by its function. */
    public boolean standalone() {
        return standalone;
    }

    /** Delay after its function's release before it runs (actions of timed functions only). */
    public long offsetNs() {
        return offsetNs;
    }

    /** {@code layer/module.function.action}. */
    public String label() {
        return function.label() + "." + name;
    }

    public String timing() {
        return RsamlLabels.timing(action);
    }
}
