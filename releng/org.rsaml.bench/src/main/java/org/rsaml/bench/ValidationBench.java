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
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
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
import org.rsaml.model.util.RsamlResourceFactoryImpl;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * Validation figures on synthetic architectures: for each size, the time to load the .rsaml file,
 * to validate it with the OCL rules, and to run EMF's structural checks alone; peak and retained
 * heap; and the number of findings. Prints a Markdown table.
 */
public final class ValidationBench {

    /** Elements per module: the module, 2 ports, 2 functions of 3 actions, 1 connection. */
    static final int ELEMENTS_PER_MODULE = 12;
    static final int LAYERS = 4;

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        List<String> rows = new ArrayList<>();
        Path dir = Files.createTempDirectory("rsaml-bench");
        for (String size : args[0].split(",")) {
            int target = Integer.parseInt(size.trim());
            Path file = dir.resolve("synthetic-" + target + ".rsaml");
            write(generate(target), file);
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

    /** A layered architecture of about {@code elements} elements with a small share of violations. */
    static Architecture generate(int elements) {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName("synthetic");
        a.setCategory(ArchitectureCategory.HIERARCHICAL);
        a.setDeclaredLayers(LAYERS);
        int modules = Math.max(LAYERS, elements / ELEMENTS_PER_MODULE);
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
            Layer layer = layers.get(i * LAYERS / modules);
            Module m = f.createModule();
            m.setName("m" + i);
            m.setType(ElementType.REAL_TIME);
            m.setExecType(ExecutionType.PERIODIC);
            m.setPeriod(20);
            m.setDelay(20);
            // about 1% of modules exceed their layer's budget (RSA-08)
            m.setExecDuration(i % 97 == 5 ? 7.5 : 2.0);
            layer.getModules().add(m);
            EntryPort in = f.createEntryPort();
            in.setName("in");
            OutputPort out = f.createOutputPort();
            out.setName("out");
            // about 1% of ports disagree on their data type (RSA-02)
            in.setDataType(i % 101 == 7 ? DataType.BOOLEAN : DataType.NUMERIC);
            m.getPorts().add(in);
            m.getPorts().add(out);
            for (int k = 0; k < 2; k++) {
                Function fn = f.createFunction();
                fn.setName("f" + k);
                fn.setType(ElementType.REAL_TIME);
                m.getFunctions().add(fn);
                for (int j = 0; j < 3; j++) {
                    var action = f.createAction();
                    action.setName("a" + j);
                    action.setType(ElementType.REAL_TIME);
                    action.setExecDuration(0.5);
                    fn.getActions().add(action);
                }
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

    static void write(Architecture a, Path file) throws Exception {
        ResourceSetImpl set = new ResourceSetImpl();
        set.getResourceFactoryRegistry().getExtensionToFactoryMap().put("rsaml", new RsamlResourceFactoryImpl());
        Resource r = set.createResource(URI.createFileURI(file.toString()));
        r.getContents().add(a);
        r.save(Map.of());
        r.unload();
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
