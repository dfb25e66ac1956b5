/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;

import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Port;
import org.rsaml.model.support.RsamlNames;
import org.rsaml.model.support.RsamlTopics;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.Rule;
import org.rsaml.validation.RsamlModelValidator;

/** RSA-28 (ROS 2 topic names) on the whole architecture: each port's topic checked against a table read once. */
class TopicNamesTest {

    private static String model(int modules, String... extra) {
        StringBuilder b = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
                + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
                + " xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"robot\" declaredLayers=\"1\">\n  <layers name=\"base\" level=\"0\">\n");
        for (int i = 0; i < modules; i++) {
            b.append("    <modules name=\"m").append(i).append("\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\"")
                    .append(" name=\"o\" dataType=\"numeric\" topic=\"t").append(i).append("\"/></modules>\n");
        }
        for (String e : extra) {
            b.append("    ").append(e).append('\n');
        }
        return b.append("  </layers>\n</rsaml:Architecture>\n").toString();
    }

    private static List<String> findings(Path tmp, String name, String text) throws Exception {
        Path file = tmp.resolve(name);
        Files.writeString(file, text);
        return RsamlModelValidator.validate(file).stream().filter(f -> f.ruleId().equals("RSA-28"))
                .map(f -> f.qualifiedName() + ": " + f.message()).sorted().toList();
    }

    @Test
    void twentyThousandPortsNamingTopicsAreCheckedAndTheOneClashAmongThemFound(@TempDir Path tmp) throws Exception {
        List<String> found = findings(tmp, "topics.rsaml", model(20_000,
                "<modules name=\"late\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"/t17\"/></modules>"));
        assertEquals(List.of(
                "robot/base/late/o: Output port 'o' of module 'late' names the topic '/t17', as output port 'o' of module 'm17' does,"
                        + " which it is not connected to: ROS 2 would connect them",
                "robot/base/m17/o: Output port 'o' of module 'm17' names the topic 't17', as output port 'o' of module 'late' does,"
                        + " which it is not connected to: ROS 2 would connect them"),
                found, "only the two ports naming one topic without a connection");
    }

    @Test
    void aNamedTopicThatIsAnotherPortsDefaultTopicIsFoundNamingBothPorts(@TempDir Path tmp) throws Exception {
        List<String> found = findings(tmp, "clash.rsaml", model(0,
                "<modules name=\"odometry\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"pose\""
                        + " dataType=\"structured\" messageType=\"geometry_msgs/msg/Pose2D\"/></modules>",
                "<modules name=\"detector\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\""
                        + " name=\"speedLimit\" dataType=\"numeric\" topic=\"base/odometry/pose\"/></modules>"));
        assertEquals(List.of("robot/base/detector/speedLimit: Output port 'speedLimit' of module 'detector' names the topic"
                + " 'base/odometry/pose', which is the default topic of output port 'pose' of module 'odometry' (base/odometry/pose),"
                + " which it is not connected to: ROS 2 would connect them; name another topic, or connect the ports"), found,
                "the generated nodes would publish a Float64 and a Pose2D on one topic");
    }

    @Test
    void aTopicRos2UsesItselfOrTooLongForRos2IsAFinding(@TempDir Path tmp) throws Exception {
        String tooLong = "a/" + "b".repeat(245);
        String justFits = "c/" + "d".repeat(244);
        List<String> found = findings(tmp, "own.rsaml", model(0,
                "<modules name=\"a\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"/rosout\"/></modules>",
                "<modules name=\"b\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"parameter_events\"/></modules>",
                "<modules name=\"c\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"" + tooLong + "\"/></modules>",
                "<modules name=\"d\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"" + justFits + "\"/></modules>"));
        assertEquals(List.of(
                "robot/base/a/o: Output port 'o' of module 'a' names the topic '/rosout', which ROS 2 itself uses (every node publishes"
                        + " its log messages there as rcl_interfaces/msg/Log): choose another name",
                "robot/base/b/o: Output port 'o' of module 'b' names the topic 'parameter_events', which ROS 2 itself uses (every node"
                        + " publishes its parameter changes there as rcl_interfaces/msg/ParameterEvent): choose another name",
                "robot/base/c/o: Output port 'o' of module 'c' names the topic '" + tooLong + "', whose full name /a/bbbbbbbbbbbbbbbbb..."
                        + " has 248 characters, more than the 247 ROS 2 takes (RMW_TOPIC_MAX_NAME_LENGTH): shorten it"),
                found, "a full name of 247 characters is taken");
    }

    @Test
    void aTopicOnWhichAManagedNodePublishesItsTransitionsIsAFinding(@TempDir Path tmp) throws Exception {
        List<String> found = findings(tmp, "lifecycle.rsaml", model(0,
                "<modules name=\"lidarDriver\" lifecycle=\"managed\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\""
                        + " name=\"scan\" dataType=\"numeric\" topic=\"scan\"/></modules>",
                "<modules name=\"plain\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"base_plain/transition_event\"/></modules>",
                "<modules name=\"spy\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"/base_lidar_driver/transition_event\"/></modules>"));
        assertEquals(List.of("robot/base/spy/o: Output port 'o' of module 'spy' names the topic '/base_lidar_driver/transition_event', on which"
                + " ROS 2 publishes the transitions of the managed node of module 'lidarDriver' (lifecycle_msgs/msg/TransitionEvent):"
                + " choose another name"), found,
                "the managed node base_lidar_driver publishes lifecycle_msgs/msg/TransitionEvent there; the plain node base_plain has no such topic");
    }

    @Test
    void theTransitionTopicOfAManagedNodeRenamedForAClashIsCheckedUnderItsNewName(@TempDir Path tmp) throws Exception {
        // base + aB and base_a + b both make the node name base_a_b: the later layer's node is base_a_b_2 in the generated code.
        List<String> found = findings(tmp, "renamed.rsaml", model(0,
                "<modules name=\"aB\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"base_a_b/transition_event\"/></modules>",
                "<modules name=\"spy\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"base_a_b_2/transition_event\"/></modules>",
                "</layers>\n  <layers name=\"base_a\" level=\"1\">",
                "<modules name=\"b\" lifecycle=\"managed\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\""
                        + " name=\"o\" dataType=\"numeric\" topic=\"b_out\"/></modules>"));
        assertEquals(List.of("robot/base/spy/o: Output port 'o' of module 'spy' names the topic 'base_a_b_2/transition_event', on which"
                + " ROS 2 publishes the transitions of the managed node of module 'b' (lifecycle_msgs/msg/TransitionEvent):"
                + " choose another name"), found,
                "the managed node of module 'b' is base_a_b_2 in the generated code (RsamlNames.RosNodes), so its transitions are on"
                + " base_a_b_2/transition_event; base_a_b is the plain node of module 'aB', which has no such topic");
    }

    @Test
    void aDefaultTopicTooLongForRos2IsAFindingOnThePortWhoseDefaultItIs(@TempDir Path tmp) throws Exception {
        // <layer>/<node>/<port>: "base/" (5) + node + "/o" (2), with the leading slash: 8 + node
        String longNode = "n".repeat(240);
        String fits = "f".repeat(239);
        List<String> found = findings(tmp, "default.rsaml", model(0,
                "<modules name=\"" + longNode + "\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\"/></modules>",
                "<modules name=\"reader\"><ports xsi:type=\"rsaml:EntryPort\" name=\"i\" dataType=\"numeric\"/></modules>",
                "<modules name=\"" + fits + "\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\"/></modules>",
                "<modules name=\"" + longNode + "x\" execType=\"periodic\" period=\"100.0\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                        + " dataType=\"numeric\" topic=\"short\"/></modules>",
                "</layers>\n  <connections source=\"//@layers[name='base']/@modules[name='" + longNode + "']/@ports[name='o']\""
                        + " target=\"//@layers[name='base']/@modules[name='reader']/@ports[name='i']\"/>\n  <layers name=\"unused\" level=\"1\">"));
        assertEquals(List.of("robot/base/" + longNode + "/o: Output port 'o' of module '" + longNode + "' names no topic, and its default topic 'base/"
                + longNode + "/o' (<layer>/<node>/<port>), whose full name /base/nnnnnnnnnnnnnn... has 248 characters, more than the 247"
                + " ROS 2 takes (RMW_TOPIC_MAX_NAME_LENGTH): name a shorter topic (topic) or shorten the layer's, module's or port's name"), found,
                "a default topic of 248 characters is a finding once, on its publisher (not on the entry port connected to it); one of 247"
                + " is taken, and a port that names a short topic has no default");
    }

    @Test
    void theValidationFindsWhatTheWholeTableFindsThoughItReadsTheTableOnlyForPortsThatNeedIt(@TempDir Path tmp) throws Exception {
        // Names near ROS 2's limit (full name "/" + layer + "/" + node + "/" + port of at most 247 characters), clashing ones
        // (renamed with a suffix _2, _3 in the generated code), unnamed ones, layers named as the generator's folders, ports naming
        // topics or not, connected or not: a port that names no topic and whose default is short is answered without the table.
        Random random = new Random(24);
        int found = 0;
        for (int round = 0; round < 60; round++) {
            Path file = tmp.resolve("random" + round + ".rsaml");
            Files.writeString(file, randomModel(random));
            LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
            Map<String, String> validation = new TreeMap<>();
            // by element (the positions of the findings: their names do not tell the ports apart)
            for (Diagnostic d : RsamlModelValidator.diagnose(model.architecture()).getChildren()) {
                if (((Rule) d.getData().get(1)).id().equals("RSA-28")) {
                    validation.put(where((Port) d.getData().get(0)), (String) d.getData().get(2));
                }
            }
            RsamlTopics.Table table = RsamlTopics.table(model.architecture());
            Map<String, String> wholeTable = new TreeMap<>();
            for (Layer l : model.architecture().getLayers()) {
                for (Module m : l.getModules()) {
                    for (Port p : m.getPorts()) {
                        String problem = table.problem(p);
                        if (problem != null) {
                            wholeTable.put(where(p), problem);
                        }
                    }
                }
            }
            assertEquals(wholeTable.keySet(), validation.keySet(), "round " + round + ": the ports with an RSA-28 finding");
            for (Map.Entry<String, String> e : wholeTable.entrySet()) {
                assertTrue(validation.get(e.getKey()).endsWith(e.getValue()), "round " + round + ": " + validation.get(e.getKey()));
            }
            found += validation.size();
        }
        assertTrue(found > 20, "the random models have findings to compare: " + found);
    }

    @Test
    void aNameInSnakeCaseIsAtMostTwiceAsLongPlusNine() {
        // the bound by which RSA-28 leaves out the ports whose default topic is short without putting their names in snake case
        Random random = new Random(28);
        String letters = "aZ09_ -é.xY";
        List<String> names = new ArrayList<>(List.of("", "class", "CON", "9", "_", "aB".repeat(40), "A1b2C3"));
        for (int i = 0; i < 20_000; i++) {
            StringBuilder b = new StringBuilder();
            for (int k = random.nextInt(12); k > 0; k--) {
                b.append(letters.charAt(random.nextInt(letters.length())));
            }
            names.add(b.toString());
        }
        for (String name : names) {
            assertTrue(RsamlNames.snake(name).length() <= 2 * name.length() + 9, name + " -> " + RsamlNames.snake(name));
        }
    }

    /** Where a port is, by index (the names are long): layer/module/port. */
    private static String where(Port p) {
        Module m = p.getModule();
        Layer l = m.getLayer();
        return l.getArchitecture().getLayers().indexOf(l) + "/" + l.getModules().indexOf(m) + "/" + m.getPorts().indexOf(p);
    }

    /** A model of two layers and a few modules with names near the limit, clashing, unnamed; topics named or not; a few connections. */
    private static String randomModel(Random random) {
        String[] layerNames = { "base", "src", "msg", null, "l".repeat(4) };
        StringBuilder b = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
                + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
                + " xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"robot\" declaredLayers=\"2\">\n");
        List<String> outputs = new ArrayList<>();
        List<String> entries = new ArrayList<>();
        for (int l = 0; l < 2; l++) {
            String layer = layerNames[random.nextInt(layerNames.length)];
            b.append("  <layers").append(layer == null ? "" : " name=\"" + layer + "\"").append(" level=\"").append(l).append("\">\n");
            int modules = 2 + random.nextInt(6);
            for (int m = 0; m < modules; m++) {
                String module = switch (random.nextInt(5)) {
                    case 0 -> null;
                    case 1 -> "n".repeat(236 + random.nextInt(4));
                    case 2 -> "aB".repeat(56 + random.nextInt(8)); // a_b_a_b...: snake case nearly doubles it
                    default -> "n".repeat(230 + random.nextInt(12));
                };
                b.append("    <modules").append(module == null ? "" : " name=\"" + module + "\"").append(" execType=\"periodic\" period=\"100.0\">");
                int ports = 1 + random.nextInt(3);
                for (int p = 0; p < ports; p++) {
                    boolean output = random.nextBoolean();
                    String port = random.nextInt(5) == 0 ? null : random.nextBoolean() ? "o" : "class";
                    String topic = switch (random.nextInt(6)) {
                        case 0 -> "t" + random.nextInt(3);
                        case 1 -> "base/" + "n".repeat(236) + "/o";
                        default -> null;
                    };
                    b.append("<ports xsi:type=\"rsaml:").append(output ? "OutputPort" : "EntryPort").append('"')
                            .append(port == null ? "" : " name=\"" + port + "\"").append(" dataType=\"numeric\"")
                            .append(topic == null ? "" : " topic=\"" + topic + "\"").append("/>");
                    (output ? outputs : entries).add("//@layers." + l + "/@modules." + m + "/@ports." + p);
                }
                b.append("</modules>\n");
            }
            b.append("  </layers>\n");
        }
        for (int c = 0; c < 3 && !outputs.isEmpty() && !entries.isEmpty(); c++) {
            b.append("  <connections source=\"").append(outputs.get(random.nextInt(outputs.size()))).append("\" target=\"")
                    .append(entries.get(random.nextInt(entries.size()))).append("\"/>\n");
        }
        return b.append("</rsaml:Architecture>\n").toString();
    }
}
