/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The up-to-date check fails on stale code: shown on a copy of the repository with edited generated files. */
class StaleGeneratedCodeTest {

    /**
     * The check covers the tree editor and the invariants compiled to Java too: an edited and a missing editor file
     * and edited compiled invariants are all reported.
     */
    @Test
    void staleEditorCodeIsReported(@TempDir Path copy) throws Exception {
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
        String compiled = OclToJava.TARGET;
        RsamlCodegen.copyTree(GeneratedCodeUpToDateTest.ROOT.resolve(compiled), copy.resolve(compiled));
        Files.writeString(copy.resolve(compiled), "// edited by hand\n", StandardOpenOption.APPEND);

        assertEquals(List.of(editor, icon + " (missing)", compiled + " (the invariants compiled to Java)"), RsamlCodegen.check(copy),
                "every stale generated file is listed, and nothing else");
    }
}
