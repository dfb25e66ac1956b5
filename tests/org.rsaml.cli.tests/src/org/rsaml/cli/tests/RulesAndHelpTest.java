/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

import com.google.gson.JsonArray;
import com.google.gson.JsonParser;

/** {@code rsaml rules}, {@code --version} and {@code --help}. */
class RulesAndHelpTest {

    @Test
    void rulesListsEveryRuleWithSeverityAndDescription() {
        Cli.Result r = Cli.run("rules");
        assertEquals(0, r.code(), r::toString);
        List<String> lines = r.outLines();
        assertEquals(Rules.all().size(), lines.size(), () -> "one line per rule of the catalogue:\n" + r);
        for (int i = 0; i < lines.size(); i++) {
            Rule rule = Rules.all().get(i);
            String line = lines.get(i);
            assertTrue(line.matches(Pattern.quote(rule.id()) + " +" + rule.severity().label() + " +" + Pattern.quote(rule.name()) + " +\\S.*"),
                    () -> "the catalogue's " + rule.id() + " listed in its place with its severity, name and description: " + line);
        }

        Cli.Result verbose = Cli.run("rules", "--verbose");
        for (Rule rule : Rules.all()) {
            assertTrue(verbose.out().contains("scope: " + rule.scope() + "\n"), () -> rule.id() + "'s scope missing:\n" + verbose.out());
            assertTrue(verbose.out().contains("fix: " + rule.remediation() + "\n"), () -> rule.id() + "'s fix missing");
        }
    }

    @Test
    void rulesAsJson() {
        Cli.Result r = Cli.run("rules", "--format", "json");
        assertEquals(0, r.code(), r::toString);
        JsonArray rules = JsonParser.parseString(r.out()).getAsJsonArray();
        assertEquals(Rules.all().size(), rules.size(), "one JSON object per rule of the catalogue");
        for (int i = 0; i < rules.size(); i++) {
            Rule rule = Rules.all().get(i);
            assertEquals(rule.id(), rules.get(i).getAsJsonObject().get("id").getAsString(), "the catalogue's order");
            assertEquals(rule.severity().label(), rules.get(i).getAsJsonObject().get("severity").getAsString(), rule.id() + "'s severity");
            assertEquals(rule.remediation(), rules.get(i).getAsJsonObject().get("help").getAsString(), rule.id() + "'s help is its fix");
            assertEquals(rule.scope(), rules.get(i).getAsJsonObject().get("scope").getAsString(), rule.id() + "'s scope");
        }
    }

    @Test
    void versionIsTheBuiltOne() {
        Cli.Result r = Cli.run("--version");
        assertEquals(0, r.code(), r::toString);
        assertEquals("rsaml " + System.getProperty("rsaml.version"), r.outLines().get(0), "the version of the build that made the jar");
    }

    @Test
    void helpOnEveryCommand() {
        Cli.Result top = Cli.run("--help");
        assertEquals(0, top.code(), top::toString);
        for (String expected : List.of("Usage: rsaml", "validate", "generate", "rules", "--version", "Exit codes:", "2   usage error")) {
            assertTrue(top.out().contains(expected), () -> expected + " missing:\n" + top.out());
        }
        Cli.Result validate = Cli.run("validate", "--help");
        assertEquals(0, validate.code(), validate::toString);
        for (String expected : List.of("Usage: rsaml validate", "--format", "--output", "--fail-on", "--quiet", "--debug")) {
            assertTrue(validate.out().contains(expected), () -> expected + " missing:\n" + validate.out());
        }
        assertEquals(validate.out(), Cli.run("help", "validate").out(), "'rsaml help validate' prints what 'validate --help' does");
        Cli.Result rules = Cli.run("rules", "--help");
        assertEquals(0, rules.code(), rules::toString);
        assertTrue(rules.out().contains("Usage: rsaml rules"), rules::toString);
    }
}
