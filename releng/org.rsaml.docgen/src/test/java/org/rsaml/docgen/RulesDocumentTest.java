/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.docgen;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

/** The rule table is made of the catalogue's rules and replaces only what is between its markers. */
class RulesDocumentTest {

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
