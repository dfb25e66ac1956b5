/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.model.Architecture;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlPackage;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;
import org.rsaml.validation.internal.ModuleActivation;
import org.rsaml.validation.internal.OclRules;

/**
 * Validation figures on synthetic architectures ({@link SyntheticArchitecture}, with about 1% of
 * defects), two shapes: <b>deployed</b>, the realistic one (four modules to a processor, each with a
 * core of its own, as {@link GenerationBench} deploys them, so the timing holds), and
 * <b>overloaded</b>, the stress case (no processor: every module on the one default processor, far
 * beyond its capacity, so most periodic functions miss). For each shape and size, in a JVM of its own
 * (so that its peak resident memory is its own): loading the file, the full validation, and beside
 * it, in the same JVM, its anchor (EMF's structural checks alone) and its two other parts alone (every
 * OCL invariant as the validation evaluates it; the timing analysis), each with its CPU time (every
 * thread of the process, the collector's included) and its wall time. Prints a Markdown table.
 */
public final class ValidationBench {

    private static final long MS = 1_000_000L;
    private static final String ROW = "ROW ";
    /**
     * How often the anchor and the full validation are measured, alternately (their medians are shown, and
     * each pair's ratio): {@code rsaml.bench.pairs}, 3 by default.
     */
    private static final int PAIRS = Math.max(1, Integer.getInteger("rsaml.bench.pairs", 3));

    public static void main(String[] args) throws Exception {
        if (args.length == 3 && args[0].equals("--one")) {
            one(args[1], Integer.parseInt(args[2]));
            return;
        }
        List<String> rows = new ArrayList<>();
        for (String shape : System.getProperty("rsaml.bench.shapes", "deployed,overloaded").split(",")) {
            shape = shape.trim();
            if (!shape.equals("deployed") && !shape.equals("overloaded")) {
                throw new IllegalArgumentException("rsaml.bench.shapes: '" + shape + "' is neither deployed nor overloaded");
            }
            for (String size : args[0].split(",")) {
                String row = child(shape, Integer.parseInt(size.trim()));
                System.out.println(row);
                rows.add(row);
            }
        }
        System.out.println();
        System.out.println("Times: CPU of the whole process (wall in brackets); ratios of CPU times, measured in the same JVM.");
        System.out.println();
        System.out.println("| shape | elements | file | load | EMF structural checks (the anchor) | full validation | ÷ structural"
                + " | OCL invariants alone (compiled) | ÷ structural | the same interpreted by classic OCL | ÷ structural"
                + " | timing analysis alone | peak RSS | findings | load average (1 min) | each pair: anchor, full validation, ratio |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|");
        rows.forEach(System.out::println);
    }

    /** Runs one shape and size in a JVM of its own, with this JVM's options; its table row. */
    private static String child(String shape, int size) throws Exception {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(ManagementFactory.getRuntimeMXBean().getInputArguments());
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(ValidationBench.class.getName());
        command.add("--one");
        command.add(shape);
        command.add(Integer.toString(size));
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        String row = null;
        try (var out = new java.io.BufferedReader(new java.io.InputStreamReader(p.getInputStream()))) {
            for (String line; (line = out.readLine()) != null;) {
                if (line.startsWith(ROW)) {
                    row = line.substring(ROW.length());
                } else {
                    System.out.println("  [" + shape + " " + size + "] " + line);
                }
            }
        }
        int exit = p.waitFor();
        return row != null ? row : "| " + shape + " | " + size + " | failed (exit " + exit + ") | | | | | | | | | | | | | |";
    }

    private static Architecture architecture(String shape, int elements) {
        Architecture a = SyntheticArchitecture.of(SyntheticArchitecture.modulesFor(elements), true);
        return shape.equals("deployed") ? SyntheticArchitecture.deploy(a, 4) : a;
    }

