/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.rsaml.diagram.DiagramView;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;

/** Findings decorate the elements they are on, and only those. */
class FindingsTest {

    @Test
    void experimentTwosFindingsDecorateExactlyTheirElements() throws Exception {
        Examples.Drawn drawn = Examples.draw("exp2-defects.rsaml", DiagramView.ARCHITECTURE);
        SvgDocument svg = new SvgDocument(drawn.svg());
        Map<String, String> decorated = new java.util.TreeMap<>();
        svg.shapes.values().stream().filter(s -> s.classes().contains("error") || s.classes().contains("warning"))
                .forEach(s -> decorated.put(s.qname(), String.join(" ", s.badges())));
        svg.links.stream().filter(l -> l.classes().contains("error") || l.classes().contains("warning"))
                .forEach(l -> decorated.put(l.qname(), String.join(" ", l.badges())));
        Map<String, String> expected = drawn.findings().stream()
                .collect(Collectors.toMap(Finding::qualifiedName, Finding::ruleId, (a, b) -> a + " " + b, java.util.TreeMap::new));
        assertEquals(expected, decorated, "decorated elements with the rule ids on their badges");
        Map<String, String> stated = ExpectedFinding.of(TestRepository.example("exp2-defects.rsaml")).stream()
                .collect(Collectors.toMap(ExpectedFinding::qualifiedName, ExpectedFinding::ruleId, (a, b) -> a + " " + b,
                        java.util.TreeMap::new));
        assertEquals(stated, expected, "the drawn findings are those the model's expect comments state");
    }

    @Test
    void aCleanModelHasNoDecoration() throws Exception {
        Examples.Drawn drawn = Examples.draw("exp3-task-interpreter.rsaml", DiagramView.ARCHITECTURE);
        assertEquals(List.of(), drawn.findings(), "experiment 3 has no finding");
        SvgDocument svg = new SvgDocument(drawn.svg());
        assertTrue(svg.shapes.values().stream().noneMatch(s -> s.classes().contains("error") || !s.badges().isEmpty()),
                "no shape is marked or badged");
        assertTrue(svg.links.stream().noneMatch(l -> l.classes().contains("error") || !l.badges().isEmpty()),
                "no link is marked or badged");
    }
}
