/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

public enum DataKind {
    NUMERIC, ALPHANUMERIC, BOOLEAN, STRUCTURED
}
