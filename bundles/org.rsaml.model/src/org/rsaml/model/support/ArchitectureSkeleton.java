/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.Layer;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.TimeUnit;

/**
 * The architecture a new RsaML model starts from: a hybrid architecture with the classic three
 * layers (functional, executive, deliberative) and a budget per layer, so that the architect
 * begins from a model that already satisfies every rule and only has to add modules.
 */
public final class ArchitectureSkeleton {

    private ArchitectureSkeleton() {
    }

    /** A new architecture called {@code name}, with its three layers at levels 0 to 2. */
    public static Architecture create(String name) {
        RsamlFactory factory = RsamlFactory.eINSTANCE;
        Architecture architecture = factory.createArchitecture();
        architecture.setName(name);
        architecture.setCategory(ArchitectureCategory.HYBRID);
        architecture.setDescription("A hybrid architecture: deliberation on top of an executive layer that"
                + " sequences and supervises the functional modules.");
        // Listed from the top, as an architect draws them; levels count from the hardware up.
        architecture.getLayers().add(layer(factory, "deliberative", 2, 100.0,
                "Plans and decides: mission and task planning, world model, reasoning."));
        architecture.getLayers().add(layer(factory, "executive", 1, 10.0,
                "Sequences and supervises: turns plans into activities, monitors their execution."));
        architecture.getLayers().add(layer(factory, "functional", 0, 1.0,
                "Acts and perceives: sensor processing, control loops and actuator drivers."));
        architecture.setDeclaredLayers(architecture.getLayers().size());
        return architecture;
    }

    private static Layer layer(RsamlFactory factory, String name, int level, double maxExecTime, String description) {
        Layer layer = factory.createLayer();
        layer.setName(name);
        layer.setLevel(level);
        layer.setMaxExecTime(maxExecTime);
        layer.setTimeUnit(TimeUnit.MS);
        layer.setDescription(description);
        return layer;
    }
}
