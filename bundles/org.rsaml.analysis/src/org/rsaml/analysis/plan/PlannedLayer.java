/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.rsaml.model.Layer;
import org.rsaml.model.support.RsamlLabels;

public final class PlannedLayer {
    final Layer layer;
    final String name;
    final List<PlannedModule> modules = new ArrayList<>();

    PlannedLayer(Layer layer) {
        this.layer = layer;
        this.name = RsamlLabels.name(layer);
    }

    public Layer layer() {
        return layer;
    }

    public String name() {
        return name;
    }

    /** Its modules in model order. */
    public List<PlannedModule> modules() {
        return Collections.unmodifiableList(modules);
    }
}
