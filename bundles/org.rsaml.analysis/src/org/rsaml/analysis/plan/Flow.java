/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import org.rsaml.model.Connection;

public final class Flow {
    final Connection connection;
    final PlannedPort source;
    final PlannedPort target;

    Flow(Connection connection, PlannedPort source, PlannedPort target) {
        this.connection = connection;
        this.source = source;
        this.target = target;
    }

    public Connection connection() {
        return connection;
    }

    public PlannedPort source() {
        return source;
    }

    public PlannedPort target() {
        return target;
    }
}
