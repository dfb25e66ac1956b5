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
 * Reads the architect's kept node classes (src/LAYER/Module.hpp and .cpp) for code written when a
 * port's member held its message by value: an entry port's {@code in_<port>} is a
 * {@code ConstSharedPtr} now (the message shared, not copied; null until the first arrives), and an
 * output port's {@code out_<port>} a {@code std::unique_ptr} to the message the activation publishes
 * (handed over, not copied; a new one each activation), so {@code in_scan.ranges} and
 * {@code out_cmd.linear} no longer compile. Generating again names each such line and says how to
 * write it, before the compiler does in the architect's file. Comments and string literals are skipped.
 */
final class Ros2UserCodeCheck {

    private static final Pattern COMMENT_OR_STRING = Pattern.compile("//[^\\n]*|/\\*.*?\\*/|\"(?:[^\"\\\\\\n]|\\\\.)*\"|'(?:[^'\\\\\\n]|\\\\.)*'",
            Pattern.DOTALL);

    private Ros2UserCodeCheck() {
    }

    /**
     * One warning per line of {@code text} (the file at {@code path}) that uses a member of a port's
     * message as a value: {@code inputs}, each entry port's {@code in_} member by its {@code on_}
     * handler; {@code outputs}, each output port's {@code out_} member.
     */
    static List<String> valueReads(String path, String text, Map<String, String> inputs, List<String> outputs) {
        List<String> warnings = new ArrayList<>();
        if (inputs.isEmpty() && outputs.isEmpty()) {
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
            String name = in.getKey();
            forEachMemberUse(path, lines, name, "get|reset|use_count|swap|owner_before", warnings,
                    member -> name + " is the latest message by shared pointer (a ConstSharedPtr, null until the first arrives), no longer a copy:"
                            + " write " + name + "->" + member + " after checking if (" + name + "), or take each message in " + in.getValue());
        }
        for (String name : outputs) {
            forEachMemberUse(path, lines, name, "get|reset|release|swap", warnings,
                    member -> name + " is the message this activation publishes, by std::unique_ptr (handed to the middleware, not copied),"
                            + " no longer a value the port keeps: write " + name + "->" + member
                            + ", and set it in every activation (each one starts with a new, default message)");
        }
        return warnings;
    }

    /** Adds a warning for each line that uses {@code name.member} (not one of the pointer's own methods). */
    private static void forEachMemberUse(String path, String[] lines, String name, String pointerMethods, List<String> warnings,
            java.util.function.Function<String, String> advice) {
        Pattern use = Pattern.compile("(?<![\\w.])" + Pattern.quote(name) + "\\s*\\.\\s*(?!(?:" + pointerMethods + ")\\b)([A-Za-z_]\\w*)");
        for (int i = 0; i < lines.length; i++) {
            Matcher m = use.matcher(lines[i]);
            if (m.find()) {
                warnings.add(path + ":" + (i + 1) + ": " + name + "." + m.group(1) + ": " + advice.apply(m.group(1)) + "; as written it does not compile");
            }
        }
    }
}
