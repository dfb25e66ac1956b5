/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
/** What a code generation target implements: {@link org.rsaml.generator.spi.TargetGenerator}. */
package org.rsaml.generator.spi;
