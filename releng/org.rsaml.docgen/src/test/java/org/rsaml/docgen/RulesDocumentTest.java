/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;
import org.rsaml.validation.RulesDocument;

/**
 * docs/rules.md's rule table is the catalogue's: every column of every rule, nothing else. The test
 * only compares; releng/org.rsaml.codegen writes the table ({@link RulesDocument#REGENERATE}).
 */
class RulesDocumentTest {

    @Test
    void theRulesTableIsTheCatalogue() throws Exception {
        String page = Files.readString(TestRepository.root().resolve(RulesDocument.PATH), StandardCharsets.UTF_8);
        assertEquals(RulesDocument.update(page, Rules.all()), page,
                RulesDocument.PATH + "'s rule table differs from the rule catalogue; regenerate it with " + RulesDocument.REGENERATE);
    }

    @Test
    void aStaleTableIsReplacedWholeAndTheRestOfThePageKept() {
        String before = "# Rules\n\nText above.\n\n" + RulesDocument.BEGIN + "\n| id |\n|---|\n| RSA-99 |\n" + RulesDocument.END
                + "\n\nText below.\n";
        List<Rule> one = Rules.all().subList(0, 1);
        String after = RulesDocument.update(before, one);
        assertEquals("# Rules\n\nText above.\n\n" + RulesDocument.BEGIN + "\n" + RulesDocument.table(one) + RulesDocument.END
                + "\n\nText below.\n", after, "only the lines between the markers are replaced");
        assertTrue(RulesDocument.table(one).contains("| " + one.get(0).id() + " | " + one.get(0).name() + " |"),
                "the table names the rule: " + RulesDocument.table(one));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> RulesDocument.update("# Rules\n", one),
                "a page without the markers is refused, not rewritten");
        assertTrue(e.getMessage().contains(RulesDocument.BEGIN), e.getMessage());
    }
}
