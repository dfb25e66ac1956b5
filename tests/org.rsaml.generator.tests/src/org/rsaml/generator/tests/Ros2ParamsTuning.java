/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Release;

/**
 * The edits {@link Ros2LaunchTest} makes to a generated package's parameters file before the build
 * of {@link Ros2LaunchTest#TUNED}, as a user tunes the system without generating again: a period
 * doubled and a topic's reliability flipped, each of which the run must then show in effect.
 */
final class Ros2ParamsTuning {
    private Ros2ParamsTuning() {
    }

    /**
     * Doubles, in the package's parameters file, the period of the longest release of a module
     * released only by it: the node must run at the file's period. The file holds the model's value
     * first, in the model's unit.
     */
    static void tune(Path root, ExecutionPlan plan, Map<Release, Long> periodsNs) throws Exception {
        Release r = plan.releases().stream().filter(x -> x.module().releases().size() == 1)
                .max(java.util.Comparator.comparingLong(Release::periodNs)).orElseThrow();
        String node = Ros2Test.nodes(root.getParent()).get(r.module().qualifiedName());
        Path file = root.resolve("config/" + root.getFileName() + ".params.yaml");
        List<String> lines = new ArrayList<>(Files.readAllLines(file));
        int section = lines.indexOf(node + ":");
        assertTrue(section >= 0, "no section for node " + node + " in " + file + ":\n" + String.join("\n", lines));
        Pattern period = Pattern.compile("(\\s+[\\w.]+\\.period_(ns|us|ms|s): )([\\d.]+)");
        for (int i = section + 1; i < lines.size() && lines.get(i).startsWith(" "); i++) {
            Matcher m = period.matcher(lines.get(i));
            if (m.matches()) {
                long unitNs = switch (m.group(2)) { case "ns" -> 1L; case "us" -> 1_000L; case "ms" -> 1_000_000L; default -> 1_000_000_000L; };
                BigDecimal value = new BigDecimal(m.group(3));
                assertEquals(r.periodNs(), value.multiply(BigDecimal.valueOf(unitNs)).longValueExact(), "the parameters file's " + lines.get(i).strip()
                        + " is not the model's period of " + r.label());
                lines.set(i, m.group(1) + value.multiply(BigDecimal.valueOf(2)).toPlainString());
                Files.write(file, lines);
                periodsNs.put(r, 2 * r.periodNs());
                return;
            }
        }
        fail("no period parameter of " + r.label() + " in the section of node " + node + " in " + file);
    }

    /**
     * Flips, in the package's parameters file, the reliability of a topic the model names, by the
     * model's name: its publisher's from best effort to reliable, or else its subscriptions' from
     * reliable to best effort (either way the publisher still reaches its subscribers). Returns the
     * endpoint type ROS 2 reports the change on and the reliability it must report.
     */
    static String[] tuneQos(Path root, String topic) throws Exception {
        Path file = root.resolve("config/" + root.getFileName() + ".params.yaml");
        String text = Files.readString(file);
        String publisher = "qos_overrides." + topic + ".publisher.reliability: ";
        String subscription = "qos_overrides." + topic + ".subscription.reliability: ";
        String[] change = text.contains(publisher + "best_effort") ? new String[] {publisher + "best_effort", publisher + "reliable", "PUBLISHER", "RELIABLE"}
                : new String[] {subscription + "reliable", subscription + "best_effort", "SUBSCRIPTION", "BEST_EFFORT"};
        assertTrue(text.contains(change[0]), "the parameters file has no " + change[0] + ":\n" + text);
        Files.writeString(file, text.replace(change[0], change[1]));
        return new String[] {change[2], change[3]};
    }
}
