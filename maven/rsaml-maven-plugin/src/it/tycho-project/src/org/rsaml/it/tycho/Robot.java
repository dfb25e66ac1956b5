/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.it.tycho;

/** Stands for the code that implements the modeled architecture. */
public final class Robot {
    private Robot() {
    }
}
