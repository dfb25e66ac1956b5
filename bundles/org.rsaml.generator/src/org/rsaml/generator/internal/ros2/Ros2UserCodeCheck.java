/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads the architect's kept node classes (src/LAYER/Module.hpp and .cpp) for code written when an
 * entry port's {@code in_<port>} held the message by value: it is a {@code ConstSharedPtr} now (the
 * message shared, not copied; null until the first arrives), so {@code in_scan.ranges} no longer
 * compiles. Generating again names each such line and says how to write it, before the compiler
 * does in the architect's file. Comments and string literals are skipped.
 */
final class Ros2UserCodeCheck {

    private static final Pattern COMMENT_OR_STRING = Pattern.compile("//[^\\n]*|/\\*.*?\\*/|\"(?:[^\"\\\\\\n]|\\\\.)*\"|'(?:[^'\\\\\\n]|\\\\.)*'",
            Pattern.DOTALL);

    private Ros2UserCodeCheck() {
    }

    /**
     * One warning per line of {@code text} (the file at {@code path}) that reads a member of an
     * entry port's {@code in_<port>} as a value; {@code inputs}: each entry port's {@code in_} member
     * by its {@code on_} handler.
     */
    static List<String> valueReads(String path, String text, Map<String, String> inputs) {
        List<String> warnings = new ArrayList<>();
        if (inputs.isEmpty()) {
            return warnings;
        }
        // comments and literals blanked, newlines kept, so that lines still count
        StringBuilder code = new StringBuilder(text);
        Matcher skip = COMMENT_OR_STRING.matcher(text);
        while (skip.find()) {
            for (int i = skip.start(); i < skip.end(); i++) {
                if (text.charAt(i) != '\n') {
                    code.setCharAt(i, ' ');
                }
            }
        }
        String[] lines = code.toString().split("\n", -1);
        for (Map.Entry<String, String> in : inputs.entrySet()) {
            Pattern read = Pattern.compile("(?<![\\w.])" + Pattern.quote(in.getKey()) + "\\s*\\.\\s*(?!(?:get|reset|use_count|swap|owner_before)\\b)([A-Za-z_]\\w*)");
            for (int i = 0; i < lines.length; i++) {
                Matcher m = read.matcher(lines[i]);
                if (m.find()) {
                    warnings.add(path + ":" + (i + 1) + ": " + in.getKey() + "." + m.group(1) + ": " + in.getKey()
                            + " is the latest message by shared pointer (a ConstSharedPtr, null until the first arrives), no longer a copy:"
                            + " write " + in.getKey() + "->" + m.group(1) + " after checking if (" + in.getKey() + "), or take each message in "
                            + in.getValue() + "; as written it does not compile");
                }
            }
        }
        return warnings;
    }
}
