/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.docgen;

import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.codegen.RsamlCodegen;
import org.rsaml.validation.RsamlValidationSetup.RuleDefinitionException;
import org.rsaml.validation.Rule;
import org.rsaml.validation.internal.RuleCatalog;

/**
 * The rule table of {@code docs/rules.md}, produced from the rule catalogue: every column of every
 * rule, between two marker lines. {@link RsamlDocgen} writes it when the generated files are regenerated
 * ({@link RsamlCodegen#REGENERATE}); the tests only compare. A build-time writer: it is in no bundle a
 * user installs.
 */
public final class RulesDocument {

    /** The rule catalogue, relative to the repository root. */
    public static final String CATALOGUE = RuleCatalog.SOURCE_FILE;

    /** The page that holds the table, relative to the repository root. */
    public static final String PATH = "docs/rules.md";

    /** The line before the table. */
    public static final String BEGIN = "<!-- rules: produced from " + CATALOGUE + " by " + RsamlCodegen.REGENERATE + " -->";

    /** The line after the table. */
    public static final String END = "<!-- end of rules -->";

    private RulesDocument() {
    }

    /** The catalogue's table, as the page shows it. */
    public static String table(List<Rule> rules) {
        StringBuilder out = new StringBuilder();
        out.append("| id | name | severity | context | rule | scope | fix |\n");
        out.append("|---|---|---|---|---|---|---|\n");
        for (Rule rule : rules) {
            out.append("| ").append(rule.id()).append(" | ").append(rule.name()).append(" | ").append(rule.severity().label())
                    .append(" | ").append(cell(rule.context())).append(" | ").append(cell(rule.description())).append(" | ")
                    .append(cell(rule.scope())).append(" | ").append(cell(rule.remediation())).append(" |\n");
        }
        return out.toString();
    }

    /**
     * The page with its table replaced by the catalogue's; throws {@link IllegalArgumentException} naming
     * the markers when the page has no table between them.
     */
    public static String update(String page, List<Rule> rules) {
        int begin = page.indexOf(BEGIN);
        int end = page.indexOf(END);
        if (begin < 0 || end < begin) {
            throw new IllegalArgumentException(PATH + " has no rule table between the lines " + BEGIN + " and " + END);
        }
        return page.substring(0, begin + BEGIN.length()) + "\n" + table(rules) + page.substring(end);
    }

    /**
     * Reads a catalogue file with the parser RsaML starts with, for tools that work on a clone;
     * throws {@link RuleDefinitionException} listing what is incomplete.
     */
    public static List<Rule> read(Reader catalogue) throws IOException {
        List<String> problems = new ArrayList<>();
        List<Rule> rules = RuleCatalog.parse(catalogue, problems);
        if (!problems.isEmpty()) {
            throw new RuleDefinitionException(problems);
        }
        return rules;
    }

    private static String cell(String text) {
        return text.replace("|", "\\|");
    }
}
