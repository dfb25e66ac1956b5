/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

/**
 * A utilisation bound applied to the processor.
 *
 * @param name        e.g. "Liu & Layland"
 * @param sufficient  true for a sufficient test (passing proves schedulability, failing proves
 *                    nothing), false for a necessary one (failing proves a miss, passing proves nothing)
 * @param limit       the bound in prose (e.g. "U <= 0.7798")
 * @param applicable  false when the bound's assumptions do not hold for this task set
 * @param holds       whether the task set satisfies the bound (meaningless when not applicable)
 * @param note        why it is not applicable, or how it was computed
 */
public record BoundCheck(String name, boolean sufficient, String limit, boolean applicable, boolean holds, String note) {
}