    private static void one(String shape, int size) throws Exception {
        String loadBefore = loadAverage();
        RsamlValidationSetup.init();
        OclRules.instance(); // set up once per JVM: not part of what is measured
        OclRules interpreter = OclRules.interpreted(RsamlPackage.eINSTANCE, true);
        Path dir = Files.createTempDirectory("rsaml-bench");
        // warm-up on a small model of the same shape, so that the JIT has compiled the common paths
        Path small = dir.resolve("warm-up.rsaml");
        SyntheticArchitecture.write(architecture(shape, 2_000), small);
        for (int i = 0; i < 3; i++) {
            LoadedModel m = ModelLoader.load(small, "warm-up.rsaml");
            RsamlModelValidator.validateStructure(m);
            RsamlModelValidator.validate(m);
            invariants(m, OclRules.instance());
            invariants(m, interpreter);
            TimingAnalysis.analyse(m.architecture());
        }
        Path file = dir.resolve("synthetic-" + size + ".rsaml");
        SyntheticArchitecture.write(architecture(shape, size), file);
        long bytes = Files.size(file);

        gc();
        Timer t = Timer.start();
        LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
        Timer load = t.stop();
        int elements = model.elementCount();

        // the anchor and the full validation one after the other, three times: the medians (a single pair on a shared
        // machine can be a collection or another process's burst apart)
        List<Finding> structural = null;
        List<Finding> findings = null;
        Timer[] structures = new Timer[PAIRS];
        Timer[] validations = new Timer[PAIRS];
        for (int i = 0; i < PAIRS; i++) {
            gc();
            t = Timer.start();
            structural = RsamlModelValidator.validateStructure(model);
            structures[i] = t.stop();

            gc();
            t = Timer.start();
            findings = RsamlModelValidator.validate(model);
            validations[i] = t.stop();
        }
        Timer structure = Timer.median(structures);
        Timer validate = Timer.median(validations);

        gc();
        t = Timer.start();
        int violated = invariants(model, OclRules.instance());
        Timer ocl = t.stop();

        gc();
        t = Timer.start();
        int violatedInterpreted = invariants(model, interpreter);
        Timer interpreted = t.stop();
        if (violatedInterpreted != violated) {
            throw new IllegalStateException("compiled and interpreted invariants disagree: " + violated + " and " + violatedInterpreted + " violated");
        }

        gc();
        t = Timer.start();
        TimingAnalysis.analyse(model.architecture());
        Timer timing = t.stop();

        System.out.println(ROW + String.format(
                "| %s | %,d | %.1f MB | %s | %s | %s | %s | %s | %s | %s | %s | %s | %,d MB | %,d (%,d structural, %,d invariants violated) | %s to %s | %s |",
                shape, elements, bytes / 1e6, load, structure, validate, validate.over(structure), ocl, ocl.over(structure),
                interpreted, interpreted.over(structure), timing,
                peakRss() >> 20, findings.size(), structural.size(), violated, loadBefore, loadAverage(), pairs(structures, validations)));
        Files.delete(file);
        Files.delete(small);
        Files.delete(dir);
    }

    /** Each pair in the order measured: the anchor's and the full validation's CPU time (ms) and their ratio. */
    private static String pairs(Timer[] structures, Timer[] validations) {
        List<String> each = new ArrayList<>();
        for (int i = 0; i < structures.length; i++) {
            each.add(String.format("%,d / %,d ms %s", structures[i].cpu() / MS, validations[i].cpu() / MS, validations[i].over(structures[i])));
        }
        return String.join("; ", each);
    }

    /**
     * Every OCL invariant of rsaml.ecore on every element, as the validation evaluates it (RSA-19 by
     * its one traversal, {@link ModuleActivation}) by {@code rules}: compiled, or all interpreted; the number violated.
     */
    static int invariants(LoadedModel model, OclRules rules) {
        Map<EClass, List<EClass>> classes = new HashMap<>();
        Map<EClass, List<String>> constraints = new HashMap<>();
        ModuleActivation activation = new ModuleActivation();
        int violated = 0;
        for (EObject root : model.resource().getContents()) {
            for (Iterator<EObject> it = EcoreUtil.getAllContents(List.of(root)); it.hasNext();) {
                EObject o = it.next();
                for (EClass c : classes.computeIfAbsent(o.eClass(), ValidationBench::withSupertypes)) {
                    for (String constraint : constraints.computeIfAbsent(c, EcoreUtil::getConstraints)) {
                        Boolean ok = ModuleActivation.CONSTRAINT.equals(constraint) && o instanceof Module m ? Boolean.valueOf(activation.isActivated(m))
                                : rules.check(c, constraint, o);
                        violated += Boolean.TRUE.equals(ok) ? 0 : 1;
                    }
                }
            }
        }
        return violated;
    }

    private static List<EClass> withSupertypes(EClass eClass) {
        List<EClass> all = new ArrayList<>(eClass.getEAllSuperTypes());
        all.add(eClass);
        return all;
    }

    /** CPU time of the whole process (every thread, the collector's too) and wall time of one measure. */
    record Timer(long cpu, long wall) {
        private static final com.sun.management.OperatingSystemMXBean OS =
                (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();

        static Timer start() {
            return new Timer(OS.getProcessCpuTime(), System.nanoTime());
        }

        Timer stop() {
            return new Timer(OS.getProcessCpuTime() - cpu, System.nanoTime() - wall);
        }

        /** The median CPU time and the median wall time of several measures of one thing. */
        static Timer median(Timer[] measures) {
            long[] cpus = java.util.Arrays.stream(measures).mapToLong(Timer::cpu).sorted().toArray();
            long[] walls = java.util.Arrays.stream(measures).mapToLong(Timer::wall).sorted().toArray();
            return new Timer(cpus[cpus.length / 2], walls[walls.length / 2]);
        }

        /** This time over the anchor's, as text; none when the anchor is below the CPU clock's resolution (10 ms). */
        String over(Timer anchor) {
            return anchor.cpu < 10 * MS ? "(anchor < 10 ms)" : String.format("%.1f×", (double) cpu / anchor.cpu);
        }

        @Override
        public String toString() {
            return String.format("%,d ms (%,d)", cpu / MS, wall / MS);
        }
    }

    /** The machine's load average over the last minute (/proc/loadavg), or "?" where it cannot be read. */
    static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (Exception e) {
            return "?";
        }
    }

    /** The process's peak resident memory (VmHWM), in bytes; 0 where /proc does not tell. */
    static long peakRss() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("VmHWM:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", "")) * 1024;
                }
            }
        } catch (Exception e) {
            // not Linux: no figure
        }
        return 0;
    }

    static void gc() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(50);
        }
    }
}
