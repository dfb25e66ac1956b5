/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.tests.support.ChainModels;

/**
 * A legal model as deep as it is long, a chain of 20,000 modules each reacting to the one before, is drawn whole: the
 * layout (whose recursion follows the chain) runs on a stack sized for the model, not on the caller's, which here is
 * a quarter of a JVM's default (a chain of 1,500 overflowed a default stack before).
 */
class DeepLayoutTest {

    private static final int MODULES = 20_000;

    @Test
    void aChainOf20000ModulesIsDrawnFromACallerWithASmallStack(@TempDir Path dir) throws Exception {
        Path model = ChainModels.write(dir.resolve("chain.rsaml"), MODULES, false);
        Path[] written = new Path[1];
        Throwable[] thrown = new Throwable[1];
        Thread caller = new Thread(null, () -> {
            try {
                written[0] = new RsamlDiagrams(DiagramView.ARCHITECTURE).write(model, "chain.rsaml", DiagramFormat.SVG, dir.resolve("out"));
            } catch (Throwable t) {
                thrown[0] = t;
            }
        }, "small-stack caller", 256 << 10);
        caller.start();
        caller.join();

        assertEquals(null, thrown[0], "the chain is drawn without an error");
        assertEquals(dir.resolve("out/chain-architecture.svg"), written[0], "the diagram is written where the batch says");
        String svg = Files.readString(written[0]);
        Matcher modules = Pattern.compile("data-kind=\"module\"").matcher(svg);
        int drawn = 0;
        while (modules.find()) {
            drawn++;
        }
        assertEquals(MODULES + 1, drawn, "every module of the chain and the timed one feeding it is drawn");
        assertTrue(svg.contains("data-qname=\"chain/l/m" + (MODULES - 1) + "\""), "the chain is drawn to its last module");
        assertTrue(svg.trim().endsWith("</svg>"), "the SVG document is complete");
    }
}
