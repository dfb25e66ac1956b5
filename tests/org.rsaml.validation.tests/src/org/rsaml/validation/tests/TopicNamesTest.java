/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
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
}
