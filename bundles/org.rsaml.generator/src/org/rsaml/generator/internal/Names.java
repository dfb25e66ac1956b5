/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.util.List;
import java.util.Locale;
import java.util.Set;

import org.rsaml.model.support.RsamlNames;
import org.rsaml.model.support.RsamlPackages;
import org.rsaml.model.support.RsamlText;

/**
 * Turns model names, which may hold any text, into names that are safe as C++ and Python
 * identifiers, ROS names and file names: ASCII letters, digits and single underscores, never a
 * reserved word, never a path. Uniqueness is the job of {@link NameScope}.
 */
public final class Names {

    private Names() {
    }

    /**
     * The name as an identifier: every character outside {@code [A-Za-z0-9_]} (path separators,
     * dots, spaces, non-ASCII letters) becomes an underscore, runs of underscores collapse (C++
     * reserves {@code __}), leading and trailing underscores go (C++ reserves {@code _X}), a leading
     * digit gets an {@code n} before it, and a reserved word gets an underscore after it.
     */
    public static String identifier(String raw) {
        String s = collapse(raw);
        if (s.isEmpty()) {
            s = "unnamed";
        }
        if (Character.isDigit(s.charAt(0))) {
            s = "n" + s;
        }
        return reserved(s) ? s + "_" : s;
    }

    /**
     * As {@link #identifier(String)} but keeping reserved words: for names that only ever appear
     * after a prefix ({@code in_class}, {@code release_switch}), where they are safe, and where an
     * added underscore would make a reserved {@code __} in composed names.
     */
    public static String stem(String raw) {
        return RsamlNames.stem(raw);
    }

    /** {@code taskInterpreter} to {@code TaskInterpreter}: for class and message type names. */
    public static String pascal(String raw) {
        StringBuilder out = new StringBuilder();
        for (String word : words(raw)) {
            out.append(Character.toUpperCase(word.charAt(0))).append(word, 1, word.length());
        }
        String s = out.length() == 0 ? "Unnamed" : out.toString();
        if (Character.isDigit(s.charAt(0))) {
            s = "N" + s;
        }
        return reserved(s) ? s + "_" : s;
    }

    /** {@code eMoveSP} to {@code e_move_sp}: for ROS package, node, executable and topic names ({@link RsamlNames#snake}). */
    public static String snake(String raw) {
        return RsamlNames.snake(raw);
    }

    /** Whether a name may not be used as it is in generated code or as a file name ({@link RsamlNames#reserved}). */
    public static boolean reserved(String s) {
        return RsamlNames.reserved(s);
    }

    /**
     * The header name rosidl derives from a message type name: {@code Pose2D} to {@code pose2_d},
     * {@code MotionInstruction} to {@code motion_instruction} (rosidl's own two rules).
     */
    public static String rosidlHeaderStem(String typeName) {
        String s = typeName.replaceAll("(.)([A-Z][a-z]+)", "$1_$2");
        s = s.replaceAll("([a-z0-9])([A-Z])", "$1_$2");
        return s.toLowerCase(Locale.ROOT);
    }

    /**
     * The words of a name, split at underscores and other characters and at lower-to-upper case
     * changes: RsaML's one rule, {@link RsamlPackages#words(String)}, which also makes the package
     * names the ROS 2 rule RSA-29 checks.
     */
    public static List<String> words(String raw) {
        return RsamlPackages.words(raw);
    }

    private static String collapse(String raw) {
        return RsamlNames.collapse(raw);
    }

    /** A string literal for C++: printable ASCII as is, everything else as 3-digit octal escapes. */
    public static String cppString(String text) {
        StringBuilder out = new StringBuilder("\"");
        for (byte b : (text == null ? "" : text).getBytes(java.nio.charset.StandardCharsets.UTF_8)) {
            int c = b & 0xff;
            if (c == '"' || c == '\\') {
                out.append('\\').append((char) c);
            } else if (c >= 0x20 && c < 0x7f && c != '?') {
                out.append((char) c);
            } else {
                out.append('\\').append((char) ('0' + (c >> 6))).append((char) ('0' + ((c >> 3) & 7))).append((char) ('0' + (c & 7)));
            }
        }
        return out.append('"').toString();
    }

    /** A string literal for Python, single-quoted, non-ASCII and control characters escaped. */
    public static String pythonString(String text) {
        StringBuilder out = new StringBuilder("'");
        for (int i = 0; i < (text == null ? 0 : text.length()); i++) {
            char c = text.charAt(i);
            if (c == '\'' || c == '\\') {
                out.append('\\').append(c);
            } else if (c >= 0x20 && c < 0x7f) {
                out.append(c);
            } else {
                out.append(String.format("\\u%04x", (int) c));
            }
        }
        return out.append('\'').toString();
    }

    /** Text for XML content and attribute values. */
    public static String xml(String text) {
        return RsamlText.xml(text);
    }

    /**
     * Free text (a description) as the body of one-line comments: one line, no control characters,
     * no trailing backslash (which would continue a C++ line comment onto the next line), and no
     * comment terminators.
     */
    public static String comment(String text) {
        if (text == null) {
            return "";
        }
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            out.append(Character.isISOControl(c) ? ' ' : c);
        }
        String s = out.toString().replace("*/", "* /").replace("??", "? ?").strip();
        while (s.endsWith("\\")) {
            s = s.substring(0, s.length() - 1).strip();
        }
        return s;
    }
}
