/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * Validation figures on synthetic architectures ({@link SyntheticArchitecture}, with defects): for
 * each size, the time to load the .rsaml file, to validate it with the OCL rules, and to run EMF's
 * structural checks alone; peak and retained heap; and the number of findings. Prints a Markdown
 * table.
 */
public final class ValidationBench {

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        List<String> rows = new ArrayList<>();
        Path dir = Files.createTempDirectory("rsaml-bench");
        for (String size : args[0].split(",")) {
            int target = Integer.parseInt(size.trim());
            Path file = dir.resolve("synthetic-" + target + ".rsaml");
            SyntheticArchitecture.write(SyntheticArchitecture.of(SyntheticArchitecture.modulesFor(target), true), file);
            long bytes = Files.size(file);

            gc();
            resetPeaks();
            long t0 = System.nanoTime();
            LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
            long load = System.nanoTime() - t0;
            long peakLoad = peakHeap();
            gc();
            long retained = usedHeap();
            int elements = model.elementCount();

            t0 = System.nanoTime();
            List<Finding> structural = RsamlModelValidator.validateStructure(model);
            long structure = System.nanoTime() - t0;

            resetPeaks();
            t0 = System.nanoTime();
            List<Finding> findings = RsamlModelValidator.validate(model);
            long validate = System.nanoTime() - t0;
            long peakValidate = peakHeap();

            rows.add(String.format("| %,d | %.1f MB | %,d ms | %,d ms | %,d ms | %,d MB | %,d MB (%d B/element) | %,d (%,d structural) |",
                    elements, bytes / 1e6, load / 1_000_000, validate / 1_000_000, structure / 1_000_000,
                    Math.max(peakLoad, peakValidate) >> 20, retained >> 20, elements == 0 ? 0 : retained / elements,
                    findings.size(), structural.size()));
            System.out.println(rows.get(rows.size() - 1));
            model = null;
            Files.delete(file);
        }
        Files.delete(dir);
        System.out.println();
        System.out.println("| elements | file | load | validate (OCL rules + structure) | EMF structural checks alone | peak heap | retained heap after load | findings |");
        System.out.println("|---:|---:|---:|---:|---:|---:|---:|---:|");
        rows.forEach(System.out::println);
    }

    static void gc() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(50);
        }
    }

    static void resetPeaks() {
        ManagementFactory.getMemoryPoolMXBeans().forEach(MemoryPoolMXBean::resetPeakUsage);
    }

    static long peakHeap() {
        return ManagementFactory.getMemoryPoolMXBeans().stream().filter(p -> p.getType() == MemoryType.HEAP)
                .mapToLong(p -> p.getPeakUsage().getUsed()).sum();
    }

    static long usedHeap() {
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }
}
