/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.report.TimingJson;
import org.rsaml.validation.ModelLoader;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The JSON of a latency requirement with more paths than can be listed: its {@code everyPath} stays within the stages
 * the list holds (and so within a size a user can open), and its count says it is at least what it shows.
 */
class TimingJsonPathsTest {

    /**
     * A ladder of {@code rungs} pairs of reacting modules between a timed module and the actuator's: 2^rungs paths of
     * rungs + 2 stages each.
     */
    private static String ladder(int rungs) {
        String port = "//@layers[name='l']/@modules[name='%s']/@ports[name='%s']";
        StringBuilder modules = new StringBuilder("<modules name=\"e\" type=\"realTime\" period=\"100.0\" execDuration=\"1.0\""
                + " execType=\"periodic\" sensors=\"//@sensors[name='s']\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\""
                + " dataType=\"numeric\"/></modules>\n");
        StringBuilder connections = new StringBuilder();
        String[] before = { "e" };
        for (int i = 0; i <= rungs; i++) {
            String[] rung = i < rungs ? new String[] { "a" + i, "b" + i } : new String[] { "act" };
            for (String m : rung) {
                modules.append("<modules name=\"").append(m).append("\" execDuration=\"0.01\" execType=\"sporadic\" period=\"")
                        .append(m.startsWith("a") ? "1000.0" : "900.0").append('"')
                        .append(i == rungs ? " actuators=\"//@actuators[name='t']\"" : "")
                        .append("><ports xsi:type=\"rsaml:EntryPort\" name=\"i\" dataType=\"numeric\"/>")
                        .append("<ports xsi:type=\"rsaml:OutputPort\" name=\"o\" dataType=\"numeric\"/></modules>\n");
                for (String from : before) {
                    connections.append("<connections source=\"").append(port.formatted(from, "o")).append("\" target=\"")
                            .append(port.formatted(m, "i")).append("\"/>\n");
                }
            }
            before = rung;
        }
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\" xmlns:xmi=\"http://www.omg.org/XMI\""
                + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"ladder\""
                + " declaredLayers=\"1\">\n<layers name=\"l\" level=\"0\" timeUnit=\"ms\">\n" + modules + "</layers>\n" + connections
                + "<sensors name=\"s\" timeUnit=\"ms\" period=\"100.0\"/>\n<actuators name=\"t\" timeUnit=\"ms\" period=\"100.0\"/>\n"
                + "<latencyRequirements name=\"req\" timeUnit=\"ms\" source=\"//@sensors[name='s']\" target=\"//@actuators[name='t']\""
                + " maxLatency=\"1000000.0\"/>\n</rsaml:Architecture>\n";
    }

    @Test
    void aRequirementOfMorePathsThanListedWritesAtMostTheListsStagesAndSaysItsCountIsALowerBound(@TempDir Path tmp) throws Exception {
        Path file = tmp.resolve("ladder.rsaml");
        Files.writeString(file, ladder(200));
        TimingJson.Document document = new TimingJson.Document();
        document.add("ladder.rsaml", TimingAnalysis.analyse(ModelLoader.load(file, "ladder.rsaml").architecture()));
        String text = document.text();
        JsonObject req = JsonParser.parseString(text).getAsJsonArray().get(0).getAsJsonObject().getAsJsonArray("latencies").get(0)
                .getAsJsonObject();
        assertEquals(Integer.MAX_VALUE, req.get("paths").getAsInt(), "2^200 paths: the count stops at its largest");
        assertTrue(req.get("pathsAtLeast").getAsBoolean(), "and says it stands for at least that many: " + req.get("pathsAtLeast"));
        JsonArray every = req.getAsJsonArray("everyPath");
        long stages = 0;
        for (JsonElement path : every) {
            stages += path.getAsJsonObject().getAsJsonArray("stages").size();
        }
        assertEquals(LatencyResult.MAX_LISTED_STAGES / 202, every.size(), "as many paths of 202 stages as the list holds");
        assertEquals(every.size(), req.get("pathsListed").getAsInt(), "pathsListed counts everyPath");
        assertTrue(stages <= LatencyResult.MAX_LISTED_STAGES, "within the list's stages: " + stages);
        assertTrue(req.get("pathsNotListed").getAsString().contains("listed are the longest of those followed, and the worst"),
                "the JSON says which paths it lists: " + req.get("pathsNotListed"));
        // each stage is written with its activation sentence, some 300 bytes indented: the list bounds the document
        assertTrue(text.length() < 400L * LatencyResult.MAX_LISTED_STAGES, "the document stays within some 40 MB: " + text.length());
    }
}
