/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

/** The process exit codes of {@code rsaml}, as CI pipelines see them. */
public final class ExitCodes {
    /** Every input was read and nothing reached the failure threshold. */
    public static final int OK = 0;
    /** At least one finding at or above {@code --fail-on}. */
    public static final int FINDINGS = 1;
    /** A usage error, or an input that could not be read. */
    public static final int INPUT_ERROR = 2;

    private ExitCodes() {
    }
}
