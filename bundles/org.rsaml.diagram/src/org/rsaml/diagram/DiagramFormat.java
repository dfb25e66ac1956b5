/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

import java.util.Locale;

import org.rsaml.model.support.Choices;

/** How a diagram is written. */
public enum DiagramFormat {
    /** A standalone SVG image. */
    SVG,
    /** One self-contained HTML page: the diagram, pan and zoom, the findings and the validation summary. */
    HTML;

    /** The name used on the command line, also the file extension. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @throws IllegalArgumentException naming the accepted values */
    public static DiagramFormat parse(String value) {
        return Choices.parse(values(), DiagramFormat::id, "format", value);
    }
}
