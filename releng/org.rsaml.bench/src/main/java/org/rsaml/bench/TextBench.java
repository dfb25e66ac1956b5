/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.text.RsamlTextStandaloneSetup;
import org.rsaml.text.convert.ModelConverter;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * The textual syntax on synthetic architectures ({@link SyntheticArchitecture}, clean): reading a textual model
 * (parse, link, locate; {@code ModelLoader}) next to reading the same model from XMI, and converting XMI to text and
 * text to XMI ({@code ModelConverter.convert}: read, write) at each size, so that one sees whether conversion grows
 * linearly. Each figure is the best of {@code runs} after one warm-up run. Prints two Markdown tables.
 */
public final class TextBench {

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        RsamlTextStandaloneSetup.injector();
        String[] parseSizes = args[0].split(",");
        String[] convertSizes = args[1].split(",");
        int runs = args.length > 2 ? Integer.parseInt(args[2]) : 3;
        Path dir = Files.createTempDirectory("rsaml-text-bench");

        List<String> parse = new ArrayList<>();
        for (String size : parseSizes) {
            Path xmi = synthetic(dir, Integer.parseInt(size.trim()));
            Path text = dir.resolve(name(xmi) + ".rsa");
            ModelConverter.convert(xmi, xmi.getFileName().toString(), text);
            int[] elements = new int[2];
            long xmiLoad = best(runs, () -> elements[0] = ModelLoader.load(xmi, xmi.getFileName().toString()).elementCount());
            long textLoad = best(runs, () -> elements[1] = ModelLoader.load(text, text.getFileName().toString()).elementCount());
            if (elements[0] != elements[1]) {
                throw new IllegalStateException("the textual model has " + elements[1] + " elements, its XMI " + elements[0]);
            }
            parse.add(String.format("| %,d | %.1f MB | %,d ms | %.1f MB | %,d ms | %.2f |", elements[0], Files.size(xmi) / 1e6,
                    xmiLoad / 1_000_000, Files.size(text) / 1e6, textLoad / 1_000_000, (double) textLoad / xmiLoad));
        }

        List<String> convert = new ArrayList<>();
        for (String size : convertSizes) {
            Path xmi = synthetic(dir, Integer.parseInt(size.trim()));
            Path text = dir.resolve(name(xmi) + ".rsa");
            Path back = dir.resolve(name(xmi) + "-back.rsaml");
            int elements = ModelLoader.load(xmi, xmi.getFileName().toString()).elementCount();
            long toText = best(runs, () -> ModelConverter.convert(xmi, xmi.getFileName().toString(), text));
            long toXmi = best(runs, () -> ModelConverter.convert(text, text.getFileName().toString(), back));
            convert.add(String.format("| %,d | %,d ms | %.2f µs | %,d ms | %.2f µs |", elements, toText / 1_000_000,
                    toText / 1e3 / elements, toXmi / 1_000_000, toXmi / 1e3 / elements));
        }

        System.out.println();
        System.out.println("Reading a textual model (.rsa) and the same model from XMI (.rsaml), best of " + runs + ":");
        System.out.println();
        System.out.println("| Elements | XMI size | XMI read | Text size | Text read | Text / XMI |");
        System.out.println("|---:|---:|---:|---:|---:|---:|");
        parse.forEach(System.out::println);
        System.out.println();
        System.out.println("Conversion (rsaml convert: read, write), best of " + runs + "; linear when the time per element stays level:");
        System.out.println();
        System.out.println("| Elements | XMI → text | per element | text → XMI | per element |");
        System.out.println("|---:|---:|---:|---:|---:|");
        convert.forEach(System.out::println);
    }

    private static Path synthetic(Path dir, int elements) throws Exception {
        Path file = dir.resolve("synthetic-" + elements + ".rsaml");
        if (!Files.exists(file)) {
            SyntheticArchitecture.write(SyntheticArchitecture.of(SyntheticArchitecture.modulesFor(elements), false), file);
        }
        return file;
    }

    private static String name(Path file) {
        String name = file.getFileName().toString();
        return name.substring(0, name.lastIndexOf('.'));
    }

    private interface Step {
        void run() throws Exception;
    }

    /** The shortest of {@code runs} runs after one warm-up, in nanoseconds. */
    private static long best(int runs, Step step) throws Exception {
        gc();
        step.run();
        long best = Long.MAX_VALUE;
        for (int i = 0; i < runs; i++) {
            gc();
            long t0 = System.nanoTime();
            step.run();
            best = Math.min(best, System.nanoTime() - t0);
        }
        return best;
    }

    private static void gc() {
        System.gc();
        System.gc();
    }
}
