/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.model.Actuator;
import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.Sensor;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * A latency requirement's paths (followed one by one, then by the longest-path computation past 1,000,000 steps) on the
 * graphs that make them many or long, each fed by one periodic module reading a sensor, the modules after it reacting
 * (sporadic), the last driving the actuator the requirement ends at: a <b>chain</b> of n modules (one path of n stages);
 * a <b>ladder</b> of n modules in layers of two, each feeding both of the next layer (2^((n - 2) / 2) paths for n even); a <b>dense</b>
 * graph of n modules, each feeding every later one (2^(n-2) paths, n (n - 1) / 2 connections). For each, in one JVM:
 * EMF's structural checks of the model (the anchor), and the timing analysis of the architecture with the requirement
 * and without it (the requirement's cost is the difference; the analysis without it, the response times, is the
 * second anchor); each with its growth against the same graph at the size before, divided by the growth of the model
 * (connections and modules; 1.0: linear). CPU time of this thread, median of 5 runs (wall in brackets).
 */
public final class LatencyPathsBench {

    static final int RUNS = 5;

    /** One measure: median CPU and wall time of this thread (ns). */
    record Measure(long cpu, long wall) {
        String text() {
            return String.format("%,.1f ms (%,.1f)", cpu / 1e6, wall / 1e6);
        }
    }

    interface Work {
        void run() throws Exception;
    }

    static Measure measure(Work work) throws Exception {
        long[] cpu = new long[RUNS];
        long[] wall = new long[RUNS];
        for (int i = 0; i < RUNS; i++) {
            ValidationBench.gc();
            long c0 = TimingBench.CPU.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            work.run();
            wall[i] = System.nanoTime() - t0;
            cpu[i] = TimingBench.CPU.getCurrentThreadCpuTime() - c0;
        }
        return new Measure(GenerationBench.median(cpu), GenerationBench.median(wall));
    }

    public static void main(String[] args) throws Exception {
        String specs = args.length > 0 ? args[0] : "chain:1000,chain:10000,chain:100000,ladder:200,ladder:2000,ladder:20000,dense:50,dense:100,dense:200";
        RsamlValidationSetup.init();
        Path dir = Files.createTempDirectory("rsaml-bench");
        run(dir, "chain", 100, null); // warm-up
        run(dir, "ladder", 100, null);
        run(dir, "dense", 20, null);
        System.out.println("Load average (1 min) at the start: " + ValidationBench.loadAverage());
        List<String> rows = new ArrayList<>();
        Row previous = null;
        for (String spec : specs.split(",")) {
            String[] kv = spec.trim().split(":");
            Row row = run(dir, kv[0], Integer.parseInt(kv[1]), previous != null && previous.kind.equals(kv[0]) ? previous : null);
            System.out.println(row.text);
            rows.add(row.text);
            previous = row;
        }
        Files.delete(dir);
        System.out.println("Load average (1 min) at the end: " + ValidationBench.loadAverage());
        System.out.println();
        System.out.println("| graph | modules | connections | paths | listed | EMF structural checks (the anchor) | analysis without the"
                + " requirement | analysis with it | the requirement (difference) | ÷ structural | growth ÷ growth of the model"
                + " (structural; the requirement) | verdict |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|");
        rows.forEach(System.out::println);
    }

    private record Row(String kind, long size, long structural, long requirement, String text) {
    }

