/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.docgen;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.codegen.RsamlCodegen;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.internal.RuleCatalog;

/** The committed tables are what the regeneration command makes of the sources; a stale one is found and rewritten. */
class GeneratedDocsUpToDateTest {

    private static final Path ROOT = TestRepository.root();

    @Test
    void theCommittedTablesAreTheGeneratedOnes() throws Exception {
        assertEquals(List.of(), RsamlDocgen.check(ROOT),
                "documentation tables differ from the rule catalogue or the textual grammar; regenerate them with " + RsamlCodegen.REGENERATE);
    }

    @Test
    void theRulesRsamlRunsAreTheCataloguesRules() throws Exception {
        try (Reader catalogue = Files.newBufferedReader(ROOT.resolve(RulesDocument.CATALOGUE), StandardCharsets.UTF_8)) {
            assertEquals(RulesDocument.read(catalogue), RuleCatalog.load(),
                    "the rules org.rsaml.validation loads (from its CompiledCatalog while the catalogue is unchanged) are those parsed from "
                            + RulesDocument.CATALOGUE);
        }
    }

    @Test
    void aStaleRuleTableAndLanguageReferenceAreReportedAndRewritten(@TempDir Path copy) throws Exception {
        for (String path : List.of(RulesDocument.CATALOGUE, RulesDocument.PATH, LanguageReference.PATH, RsamlDocgen.GRAMMAR,
                CatalogueClass.PATH)) {
            Files.createDirectories(copy.resolve(path).getParent());
            Files.copy(ROOT.resolve(path), copy.resolve(path));
        }
        Files.createDirectories(copy.resolve("examples-text"));
        try (var examples = Files.list(ROOT.resolve("examples-text"))) {
            for (Path example : examples.toList()) {
                Files.copy(example, copy.resolve("examples-text").resolve(example.getFileName()));
            }
        }
        Path catalogue = copy.resolve(RulesDocument.CATALOGUE);
        String remediation = "RSA-01.remediation = Set declaredLayers to the number of layers, or add or remove layers.";
        assertTrue(Files.readString(catalogue).contains(remediation), "the catalogue no longer holds " + remediation);
        Files.writeString(catalogue, Files.readString(catalogue).replace(remediation, remediation + " Or both."));
        Path reference = copy.resolve(LanguageReference.PATH);
        String edited = Files.readString(reference).replace(LanguageReference.END, "| a row written by hand |\n" + LanguageReference.END);
        Files.writeString(reference, edited);

        assertEquals(List.of(RulesDocument.PATH + " (the rule table)", LanguageReference.PATH + " (the language reference)",
                CatalogueClass.PATH + " (the rule catalogue as Java)"), RsamlDocgen.check(copy),
                "both stale tables and the catalogue's class are listed");

        RsamlDocgen.write(copy);
        assertTrue(Files.readString(copy.resolve(RulesDocument.PATH)).contains("add or remove layers. Or both. |"),
                "regeneration writes the catalogue's new text into the table");
        assertTrue(Files.readString(copy.resolve(CatalogueClass.PATH)).contains("add or remove layers. Or both.\","),
                "regeneration writes the catalogue's new text into its class");
        assertEquals(Files.readString(ROOT.resolve(LanguageReference.PATH)), Files.readString(reference),
                "regeneration replaces the hand-written row with the reference made from the grammar");
        assertEquals(List.of(), RsamlDocgen.check(copy), "nothing is stale after writing");
    }
}
