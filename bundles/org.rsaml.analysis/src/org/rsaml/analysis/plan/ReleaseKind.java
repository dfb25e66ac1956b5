/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

public enum ReleaseKind {
    /** A periodic function and its inline actions. */
    FUNCTION,
    /** A periodic action released on its own. */
    ACTION,
    /** A periodic module's step functions. */
    MODULE
}
