/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

/** The outcome of an analysis: never a silent pass, so what was not analysed says so. */
public enum Verdict {
    /** Proven: every deadline (or requirement) is met in the worst case. */
    MEETS,
    /** A deadline (or requirement) can be missed; the result carries a witness. */
    MISSES,
    /** No sound verdict; the result says why. */
    NOT_ANALYSED;

    /** The worse of two verdicts: a miss outweighs an unknown, which outweighs a pass. */
    public Verdict and(Verdict other) {
        if (this == MISSES || other == MISSES) {
            return MISSES;
        }
        return this == NOT_ANALYSED || other == NOT_ANALYSED ? NOT_ANALYSED : MEETS;
    }
}
