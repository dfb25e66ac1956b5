/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The paper's experiments: experiment 2 shows exactly its five defects (errors) and experiment 1's one timing warning, and every
 * example gives the findings it states.
 */
class PaperExperimentsTest {

    @Test
    void experimentTwoYieldsExactlyThePapersFiveFindings() throws Exception {
        Path file = TestRepository.example("exp2-defects.rsaml");
        List<Finding> findings = RsamlModelValidator.validate(file, "examples/exp2-defects.rsaml");
        List<ExpectedFinding> actual = findings.stream().map(f -> new ExpectedFinding(f.ruleId(), f.severity().label(),
                f.qualifiedName(), f.line(), f.column(), f.message())).collect(Collectors.toList());
        // The expected findings are written in the model itself, as in the rule fixtures.
        List<ExpectedFinding> expected = ExpectedFinding.of(file);
        assertEquals(List.of("RSA-01", "RSA-04", "RSA-08", "RSA-07", "RSA-02"), expected.stream().filter(e -> e.severity().equals("error"))
                .map(ExpectedFinding::ruleId).toList(), "exp2-defects.rsaml states the paper's five defects, as errors");
        // and, not a defect of the paper's, experiment 1's timing warning: m01's function waits for m01's aperiodic reaction
        assertEquals(List.of("RSA-24 warning hybridMobileRobotWithDefects/functional/m01/f0_m01"), expected.stream()
                .filter(e -> !e.severity().equals("error")).map(ExpectedFinding::what).toList(), "exp2-defects.rsaml's one other finding");
        assertEquals(expected, actual, "rule, severity, element, location and message of each finding, in order");
        for (Finding f : findings) {
            assertEquals("examples/exp2-defects.rsaml", f.file(), f + " names the file as it was given");
        }

        // Every finding points at the start tag of its element in the file.
        List<String> lines = Files.readAllLines(file);
        for (Finding f : findings) {
            assertTrue(f.line() > 0 && f.column() > 0, "no location for " + f);
            String rest = String.join("\n", lines.subList(f.line() - 1, lines.size())).substring(f.column() - 1);
            String at = rest.substring(0, rest.indexOf('>') + 1);
            assertTrue(at.startsWith("<"), "finding " + f + " does not point at a start tag: " + at);
            String last = f.qualifiedName().substring(f.qualifiedName().lastIndexOf('/') + 1);
            if (!last.contains("->")) {
                assertTrue(at.contains("name=\"" + last + "\""), f + " points at " + at);
            }
        }
    }

    /** Every model of examples/ gives exactly the findings its expect comments state (none for a clean one); a new example needs none here. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("examples")
    void everyExampleGivesTheFindingsItStates(String name) throws Exception {
        Path file = TestRepository.example(name);
        List<String> stated = ExpectedFinding.of(file).stream().map(e -> e.what() + " line " + e.line()).sorted().toList();
        List<String> found = RsamlModelValidator.validate(file).stream().map(f -> new ExpectedFinding(f.ruleId(),
                f.severity().label(), f.qualifiedName(), f.line(), f.column(), f.message()).what() + " line " + f.line()).sorted().toList();
        assertEquals(stated, found, name + " gives the findings its expect comments state, and no other");
    }

    static Stream<String> examples() throws Exception {
        try (Stream<Path> files = Files.list(TestRepository.root().resolve("examples"))) {
            List<String> names = files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted().toList();
            assertTrue(names.contains("exp2-defects.rsaml"), "examples/ holds the paper's experiments: " + names);
            return names.stream();
        }
    }

    /** Its structure is clean; its latency requirement is not, and validation says so on the requirement. */
    @Test
    void theMissedLatencyExampleReportsItsRequirement() throws Exception {
        Path file = TestRepository.example("mobile-base-latency-missed.rsaml");
        List<ExpectedFinding> actual = RsamlModelValidator.validate(file).stream().map(f -> new ExpectedFinding(f.ruleId(),
                f.severity().label(), f.qualifiedName(), f.line(), f.column(), f.message())).collect(Collectors.toList());
        List<ExpectedFinding> expected = ExpectedFinding.of(file);
        assertEquals(List.of("RSA-23"), expected.stream().map(ExpectedFinding::ruleId).toList(),
                "the model states its one finding, on the latency requirement");
        assertEquals(expected, actual, "rule, severity, element, location and message, as the model states them");
    }
}
