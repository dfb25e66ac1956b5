/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.docgen;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.GrammarUtil;
import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.TestRepository;

/**
 * docs/textual-syntax.md's generated reference names every keyword and unit of the grammar ({@link GeneratedDocsUpToDateTest}
 * checks that it is what the regeneration command makes of the grammar).
 */
class LanguageReferenceTest {

    private static String page() throws Exception {
        return Files.readString(TestRepository.root().resolve(LanguageReference.PATH), StandardCharsets.UTF_8);
    }

    @Test
    void theReferenceShowsEveryKeywordAndUnitInItsTables() throws Exception {
        String page = page();
        String generated = page.substring(page.indexOf(LanguageReference.BEGIN), page.indexOf(LanguageReference.END));
        List<String> missing = new ArrayList<>();
        for (String keyword : GrammarUtil.getAllKeywords(RsamlDocgen.grammar(TestRepository.root()))) {
            if (Character.isLetter(keyword.charAt(0)) && !generated.contains("`" + keyword + "`") && !generated.contains(" " + keyword + ",")
                    && !generated.contains(" " + keyword + " |")) {
                missing.add(keyword);
            }
        }
        missing.removeAll(List.of("NaN", "Infinity"));
        assertEquals(List.of(), missing, "keywords the generated reference does not show");
        for (String unit : List.of("ns", "us", "ms", "s")) {
            assertTrue(generated.contains("| `" + unit + "` |"), "the units table has " + unit);
        }
    }
}
