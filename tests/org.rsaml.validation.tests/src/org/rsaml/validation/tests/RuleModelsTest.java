/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

/**
 * For every rule, a model that violates it and one that satisfies it. Each violating model states
 * its expected findings in comments: {@code <!-- expect: RSA-08 error robot/control/resourceChecker -->}.
 */
class RuleModelsTest {

    static Stream<String> models() throws Exception {
        try (Stream<Path> files = Files.list(TestRepository.resource("org.rsaml.validation.tests", "rules"))) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted()
                    .collect(Collectors.toList()).stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("models")
    void modelYieldsExactlyItsExpectedFindings(String name) throws Exception {
        Path file = TestRepository.resource("org.rsaml.validation.tests", "rules").resolve(name);
        List<String> expected = new ArrayList<>(ExpectedFinding.of(file).stream().map(ExpectedFinding::what).toList());
        if (name.contains("-violated")) {
            assertTrue(!expected.isEmpty(), name + " states no expected finding");
            String rule = name.substring(5, 11);
            assertTrue(expected.stream().allMatch(e -> e.startsWith(rule)), name + " expects findings of other rules");
        } else {
            assertEquals(List.of(), expected, name + " is a satisfied model and must expect nothing");
        }
        List<Finding> findings = RsamlModelValidator.validate(file);
        List<String> actual = findings.stream().map(f -> f.ruleId() + " " + f.severity().label() + " " + f.qualifiedName())
                .sorted().collect(Collectors.toList());
        expected.sort(null);
        assertEquals(expected, actual, () -> "findings of " + name + ":\n" + findings.stream().map(Finding::toString)
                .collect(Collectors.joining("\n")));
        for (Finding f : findings) {
            assertTrue(f.line() > 0, "finding without a line: " + f);
            assertEquals(f.rule().severity(), f.severity(), "a finding has its rule's severity in the catalogue: " + f);
        }
    }

    @Test
    void everyRuleHasAViolatingAndASatisfyingModel() throws Exception {
        TreeSet<String> names = models().collect(Collectors.toCollection(TreeSet::new));
        for (Rule rule : Rules.all()) {
            assertTrue(names.contains("rule-" + rule.id() + "-violated.rsaml"), "no violating model for " + rule.id());
            assertTrue(names.contains("rule-" + rule.id() + "-satisfied.rsaml"), "no satisfying model for " + rule.id());
        }
    }
}
