/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.validation.RulesDocument;

/** The up-to-date check fails on stale code: shown on a copy of the repository with edited generated files. */
class StaleGeneratedCodeTest {

    /**
     * The check covers the tree editor and the rule table of docs/rules.md too: an edited and a missing
     * editor file and a table that no longer shows the catalogue are all reported.
     */
    @Test
    void staleEditorCodeAndRuleTableAreReported(@TempDir Path copy) throws Exception {
        RsamlCodegen.copyTree(GeneratedCodeUpToDateTest.ROOT.resolve(RsamlCodegen.MODEL_DIR), copy.resolve(RsamlCodegen.MODEL_DIR));
        for (Map.Entry<String, List<String>> bundle : RsamlCodegen.GENERATED.entrySet()) {
            for (String item : bundle.getValue()) {
                String path = "bundles/" + bundle.getKey() + "/" + item;
                RsamlCodegen.copyTree(GeneratedCodeUpToDateTest.ROOT.resolve(path), copy.resolve(path));
            }
        }
        String editor = "bundles/org.rsaml.model.editor/src-gen/org/rsaml/model/editor/presentation/RsamlEditor.java";
        String icon = "bundles/org.rsaml.model.editor/icons/full/obj16/RsamlModelFile.gif";
        Files.writeString(copy.resolve(editor), "// edited by hand\n", StandardOpenOption.APPEND);
        Files.delete(copy.resolve(icon));
        for (String path : List.of(RulesDocument.CATALOGUE, RulesDocument.PATH)) {
            Files.createDirectories(copy.resolve(path).getParent());
            Files.copy(GeneratedCodeUpToDateTest.ROOT.resolve(path), copy.resolve(path));
        }
        Path catalogue = copy.resolve(RulesDocument.CATALOGUE);
        String remediation = "RSA-01.remediation = Set declaredLayers to the number of layers, or add or remove layers.";
        assertTrue(Files.readString(catalogue).contains(remediation), "the catalogue no longer holds " + remediation);
        Files.writeString(catalogue, Files.readString(catalogue).replace(remediation, remediation + " Or both."));

        assertEquals(List.of(editor, icon + " (missing)", RulesDocument.PATH + " (the rule table)"), RsamlCodegen.check(copy),
                "every stale generated file is listed, and nothing else");

        RsamlCodegen.writeRulesDocument(copy);
        assertTrue(Files.readString(copy.resolve(RulesDocument.PATH)).contains("add or remove layers. Or both. |"),
                "regeneration writes the catalogue's new text into the table");
    }
}
