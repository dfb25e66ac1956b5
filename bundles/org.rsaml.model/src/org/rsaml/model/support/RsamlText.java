/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

/**
 * The one reading of names and message types that the rules and the generators share: surrounding
 * white space is not part of the text, and text that is blank is missing. And the one way model text
 * is put into the XML RsaML writes (SVG, package manifests).
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

    /**
     * Text as XML content or an attribute value (either quote): markup characters escaped, and what XML 1.0 cannot
     * carry at all (control characters other than tab and line ends, U+FFFE, U+FFFF, a lone surrogate) replaced by a
     * space, so a model's names can never break or forge the document.
     */
    public static String xml(String text) {
        if (text == null) {
            return "";
        }
        StringBuilder out = new StringBuilder(text.length() + 16);
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                case '\'' -> out.append("&#39;");
                default -> {
                    if (Character.isHighSurrogate(c) && i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1))) {
                        out.append(c).append(text.charAt(++i));
                    } else if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0xFFFE || c == 0xFFFF
                            || Character.isSurrogate(c)) {
                        out.append(' ');
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        return out.toString();
    }
}
