/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.rsaml.model.Architecture;

/**
 * Extra information drawn over a diagram, such as the results of a timing analysis: notes written
 * into elements (a task's response time), classes that style elements (a latency path) and items
 * listed beside the diagram in the HTML page (a processor's utilisation). Elements are named by their
 * qualified name ({@code RsamlLabels.qualifiedName}); a reference drawn without a model element of its
 * own (a sensor's line to a module that reads it) by {@code source -> target}.
 */
public interface DiagramOverlay {

    /** The notes of this overlay for an architecture. */
    Notes notes(Architecture architecture);

    /**
     * A line of text.
     *
     * @param text  what is written
     * @param style how it looks: {@code overlay} (plain), {@code overlay-meets}, {@code overlay-misses} or
     *              {@code overlay-unknown} (a verdict's colour)
     */
    record Line(String text, String style) {
        public static Line plain(String text) {
            return new Line(text, "overlay");
        }
    }

    /**
     * Something the overlay says, listed beside the diagram in the HTML page; clicking it highlights
     * the elements it concerns and zooms to them.
     *
     * @param section  the heading it is listed under (e.g. "Timing")
     * @param line     its text and style
     * @param details  further lines shown under it (e.g. a latency path's hops)
     * @param elements the qualified names of the elements it concerns, possibly none
     */
    record Item(String section, Line line, List<String> details, List<String> elements) {
        public Item {
            details = List.copyOf(details);
            elements = List.copyOf(elements);
        }
    }

    /**
     * @param lines   text lines per element, drawn inside it below its own text
     * @param classes extra classes per element (styled by the diagram's CSS: {@code emphasis},
     *                {@code latency-path}, {@code latency-misses}, ...)
     * @param data    {@code data-} attributes per element (name without the prefix, value)
     * @param items   what is listed beside the diagram in the HTML page
     */
    record Notes(Map<String, List<Line>> lines, Map<String, Set<String>> classes, Map<String, Map<String, String>> data,
            List<Item> items) {

        public static final Notes NONE = new Notes(Map.of(), Map.of(), Map.of(), List.of());

        public Notes {
            lines = Map.copyOf(lines);
            classes = Map.copyOf(classes);
            data = Map.copyOf(data);
            items = List.copyOf(items);
        }

        /** Plain lines per element, and elements drawn with a heavier stroke ({@code emphasis}). */
        public static Notes of(Map<String, List<String>> lines, Set<String> emphasised) {
            Map<String, List<Line>> styled = new HashMap<>();
            lines.forEach((k, v) -> styled.put(k, v.stream().map(Line::plain).toList()));
            Map<String, Set<String>> classes = new HashMap<>();
            for (String e : emphasised) {
                classes.put(e, Set.of("emphasis"));
            }
            return new Notes(styled, classes, Map.of(), List.of());
        }
    }
}
