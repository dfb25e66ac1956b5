/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

import java.util.List;
import java.util.Map;
import java.util.Set;

import org.rsaml.model.Architecture;

/**
 * Extra information drawn over a diagram, such as the results of a timing analysis: notes written
 * into elements (a processor's utilisation) and elements drawn emphasised (a latency path).
 * Elements are named by their qualified name ({@code RsamlLabels.qualifiedName}).
 */
public interface DiagramOverlay {

    /** The notes of this overlay for an architecture. */
    Notes notes(Architecture architecture);

    /**
     * @param lines      text lines per element, drawn inside it below its own text
     * @param emphasised elements drawn with a heavier stroke
     */
    record Notes(Map<String, List<String>> lines, Set<String> emphasised) {
        public static final Notes NONE = new Notes(Map.of(), Set.of());
    }
}
