/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

import org.rsaml.generator.GenerationResult;
import org.rsaml.generator.RsamlGenerator;
import org.rsaml.generator.Target;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * Generation figures on a clean synthetic architecture of N modules ({@link SyntheticArchitecture}),
 * deployed four modules to a processor so that its timing holds and the generator takes it:
 * for each target, the time of a first generation into an empty directory, of a regeneration with
 * nothing to change, and the size of the output. Prints a Markdown table.
 */
public final class GenerationBench {

    static final int RUNS = 3;

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        int modules = Integer.parseInt(args[0].trim());
        Path dir = Files.createTempDirectory("rsaml-genbench");
        Path file = dir.resolve("synthetic-" + modules + ".rsaml");
        SyntheticArchitecture.write(SyntheticArchitecture.deploy(SyntheticArchitecture.of(modules, false), 4), file);

        long t0 = System.nanoTime();
        LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
        long load = System.nanoTime() - t0;
        t0 = System.nanoTime();
        int findings = RsamlModelValidator.validate(model).size();
        long validate = System.nanoTime() - t0;

        RsamlGenerator generator = new RsamlGenerator();
        List<String> rows = new ArrayList<>();
        for (Target target : Target.values()) {
            generator.generate(model, target, dir.resolve("warmup-" + target.id()), false); // JIT, class loading
            long[] first = new long[RUNS];
            long[] again = new long[RUNS];
            GenerationResult result = null;
            for (int run = 0; run < RUNS; run++) {
                Path out = dir.resolve(target.id() + "-" + run);
                t0 = System.nanoTime();
                result = generator.generate(model, target, out, false);
                first[run] = System.nanoTime() - t0;
                t0 = System.nanoTime();
                GenerationResult second = generator.generate(model, target, out, false);
                again[run] = System.nanoTime() - t0;
                if (!second.written().isEmpty()) {
                    throw new IllegalStateException("regeneration rewrote " + second.written().size() + " files");
                }
            }
            long[] size = size(result.outputDirectory());
            rows.add(String.format("| %s | %,d | %,d ms | %,d ms | %,d | %.1f MB |", target.id(), modules, median(first) / 1_000_000,
                    median(again) / 1_000_000, size[0], size[1] / 1e6));
            System.out.println(rows.get(rows.size() - 1));
        }
        deleteTree(dir);
        System.out.println();
        System.out.printf("model: %,d elements, load %,d ms, validation %,d ms (%d findings); generation times include validation%n",
                model.elementCount(), load / 1_000_000, validate / 1_000_000, findings);
        System.out.println("| target | modules | first generation (median of " + RUNS + ") | regeneration, nothing changed | files | output |");
        System.out.println("|---|---:|---:|---:|---:|---:|");
        rows.forEach(System.out::println);
    }

    static long median(long[] values) {
        long[] sorted = values.clone();
        java.util.Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    static long[] size(Path dir) throws Exception {
        try (Stream<Path> walk = Files.walk(dir)) {
            List<Path> files = walk.filter(Files::isRegularFile).toList();
            long bytes = 0;
            for (Path p : files) {
                bytes += Files.size(p);
            }
            return new long[] { files.size(), bytes };
        }
    }

    static void deleteTree(Path root) throws Exception {
        try (Stream<Path> walk = Files.walk(root)) {
            for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }
}
