/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.TestRepository;

class GeneratedCodeUpToDateTest {

    static final Path ROOT = TestRepository.root();

    @Test
    void committedGeneratedCodeMatchesTheEcore() throws Exception {
        List<String> stale = RsamlCodegen.check(ROOT);
        assertEquals(List.of(), stale,
                "Generated code is out of date with rsaml.ecore. Regenerate it with " + RsamlCodegen.REGENERATE);
    }
}
