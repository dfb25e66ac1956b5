/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

/**
 * docs/rules.md's rule table is the catalogue's: every column of every rule, nothing else. When the
 * catalogue changes, run this test with {@code RSAML_UPDATE_DOCS=1} in the environment to rewrite the
 * table, e.g. {@code RSAML_UPDATE_DOCS=1 ./mvnw -o -pl tests/org.rsaml.validation.tests -am verify -Dtest=RulesDocumentTest}.
 */
class RulesDocumentTest {

    static final String BEGIN = "<!-- rules: produced from bundles/org.rsaml.model/model/rules.properties by RulesDocumentTest -->";
    static final String END = "<!-- end of rules -->";

    /** The table of the catalogue, as docs/rules.md shows it. */
    static String table() {
        StringBuilder out = new StringBuilder();
        out.append("| id | name | severity | context | rule | scope | fix |\n");
        out.append("|---|---|---|---|---|---|---|\n");
        for (Rule rule : Rules.all()) {
            out.append("| ").append(rule.id()).append(" | ").append(rule.name()).append(" | ").append(rule.severity().label())
                    .append(" | ").append(cell(rule.context())).append(" | ").append(cell(rule.description())).append(" | ")
                    .append(cell(rule.scope())).append(" | ").append(cell(rule.remediation())).append(" |\n");
        }
        return out.toString();
    }

    private static String cell(String text) {
        return text.replace("|", "\\|");
    }

    @Test
    void theRulesTableIsTheCatalogue() throws Exception {
        Path doc = TestRepository.root().resolve("docs/rules.md");
        String text = Files.readString(doc, StandardCharsets.UTF_8);
        int begin = text.indexOf(BEGIN);
        int end = text.indexOf(END);
        assertTrue(begin >= 0 && end > begin, "docs/rules.md has no rule table between " + BEGIN + " and " + END);
        String current = text.substring(begin + BEGIN.length() + 1, end);
        String expected = table();
        if (!expected.equals(current) && System.getenv("RSAML_UPDATE_DOCS") != null) {
            Files.writeString(doc, text.substring(0, begin + BEGIN.length() + 1) + expected + text.substring(end),
                    StandardCharsets.UTF_8);
            current = expected;
        }
        assertEquals(expected, current, "docs/rules.md's rule table differs from the catalogue; rerun with RSAML_UPDATE_DOCS=1");
    }
}
