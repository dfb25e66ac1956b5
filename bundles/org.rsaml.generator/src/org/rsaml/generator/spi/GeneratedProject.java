/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.spi;

import java.util.List;
import java.util.Map;

/**
 * What a target renders from a plan.
 *
 * @param files    every file of the project, regenerated and the architect's
 * @param warnings what the target cannot do as modeled (beyond the plan's own warnings)
 * @param keep     settings to remember in the output for the next run (names without blanks, such
 *                 as a namespace the architect's files depend on)
 */
public record GeneratedProject(List<GeneratedFile> files, List<String> warnings, Map<String, String> keep) {
    public GeneratedProject {
        files = List.copyOf(files);
        warnings = List.copyOf(warnings);
        keep = Map.copyOf(keep);
    }

    public GeneratedProject(List<GeneratedFile> files, List<String> warnings) {
        this(files, warnings, Map.of());
    }
}
