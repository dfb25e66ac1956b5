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
 * Reads the architect's kept parameters file for times the model no longer gives a node (a
 * function renamed, a unit changed): the launch files refuse such a file (Ros2LaunchTemplate), so
 * generating again says so at once, naming the line. Only the file's usual form is recognised (a
 * node's section at the start of a line, each time on a line of its own); the launch files check
 * every form.
 */
final class Ros2ParamsCheck {

    private static final Pattern SECTION = Pattern.compile("/?([A-Za-z_][\\w/]*)\\s*:\\s*(#.*)?");
    private static final Pattern TIME = Pattern.compile("\\s+([\\w.]+\\.(?:period|min_interval|duration)_(?:ns|us|ms|s))\\s*:.*");

    private Ros2ParamsCheck() {
    }

    /**
     * One warning per line of {@code text} (the file at {@code path}) setting a time that its node,
     * one of {@code times}' keys, does not declare.
     */
    static List<String> staleTimes(String path, String text, Map<String, List<String>> times) {
        List<String> warnings = new ArrayList<>();
        String node = null;
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            Matcher section = SECTION.matcher(lines[i]);
            if (section.matches()) {
                node = section.group(1);
                continue;
            }
            Matcher time = TIME.matcher(lines[i]);
            if (node != null && times.containsKey(node) && time.matches() && !times.get(node).contains(time.group(1))) {
                warnings.add(path + ":" + (i + 1) + ": node '" + node + "' has no parameter " + time.group(1) + " since the model changed (its times: "
                        + (times.get(node).isEmpty() ? "none" : String.join(", ", times.get(node)))
                        + "); the launch files refuse the file until you rename or remove the line");
            }
        }
        return warnings;
    }
}
