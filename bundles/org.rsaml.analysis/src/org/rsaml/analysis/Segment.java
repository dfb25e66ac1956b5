/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

/**
 * The processor running job {@code job} (0 is the first) of task {@code task} from {@code start} to
 * {@code end} (nanoseconds from the critical instant).
 */
public record Segment(String task, long job, long start, long end) {
}
