/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.ExecutionType;
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
 * RSA-19 (every module is activated by something timed) on the graphs that made it slow: a
 * <b>chain</b> of n modules fed by one periodic module (each module's output connected to the
 * next one's entry), and a <b>dense</b> graph of n modules, each connected to every other, nothing
 * timed. For each, in one JVM: EMF's structural checks of the model (the anchor), RSA-19 alone over
 * every module as the validation evaluates it (one traversal, {@link ModuleActivation}), the whole
 * validation, and on the smaller graphs RSA-19 as classic OCL interprets the invariant of rsaml.ecore
 * (its definition and the tests' oracle), for comparison. CPU time of the process (wall in brackets).
 */
public final class ActivationBench {

    /** Graphs up to this many modules also get the interpreted invariant (quadratic on a chain). */
    private static final int INTERPRETED_CHAIN = 1_000;
    private static final int INTERPRETED_DENSE = 30;

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        OclRules.instance();
        Path dir = Files.createTempDirectory("rsaml-bench");
        List<String> rows = new ArrayList<>();
        run(dir, "chain", 200, false); // warm-up
        run(dir, "dense", 20, false);
        for (String spec : (args.length > 0 ? args[0] : "chain:1000,chain:2000,chain:20000,chain:100000,dense:60,dense:200").split(",")) {
            String[] kv = spec.trim().split(":");
            String row = run(dir, kv[0], Integer.parseInt(kv[1]), true);
            System.out.println(row);
            rows.add(row);
        }
        Files.delete(dir);
        System.out.println();
        System.out.println("| graph | modules | connections | EMF structural checks (the anchor) | RSA-19 alone | ÷ structural"
                + " | whole validation | ÷ structural | RSA-19 interpreted by OCL | modules not activated |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        rows.forEach(System.out::println);
    }

    private static String run(Path dir, String kind, int n, boolean interpreted) throws Exception {
        Architecture a = kind.equals("chain") ? chain(n) : dense(n);
        int connections = a.getConnections().size();
        Path file = dir.resolve(kind + "-" + n + ".rsaml");
        SyntheticArchitecture.write(a, file);
        LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
        List<Module> modules = model.architecture().getLayers().stream().flatMap(l -> l.getModules().stream()).toList();

        ValidationBench.gc();
        ValidationBench.Timer t = ValidationBench.Timer.start();
        RsamlModelValidator.validateStructure(model);
        ValidationBench.Timer structure = t.stop();

        ValidationBench.gc();
        t = ValidationBench.Timer.start();
        ModuleActivation activation = new ModuleActivation();
        int off = 0;
        for (Module m : modules) {
            off += activation.isActivated(m) ? 0 : 1;
        }
        ValidationBench.Timer rule = t.stop();

        ValidationBench.gc();
        t = ValidationBench.Timer.start();
        List<Finding> findings = RsamlModelValidator.validate(model);
        ValidationBench.Timer validate = t.stop();
        long reported = findings.stream().filter(f -> f.ruleId().equals("RSA-19")).count();

        String oclColumn = "not run";
        if (interpreted && n <= (kind.equals("chain") ? INTERPRETED_CHAIN : INTERPRETED_DENSE)) {
            ValidationBench.gc();
            t = ValidationBench.Timer.start();
            int oclOff = 0;
            for (Module m : modules) {
                oclOff += Boolean.TRUE.equals(OclRules.instance().check(RsamlPackage.Literals.MODULE, ModuleActivation.CONSTRAINT, m)) ? 0 : 1;
            }
            oclColumn = t.stop() + (oclOff == off ? "" : " DIFFERS: " + oclOff + " not activated");
        }
        Files.delete(file);
        return String.format("| %s | %,d | %,d | %s | %s | %s | %s | %s | %s | %,d%s |", kind, n, connections, structure, rule,
                rule.over(structure), validate, validate.over(structure), oclColumn, off,
                reported == off ? "" : " (validation reported " + reported + ")");
    }

    /** n modules in a chain, the first periodic (so activation must travel the whole chain), the rest untimed. */
    static Architecture chain(int n) {
        return SyntheticArchitecture.build("chain", ArchitectureCategory.HIERARCHICAL, n, (m, i, all) -> {
            if (i == 0) {
                m.setExecType(ExecutionType.PERIODIC);
                m.setPeriod(100);
                m.setExecDuration(1);
            }
        }).architecture();
    }

    /** n untimed modules, each connected to every other (n (n - 1) connections): none is activated. */
    static Architecture dense(int n) {
        SyntheticArchitecture.Built built = SyntheticArchitecture.build("dense", ArchitectureCategory.HIERARCHICAL, n, (m, i, all) -> {
        });
        Architecture a = built.architecture();
        a.getConnections().clear();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (i != j) {
                    SyntheticArchitecture.connect(a, built.outs().get(i), built.ins().get(j));
                }
            }
        }
        return a;
    }
}
