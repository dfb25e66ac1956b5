/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.util.List;

import org.rsaml.validation.Finding;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Severity;

/**
 * The outcome of checking a set of inputs, in the order they were named: what every report format
 * renders and what decides the exit code.
 *
 * @param rules   the rules the check applies (SARIF lists them, JUnit has a test per rule and file)
 * @param results one entry per model file, and one per input that could not be read
 * @param failOn  the lowest severity that fails the run, or {@code null} when findings never fail it
 */
public record Report(List<Rule> rules, List<FileResult> results, Severity failOn) {

    public Report {
        rules = List.copyOf(rules);
        results = List.copyOf(results);
    }

    public long count(Severity severity) {
        return results.stream().mapToLong(r -> r.count(severity)).sum();
    }

    public long unreadable() {
        return results.stream().filter(r -> !r.readable()).count();
    }

    /** The model files that were read and checked. */
    public long files() {
        return results.size() - unreadable();
    }

    /** Whether a finding is serious enough to fail the run. */
    public boolean fails(Finding finding) {
        return failOn != null && finding.severity().atLeast(failOn);
    }

    public boolean hasFailingFindings() {
        return results.stream().flatMap(r -> r.findings().stream()).anyMatch(this::fails);
    }

    /** 0 clean, 1 findings at or above the threshold, 2 an input could not be read. */
    public int exitCode() {
        if (unreadable() > 0) {
            return ExitCodes.INPUT_ERROR;
        }
        return hasFailingFindings() ? ExitCodes.FINDINGS : ExitCodes.OK;
    }

    /**
     * Why the run fails, in the words of {@link #exitCode()}'s decision, as a build says it after the findings
     * ({@code could not read 1 model file; see the errors above}, {@code validation failed: 2 files checked: 1 error,
     * 0 warnings (fail on error)}), or {@code null} when it passes.
     */
    public String failure() {
        return switch (exitCode()) {
            case ExitCodes.INPUT_ERROR -> "could not read " + plural(unreadable(), "model file") + "; see the errors above";
            case ExitCodes.FINDINGS -> "validation failed: " + summary() + failingOn(failOn.label());
            default -> null;
        };
    }

    /** How a failure names the level that decided it, for every check alike: {@code  (fail on error)}. */
    static String failingOn(String level) {
        return " (fail on " + level + ")";
    }

    /** One line: {@code 3 files checked: 5 errors, 1 warning; 1 file could not be read}. */
    public String summary() {
        StringBuilder s = new StringBuilder();
        s.append(plural(files(), "file")).append(" checked: ")
                .append(plural(count(Severity.ERROR), "error")).append(", ")
                .append(plural(count(Severity.WARNING), "warning"));
        long infos = count(Severity.INFO);
        if (infos > 0) {
            s.append(", ").append(plural(infos, "info"));
        }
        long unreadable = unreadable();
        if (unreadable > 0) {
            s.append("; ").append(plural(unreadable, "input")).append(" could not be read");
        }
        return s.toString();
    }

    /**
     * The {@link #summary()} of a report also written as files into {@code reportsShown} (as the user reads the
     * directory; {@code null} when none were written): {@code 3 files checked: 5 errors, 1 warning; reports in target/rsaml}.
     */
    public String summary(String reportsShown) {
        return summary() + (reportsShown == null ? "" : "; reports in " + reportsShown);
    }

    private static String plural(long n, String word) {
        return n + " " + word + (n == 1 ? "" : "s");
    }
}
