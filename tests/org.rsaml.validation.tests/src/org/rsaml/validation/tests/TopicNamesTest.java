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
}
