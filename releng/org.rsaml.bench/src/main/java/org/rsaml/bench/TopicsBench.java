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
import org.rsaml.model.Port;
import org.rsaml.model.support.RsamlTopics;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * RSA-28 (the ROS 2 topics ports name) at growing numbers of ports: {@link SyntheticArchitecture}'s chain of modules, each
 * output port naming a topic of its own that the entry port it is connected to names too (so every port names one), and one
 * module in 100 naming the topic of another, unconnected port (a finding). For each, in one JVM: EMF's structural checks of
 * the model (the anchor), RSA-28 alone over every port as the validation evaluates it (the topic table of the architecture
 * once, {@link RsamlTopics#table}, then each port's problem), and the whole validation; with the growth of RSA-28 against
 * the size before divided by the growth of the ports (1.0: linear). CPU time of this thread, median of 5 runs (wall in
 * brackets).
 */
public final class TopicsBench {

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.init();
        Path dir = Files.createTempDirectory("rsaml-bench");
        run(dir, 500, null); // warm-up
        System.out.println("Load average (1 min) at the start: " + ValidationBench.loadAverage());
        List<String> rows = new ArrayList<>();
        Row previous = null;
        for (String n : (args.length > 0 ? args[0] : "2000,20000,200000").split(",")) {
            previous = run(dir, Integer.parseInt(n.trim()) / 2, previous);
            System.out.println(previous.text);
            rows.add(previous.text);
        }
        Files.delete(dir);
        System.out.println("Load average (1 min) at the end: " + ValidationBench.loadAverage());
        System.out.println();
        System.out.println("| ports | connections | EMF structural checks (the anchor) | RSA-28 alone | ÷ structural | growth ÷ growth of the"
                + " ports (structural; RSA-28) | whole validation | ÷ structural | RSA-28 findings |");
        System.out.println("|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        rows.forEach(System.out::println);
    }

    private record Row(int ports, long structural, long rule, String text) {
    }

    private static Row run(Path dir, int modules, Row before) throws Exception {
        Architecture a = architecture(modules);
        Path file = dir.resolve("topics-" + modules + ".rsaml");
        SyntheticArchitecture.write(a, file);
        LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
        Architecture loaded = model.architecture();
        List<Port> ports = loaded.getLayers().stream().flatMap(l -> l.getModules().stream()).flatMap(m -> m.getPorts().stream()).toList();
        LatencyPathsBench.Measure structure = LatencyPathsBench.measure(() -> RsamlModelValidator.validateStructure(model));
        int[] problems = new int[1];
        LatencyPathsBench.Measure rule = LatencyPathsBench.measure(() -> {
            RsamlTopics.Table table = RsamlTopics.table(loaded);
            int found = 0;
            for (Port p : ports) {
                found += table.problem(p) == null ? 0 : 1;
            }
            problems[0] = found;
        });
        List<Finding> findings = new ArrayList<>();
        LatencyPathsBench.Measure validation = LatencyPathsBench.measure(() -> {
            findings.clear();
            findings.addAll(RsamlModelValidator.validate(model));
        });
        Files.delete(file);
        long reported = findings.stream().filter(f -> f.ruleId().equals("RSA-28")).count();
        int n = ports.size();
        String growth = before == null ? ""
                : String.format("%.2f; %.2f", (double) structure.cpu() / before.structural / ((double) n / before.ports),
                        (double) Math.max(1, rule.cpu()) / before.rule / ((double) n / before.ports));
        String text = String.format("| %,d | %,d | %s | %s | %.2f× | %s | %s | %.1f× | %,d%s |", n, loaded.getConnections().size(),
                structure.text(), rule.text(), (double) rule.cpu() / Math.max(1, structure.cpu()), growth, validation.text(),
                (double) validation.cpu() / Math.max(1, structure.cpu()), problems[0],
                reported == problems[0] ? "" : " (the validation reported " + reported + ")");
        return new Row(n, Math.max(1, structure.cpu()), Math.max(1, rule.cpu()), text);
    }

    /** {@code modules} modules in a chain; module i's output and the entry it feeds name topic t_i; every 100th module's entry t_0. */
    static Architecture architecture(int modules) {
        SyntheticArchitecture.Built built = SyntheticArchitecture.build("topics", ArchitectureCategory.HIERARCHICAL, modules, (m, i, all) -> {
        });
        for (int i = 0; i < modules; i++) {
            built.outs().get(i).setTopic("sensors/t_" + i);
            if (i > 0) {
                built.ins().get(i).setTopic(i % 100 == 50 ? "sensors/t_0" : "sensors/t_" + (i - 1));
            }
        }
        return built.architecture();
    }
}
