/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import org.rsaml.model.Module;
import org.rsaml.model.support.RsamlTimes;

/**
 * One stage of an end-to-end path and what it adds to the latency.
 *
 * @param label      {@code layer/module}
 * @param module     the module of the stage: names need not tell modules apart (a duplicate name is
 *                   an error, RSA-09, but such a model is still analysed and drawn)
 * @param activation how the stage picks the data up, in words
 * @param waitNs     the longest the data waits before the stage starts on it (sampling)
 * @param responseNs the stage's worst-case response time once started
 */
public record Hop(String label, Module module, String activation, long waitNs, long responseNs) {

    /** What the stage adds: wait plus response. */
    public long totalNs() {
        return waitNs + responseNs;
    }

    /**
     * What the stage adds, as the text report and the diagrams' timing overlay both word it:
     * {@code +44 ms (wait 40 ms + response 4 ms)}.
     */
    public String contribution() {
        return "+" + RsamlTimes.text(totalNs()) + " (wait " + RsamlTimes.text(waitNs) + " + response " + RsamlTimes.text(responseNs) + ")";
    }
}
