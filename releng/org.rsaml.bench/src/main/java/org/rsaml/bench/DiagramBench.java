/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.diagram.internal.ArchitectureLayout;
import org.rsaml.diagram.internal.Drawing;
import org.rsaml.diagram.internal.SvgWriter;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * Diagram figures on a clean synthetic architecture of N modules ({@link SyntheticArchitecture}): the
 * time to lay out and write the architecture view as SVG and as HTML (median of a few runs after a
 * warm-up), the SVG's two halves (layout by ELK with the text sized, writing the text), and the size
 * of each file. Prints a Markdown table.
 */
public final class DiagramBench {

    static final int RUNS = 3;

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        System.out.println("| modules | SVG (layout + drawing) | of which layout (ELK, text sizes) | of which writing the SVG | SVG size | HTML | HTML size |");
        System.out.println("|---:|---:|---:|---:|---:|---:|---:|");
        for (String size : args[0].split(",")) {
            int modules = Integer.parseInt(size.trim());
            Path dir = Files.createTempDirectory("rsaml-diagrambench");
            Path file = dir.resolve("synthetic-" + modules + ".rsaml");
            SyntheticArchitecture.write(SyntheticArchitecture.of(modules, false), file);
            LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
            List<Finding> findings = RsamlModelValidator.validate(model);
            RsamlDiagrams diagrams = new RsamlDiagrams(DiagramView.ARCHITECTURE);
            diagrams.svg(model.architecture(), findings); // JIT, class loading
            long[] svgTimes = new long[RUNS];
            long[] htmlTimes = new long[RUNS];
            long[] layoutTimes = new long[RUNS];
            long[] writeTimes = new long[RUNS];
            String svg = null;
            String html = null;
            for (int run = 0; run < RUNS; run++) {
                long t0 = System.nanoTime();
                svg = diagrams.svg(model.architecture(), findings);
                svgTimes[run] = System.nanoTime() - t0;
                t0 = System.nanoTime();
                html = diagrams.html(model.architecture(), file.getFileName().toString(), findings);
                htmlTimes[run] = System.nanoTime() - t0;
                // The two halves of svg(): what RsamlDiagrams does for a model without timing questions.
                t0 = System.nanoTime();
                Drawing drawing = ArchitectureLayout.draw(model.architecture(), findings, DiagramOverlay.Notes.NONE);
                layoutTimes[run] = System.nanoTime() - t0;
                t0 = System.nanoTime();
                SvgWriter.write(drawing, true);
                writeTimes[run] = System.nanoTime() - t0;
            }
            System.out.printf("| %,d | %,d ms | %,d ms | %,d ms | %.1f MB | %,d ms | %.1f MB |%n", modules, median(svgTimes) / 1_000_000,
                    median(layoutTimes) / 1_000_000, median(writeTimes) / 1_000_000, svg.length() / 1e6, median(htmlTimes) / 1_000_000,
                    html.length() / 1e6);
            Files.delete(file);
            Files.delete(dir);
        }
    }

    private static long median(long[] values) {
        long[] sorted = values.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }
}
