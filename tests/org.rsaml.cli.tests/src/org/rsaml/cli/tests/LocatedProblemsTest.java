/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.generator.GenerationException;
import org.rsaml.model.resource.Located;
import org.rsaml.validation.ModelLoadException;

/** A load error and a generation error at the same place are located, and printed, the same way. */
class LocatedProblemsTest {

    @Test
    void loadAndGenerationErrorsShareOneLocation() {
        List<Located> problems = List.of(new ModelLoadException("models/rover.rsaml", 3, 7, "it is wrong", null),
                new GenerationException("models/rover.rsaml", 3, 7, "it is wrong", null));
        for (Located p : problems) {
            assertEquals("models/rover.rsaml", p.file(), p.getClass().getSimpleName() + " names the file");
            assertEquals(3, p.line(), p.getClass().getSimpleName() + " names the line");
            assertEquals(7, p.column(), p.getClass().getSimpleName() + " names the column");
            assertEquals("models/rover.rsaml:3:7: error: it is wrong", p.toString(), p.getClass().getSimpleName());
        }
        Located unplaced = new GenerationException("out/", "not a directory");
        assertEquals(0, unplaced.line(), "a problem of a whole file has no line");
        assertEquals("out/: error: not a directory", unplaced.toString(), "a problem of a whole file names the file alone");
        assertEquals("models/rover.rsaml: error: empty", new ModelLoadException("models/rover.rsaml", "empty").toString(),
                "a load error of a whole file names the file alone");
    }
}
