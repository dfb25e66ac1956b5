/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import org.rsaml.model.support.RsamlNames;

/**
 * The names taken in one scope (a namespace, a class, a folder), handed out in model order: RsaML's one
 * rule, {@link RsamlNames.Scope}, which also names the default ROS 2 topics that the rule RSA-28 checks.
 */
public final class NameScope extends RsamlNames.Scope {

    public NameScope(boolean ignoreCase, String... reserved) {
        super(ignoreCase, reserved);
    }
}