    private static Row run(Path dir, String kind, int n, Row before) throws Exception {
        Architecture a = switch (kind) {
            case "chain" -> graph(n, false, false);
            case "ladder" -> graph(n, true, false);
            case "dense" -> graph(n, false, true);
            default -> throw new IllegalArgumentException("a graph is chain, ladder or dense, not " + kind);
        };
        Path file = dir.resolve(kind + "-" + n + ".rsaml");
        SyntheticArchitecture.write(a, file);
        LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
        Architecture loaded = model.architecture();
        int connections = loaded.getConnections().size();
        Measure structure = measure(() -> RsamlModelValidator.validateStructure(model));
        ArchitectureTiming[] with = new ArchitectureTiming[1];
        Measure analysis = measure(() -> with[0] = TimingAnalysis.analyse(loaded));
        List<LatencyRequirement> requirements = new ArrayList<>(loaded.getLatencyRequirements());
        loaded.getLatencyRequirements().clear();
        Measure without = measure(() -> TimingAnalysis.analyse(loaded));
        loaded.getLatencyRequirements().addAll(requirements);
        Files.delete(file);
        LatencyResult l = with[0].latencies().get(0);
        long requirement = Math.max(0, analysis.cpu() - without.cpu());
        long size = (long) n + connections;
        String growth = before == null ? ""
                : String.format("%.2f; %.2f", (double) structure.cpu() / before.structural / ((double) size / before.size),
                        (double) Math.max(1, requirement) / Math.max(1, before.requirement) / ((double) size / before.size));
        String text = String.format("| %s | %,d | %,d | %,d | %,d | %s | %s | %s | %,.1f ms | %.2f× | %s | %s |", kind, n, connections, l.paths(),
                l.pathBounds().size(), structure.text(), without.text(), analysis.text(), requirement / 1e6,
                (double) requirement / Math.max(1, structure.cpu()), growth, l.verdict());
        return new Row(kind, size, Math.max(1, structure.cpu()), requirement, text);
    }

    /**
     * n modules m0..m(n-1): m0 periodic (reads the sensor), the others sporadic reactions (at least 1 s apart, 1 µs each:
     * 100,000 of them use a tenth of the processor), the last driving the actuator; connected in a chain, a ladder (m0 to
     * m1 and m2, then each of a layer of two to both of the next; n - 1 odd or the last layer of one) or densely (each to
     * every later one).
     */
    static Architecture graph(int n, boolean ladder, boolean dense) {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Sensor sensor = f.createSensor();
        sensor.setName("scan");
        sensor.setPeriod(100);
        Actuator actuator = f.createActuator();
        actuator.setName("wheels");
        actuator.setPeriod(100);
        SyntheticArchitecture.Built built = SyntheticArchitecture.build("paths", ArchitectureCategory.HIERARCHICAL, n, (m, i, all) -> {
            if (i == 0) {
                m.setExecType(ExecutionType.PERIODIC);
                m.setPeriod(100);
                m.setExecDuration(1);
                m.getSensors().add(sensor);
            } else {
                m.setExecType(ExecutionType.SPORADIC);
                m.setPeriod(1000);
                m.setExecDuration(0.001);
            }
            if (i == all - 1) {
                m.getActuators().add(actuator);
            }
        });
        Architecture a = built.architecture();
        a.getSensors().add(sensor);
        a.getActuators().add(actuator);
        if (ladder || dense) {
            a.getConnections().clear();
            for (int i = 0; i < n; i++) {
                for (int j : successors(i, n, ladder)) {
                    SyntheticArchitecture.connect(a, built.outs().get(i), built.ins().get(j));
                }
            }
        }
        LatencyRequirement r = f.createLatencyRequirement();
        r.setName("scanToWheels");
        r.setSource(sensor);
        r.setTarget(actuator);
        r.setMaxLatency(1e9);
        a.getLatencyRequirements().add(r);
        return a;
    }

    /** The modules module i feeds. */
    private static List<Integer> successors(int i, int n, boolean ladder) {
        List<Integer> next = new ArrayList<>();
        if (!ladder) {
            for (int j = i + 1; j < n; j++) {
                next.add(j);
            }
            return next;
        }
        // layers: {0}, {1, 2}, {3, 4}, ...; the last module alone when n - 1 is odd
        int layerStart = i == 0 ? 1 : i % 2 == 1 ? i + 2 : i + 1;
        for (int j = layerStart; j < Math.min(n, layerStart + 2); j++) {
            next.add(j);
        }
        return next;
    }
}
