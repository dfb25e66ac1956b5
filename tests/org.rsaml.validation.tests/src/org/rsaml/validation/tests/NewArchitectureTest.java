/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.rsaml.model.Architecture;
import org.rsaml.model.support.ArchitectureSkeleton;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;

/** The architecture the new-model wizard creates: three layers with budgets, and not a single finding. */
class NewArchitectureTest {

    @Test
    void newArchitectureHasThreeBudgetedLayersAndNoFinding() {
        Architecture architecture = ArchitectureSkeleton.create("rover");

        assertEquals("rover", architecture.getName(), "the new architecture has the name the user typed");
        assertEquals(List.of("deliberative level 2 100.0 ms", "executive level 1 10.0 ms", "functional level 0 1.0 ms"),
                architecture.getLayers().stream()
                        .map(l -> l.getName() + " level " + l.getLevel() + " " + l.getMaxExecTime() + " " + l.getTimeUnit())
                        .collect(Collectors.toList()), "the new architecture has three layers, each with its level and budget");
        assertEquals(3, architecture.getDeclaredLayers(), "the new architecture declares the three layers it has");
        assertEquals(List.of(), RsamlModelValidator.validate(architecture).stream().map(Finding::toString)
                .collect(Collectors.toList()), "a new architecture has no finding");
    }
}
