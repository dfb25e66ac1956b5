/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.util.List;

import org.rsaml.validation.ModelLoadException;

/**
 * Makes text from a model (names, descriptions, file names) safe to print where people and CI
 * runners read lines: a terminal, a build log. A model must not be able to forge a finding with a
 * newline, recolour or rewrite a terminal with an escape sequence, or give a CI runner a workflow
 * command ({@code ::error file=...::}, {@code ##vso[...]}).
 */
public final class Text {

    private Text() {
    }

    /**
     * One printable line: control characters (C0, DEL, C1), line and paragraph separators and the
     * bidirectional overrides become visible escapes such as {@code \n} or {@code \x1b};
     * a workflow command at the start of the line, or Azure's {@code ##vso[} anywhere,
     * loses its first character to an escape. Everything else is kept as it was.
     */
    public static String line(String text) {
        if (text == null) {
            return "null";
        }
        StringBuilder s = new StringBuilder(text.length() + 8);
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '\n' -> s.append("\\n");
                case '\r' -> s.append("\\r");
                case '\t' -> s.append("\\t");
                default -> {
                    if (unsafe(c)) {
                        s.append(c <= 0xff ? String.format("\\x%02x", (int) c) : String.format("\\u%04x", (int) c));
                    } else {
                        s.append(c);
                    }
                }
            }
        }
        String escaped = s.toString();
        int start = 0;
        while (start < escaped.length() && escaped.charAt(start) == ' ') {
            start++;
        }
        if (escaped.startsWith("::", start)) {
            escaped = escaped.substring(0, start) + "\\x3a" + escaped.substring(start + 1);
        }
        if (escaped.contains("##")) {
            escaped = escaped.replace("##vso[", "\\x23#vso[").replace("##[", "\\x23#[");
        }
        return escaped;
    }

    /** Every problem of an input that cannot be read, compiler style, one safe {@link #line} each. */
    public static List<String> lines(ModelLoadException error) {
        return error.problems().stream().map(p -> line(p.toString())).toList();
    }

    /** Whether a character must not reach a terminal or log as it is. */
    static boolean unsafe(char c) {
        return c < 0x20 || (c >= 0x7f && c <= 0x9f) // C0, DEL, C1 (NEL among them)
                || c == '\u2028' || c == '\u2029' // line and paragraph separators
                || (c >= '\u202a' && c <= '\u202e') || (c >= '\u2066' && c <= '\u2069') // bidi overrides
                || c == '\ufeff'; // zero-width no-break space
    }
}
