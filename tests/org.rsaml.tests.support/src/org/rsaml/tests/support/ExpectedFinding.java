/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.tests.support;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A finding a model states it must give, in a comment of the model itself, so that every test reads
 * the expectation from one place (the validation, command-line, builder, design and install tests):
 * {@code <!-- expect: RSA-11 warning robot/functional/odometry -->},
 * or located and worded, {@code <!-- expect: RSA-08 error robot/control/checker at 50:5: Module 'checker' takes ... -->}.
 *
 * @param line    1-based, or 0 when the comment does not say
 * @param column  1-based, or 0 when the comment does not say
 * @param message the finding's message, or {@code null} when the comment does not say
 */
public record ExpectedFinding(String ruleId, String severity, String qualifiedName, int line, int column, String message) {

    private static final Pattern EXPECT = Pattern.compile(
            "<!-- expect: (RSA-\\d\\d) (error|warning|info) (.+?)(?: at (\\d+):(\\d+): (.+?))? -->");

    /** The expectations of the model, in the order it states them. */
    public static List<ExpectedFinding> of(Path model) throws IOException {
        List<ExpectedFinding> expected = new ArrayList<>();
        Matcher m = EXPECT.matcher(Files.readString(model));
        while (m.find()) {
            boolean located = m.group(4) != null;
            expected.add(new ExpectedFinding(m.group(1), m.group(2), m.group(3), located ? Integer.parseInt(m.group(4)) : 0,
                    located ? Integer.parseInt(m.group(5)) : 0, m.group(6)));
        }
        return expected;
    }

    /**
     * The one expectation the model states for the element {@code qualifiedName}.
     *
     * @throws IllegalArgumentException when the model states none or several for it, naming the model
     */
    public static ExpectedFinding on(Path model, String qualifiedName) throws IOException {
        List<ExpectedFinding> found = of(model).stream().filter(e -> e.qualifiedName.equals(qualifiedName)).toList();
        if (found.size() != 1) {
            throw new IllegalArgumentException(model + " states " + found.size() + " expectations for " + qualifiedName
                    + " in its <!-- expect: --> comments; a test asking for one needs exactly one");
        }
        return found.get(0);
    }

    /** The finding as EMF's diagnostics and the editor word it: {@code RSA-08: Module 'checker' takes ...}. */
    public String diagnosticMessage() {
        if (message == null) {
            throw new IllegalStateException(what() + ": the model's expect comment does not state the message");
        }
        return ruleId + ": " + message;
    }

    /** Rule, severity and element, as in {@code RSA-11 warning robot/functional/odometry}: what is found, and where in the model. */
    public String what() {
        return ruleId + " " + severity + " " + qualifiedName;
    }
}
