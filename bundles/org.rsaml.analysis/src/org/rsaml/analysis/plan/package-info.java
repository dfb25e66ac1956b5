/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
/**
 * The target-neutral execution plan of an architecture ({@link org.rsaml.analysis.plan.ExecutionPlan}):
 * releases, reactions, flows and links, as every code generator renders them and as a timing
 * analysis can read them.
 */
package org.rsaml.analysis.plan;
