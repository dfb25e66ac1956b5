/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.spi;

import java.util.List;

/**
 * What a target renders from a plan.
 *
 * @param files    every file of the project, regenerated and the architect's
 * @param warnings what the target cannot do as modeled (beyond the plan's own warnings)
 */
public record GeneratedProject(List<GeneratedFile> files, List<String> warnings) {
    public GeneratedProject {
        files = List.copyOf(files);
        warnings = List.copyOf(warnings);
    }
}
