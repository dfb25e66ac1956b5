/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

/**
 * The one reading of names and message types that the rules and the generators share: surrounding
 * white space is not part of the text, and text that is blank is missing.
 */
public final class RsamlText {

    private RsamlText() {
    }

    /** The text without surrounding white space, or {@code null} when it is missing or blank. */
    public static String normalized(String text) {
        if (text == null) {
            return null;
        }
        String stripped = text.strip();
        return stripped.isEmpty() ? null : stripped;
    }

    /** Whether the text is missing or blank. */
    public static boolean isMissing(String text) {
        return normalized(text) == null;
    }
}
