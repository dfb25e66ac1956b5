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
import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * Generation figures on a synthetic, valid architecture of N modules (4 layers; per module a
 * periodic function of 3 actions, an aperiodic function of 2, an entry and an output port, a
 * connection to the next module): for each target, the time of a first generation into an empty
 * directory, of a regeneration with nothing to change, and the size of the output. Prints a
 * Markdown table.
 */
public final class GenerationBench {

    static final int LAYERS = 4;
    static final int RUNS = 3;

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        int modules = Integer.parseInt(args[0].trim());
        Path dir = Files.createTempDirectory("rsaml-genbench");
        Path file = dir.resolve("synthetic-" + modules + ".rsaml");
        ValidationBench.write(generate(modules), file);

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

    /** A clean layered architecture: every connection joins the same or adjacent layers, with equal types. */
    static Architecture generate(int modules) {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName("synthetic");
        a.setCategory(ArchitectureCategory.HIERARCHICAL);
        a.setDeclaredLayers(LAYERS);
        List<Layer> layers = new ArrayList<>();
        for (int l = 0; l < LAYERS; l++) {
            Layer layer = f.createLayer();
            layer.setName("layer" + l);
            layer.setLevel(l);
            layer.setMaxExecTime(5.0);
            a.getLayers().add(layer);
            layers.add(layer);
        }
        OutputPort previous = null;
        for (int i = 0; i < modules; i++) {
            Module m = f.createModule();
            m.setName("m" + i);
            m.setExecDuration(2.0);
            layers.get(i * LAYERS / modules).getModules().add(m);
            EntryPort in = f.createEntryPort();
            in.setName("in");
            in.setDataType(DataType.NUMERIC);
            OutputPort out = f.createOutputPort();
            out.setName("out");
            m.getPorts().add(in);
            m.getPorts().add(out);
            Function periodic = f.createFunction();
            periodic.setName("control");
            periodic.setExecType(ExecutionType.PERIODIC);
            periodic.setPeriod(20 + 10 * (i % 5));
            periodic.setSchedPolicy(SchedulingPolicy.RM);
            m.getFunctions().add(periodic);
            for (int j = 0; j < 3; j++) {
                var action = f.createAction();
                action.setName("step" + j);
                action.setExecDuration(0.5);
                action.setStartDate(j * 0.5);
                periodic.getActions().add(action);
            }
            Function onData = f.createFunction();
            onData.setName("update");
            onData.setType(ElementType.SIMPLE);
            m.getFunctions().add(onData);
            for (int j = 0; j < 2; j++) {
                var action = f.createAction();
                action.setName("apply" + j);
                onData.getActions().add(action);
            }
            if (previous != null) {
                Connection c = f.createConnection();
                c.setSource(previous);
                c.setTarget(in);
                a.getConnections().add(c);
            }
            previous = out;
        }
        return a;
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
