/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.Verdict;
import org.rsaml.report.ExitCodes;
import org.rsaml.report.FileResult;
import org.rsaml.report.Report;
import org.rsaml.report.TimingBatch;
import org.rsaml.report.TimingFailOn;
import org.rsaml.report.TimingJson;
import org.rsaml.tests.support.TestRepository;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** What {@code rsaml analyze} and the analyze goal run: every model analysed, its timelines, the outcome and the JSON document. */
class TimingBatchTest {

    private static final Path MEETS = Path.of("examples/mobile-base-latency.rsaml");
    private static final Path MISSES = Path.of("examples/mobile-base-latency-missed.rsaml");
    private static final Path MISSING = Path.of("examples/no-such-model.rsaml");

    /** What a front end is told, in order. */
    private static final class Heard implements TimingBatch.Listener {
        final List<String> analysed = new ArrayList<>();
        final List<Verdict> verdicts = new ArrayList<>();
        final List<String> unanalysable = new ArrayList<>();
        final List<Path> timelines = new ArrayList<>();
        final List<String> withoutTimeline = new ArrayList<>();
        final List<String> failures = new ArrayList<>();
        final List<String> lines = new ArrayList<>();

        @Override
        public void analysed(String displayName, ArchitectureTiming timing) {
            analysed.add(displayName);
            verdicts.add(timing.verdict());
        }

        @Override
        public void unanalysable(List<String> lines) {
            unanalysable.addAll(lines);
        }

        @Override
        public void timelineFailed(String line) {
            failures.add(line);
        }

        @Override
        public void timeline(Path file, String line) {
            timelines.add(file);
            lines.add(line);
        }

        @Override
        public void noTimeline(String displayName, String line) {
            withoutTimeline.add(displayName);
            lines.add(line);
        }
    }

    private static TimingBatch.Outcome run(List<Path> models, Path timeline, TimingFailOn failOn, Heard heard) {
        return TimingBatch.run(TestRepository.root(), models, timeline, failOn, heard);
    }

    @Test
    void aMissFailsTheRunAndAModelThatCannotBeReadCostsOnlyItself() {
        Heard heard = new Heard();
        TimingBatch.Outcome outcome = run(List.of(MISSING, MEETS, MISSES), null, TimingFailOn.MISS, heard);

        assertEquals(List.of("examples/mobile-base-latency.rsaml", "examples/mobile-base-latency-missed.rsaml"), heard.analysed,
                "both readable models are analysed, after the missing one");
        assertEquals(List.of(Verdict.MEETS, Verdict.MISSES), heard.verdicts, "the slow detector's requirement can be missed");
        assertTrue(heard.unanalysable.stream().anyMatch(l -> l.startsWith(MISSING + ":")), "the missing model is named: " + heard.unanalysable);
        assertEquals(List.of("examples/mobile-base-latency-missed.rsaml"), outcome.failing(), "only the missing requirement fails");
        assertEquals(List.of("examples/no-such-model.rsaml"), outcome.unanalysable(), "the model that cannot be read");
        assertEquals(ExitCodes.INPUT_ERROR, outcome.exitCode(), "a model that cannot be read makes the exit code 2");
        assertEquals("cannot read or analyse examples/no-such-model.rsaml; see the errors above", outcome.inputFailure(),
                "what the analyze goal fails the build with names the model that cannot be read");
        assertEquals("a deadline or a latency requirement can be missed in examples/mobile-base-latency-missed.rsaml (fail on miss)",
                outcome.verdictFailure(), "what the analyze goal fails the build with names the model that can miss");
        assertNull(outcome.outputFailure(), "no timeline was asked for, none failed");
    }

    @Test
    void theLevelDecidesWhatFails() {
        assertEquals(ExitCodes.FINDINGS, run(List.of(MEETS, MISSES), null, TimingFailOn.MISS, new Heard()).exitCode(),
                "a possible miss exits with 1");
        assertEquals(ExitCodes.OK, run(List.of(MEETS, MISSES), null, TimingFailOn.NEVER, new Heard()).exitCode(),
                "never: verdicts do not change the exit code");
        assertEquals(ExitCodes.OK, run(List.of(MEETS), null, TimingFailOn.NOT_ANALYSED, new Heard()).exitCode(),
                "a proven model passes even when anything not analysed would fail");
    }

    @Test
    void underNotAnalysedAMissIsStillWordedAsAMissAndTheUnprovenApart(@TempDir Path dir) throws Exception {
        String model = Files.readString(TestRepository.root().resolve(MEETS));
        String llf = model.replace("core=\"0\" modules", "core=\"0\" schedPolicy=\"LLF\" modules")
                .replace("core=\"1\" modules", "core=\"1\" schedPolicy=\"LLF\" modules");
        assertFalse(llf.equals(model), "both processors declared LLF, which the analysis does not decide");
        Files.writeString(dir.resolve("llf.rsaml"), llf);
        Files.copy(TestRepository.root().resolve(MISSES), dir.resolve("missed.rsaml"));

        TimingBatch.Outcome outcome = TimingBatch.run(dir, List.of(Path.of("llf.rsaml"), Path.of("missed.rsaml")), null,
                TimingFailOn.NOT_ANALYSED, new Heard());

        assertEquals(List.of("llf.rsaml (not analysed)", "missed.rsaml"), outcome.failing(), "both fail, in the order named");
        assertEquals("a deadline or a latency requirement can be missed in missed.rsaml; the timing is not proven in llf.rsaml (not analysed)"
                + " (fail on not-analysed)", outcome.verdictFailure(), "the miss is said as a miss, the unproven model apart");
    }

    @Test
    void aWitnessIsDrawnAsATimelineAndAModelWithoutOneIsSaid(@TempDir Path dir) throws Exception {
        Heard heard = new Heard();
        TimingBatch.Outcome outcome = run(List.of(MEETS, MISSES), dir.resolve("timeline"), TimingFailOn.MISS, heard);

        assertFalse(outcome.outputFailed(), "the timelines are written: " + heard.failures);
        assertEquals(List.of("examples/mobile-base-latency.rsaml"), heard.withoutTimeline, "the proven model has no witness to draw");
        assertFalse(heard.timelines.isEmpty(), "the missed requirement's worst path is drawn");
        for (Path file : heard.timelines) {
            assertEquals(dir.resolve("timeline"), file.getParent(), "timelines go into the directory asked for");
            assertTrue(Files.readString(file).contains("<svg"), file + " is an SVG image");
            assertTrue(heard.lines.contains("timeline written: " + dir.resolve("timeline").resolve(file.getFileName()).toString().replace('\\', '/')),
                    "each timeline is said, in the directory as named: " + heard.lines);
        }
        assertTrue(heard.lines.contains("examples/mobile-base-latency.rsaml: no timeline written: no missed deadline or exceeded latency"
                + " requirement has a witness"), "the model without a witness is said: " + heard.lines);
    }

    @Test
    void aTimelineThatCannotBeWrittenIsAnOutputError(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("taken"), "a file where the directory should be");
        Heard heard = new Heard();
        TimingBatch.Outcome outcome = run(List.of(MISSES), dir.resolve("taken"), TimingFailOn.MISS, heard);

        assertTrue(outcome.outputFailed(), "the timeline could not be written");
        assertEquals(1, heard.failures.size(), "one line says so: " + heard.failures);
        assertTrue(heard.failures.get(0).contains("error: cannot write the timeline"), heard.failures.get(0));
        assertEquals(ExitCodes.INPUT_ERROR, outcome.exitCode(), "output that cannot be written makes the exit code 2");
        assertEquals("cannot write the timeline into " + dir.resolve("taken").toString().replace('\\', '/') + "; see the errors above",
                outcome.outputFailure(), "the run's failure names the directory");
    }

    @Test
    void aTimingAnalysisThatCannotBeWrittenIsSaidInOneLine(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("taken"), "a file where the directory should be");
        TimingJson.Document json = TimingBatch.run(TestRepository.root(), List.of(MEETS),
                new TimingBatch.Request(null, TimingFailOn.MISS, true, false), new Heard()).json();
        String failure = json.writeTo(dir, Path.of("taken/timing.json"));
        assertTrue(failure != null && failure.startsWith("taken/timing.json: error: cannot write the timing analysis: "),
                "the line names the file and says why: " + failure);
        assertNull(json.writeTo(dir, Path.of("timing.json")), "a file that can be written is written");
        assertTrue(Files.readString(dir.resolve("timing.json")).startsWith("["), "the document is written");
    }

    @Test
    void oneRunGivesTheVerdictsTimelinesJsonAndFindingsOfEachModelOnce(@TempDir Path dir) {
        Heard heard = new Heard();
        TimingBatch.Outcome outcome = TimingBatch.run(TestRepository.root(), List.of(MISSING, MEETS, MISSES),
                new TimingBatch.Request(dir.resolve("timeline"), TimingFailOn.MISS, true, true), heard);

        assertEquals(List.of("examples/mobile-base-latency.rsaml", "examples/mobile-base-latency-missed.rsaml"), heard.analysed,
                "each readable model is analysed and told once, whatever the run writes");
        assertFalse(heard.timelines.isEmpty(), "the missed requirement's worst path is drawn in the same run");
        JsonArray document = JsonParser.parseString(outcome.json().text()).getAsJsonArray();
        assertEquals(heard.analysed.size(), document.size(), "one JSON entry per analysed model: " + outcome.json().text());
        Report findings = outcome.findings();
        assertEquals(List.of(MISSING.toString(), MEETS.toString(), MISSES.toString()),
                findings.results().stream().map(FileResult::file).toList(), "one result per model, in the order named");
        assertFalse(findings.results().get(0).readable(), "the missing model is a result that could not be read");
        assertEquals(List.of(), findings.results().get(1).findings(), "the proven model has no timing finding");
        List<String> failing = findings.results().stream().filter(r -> r.findings().stream().anyMatch(findings::fails))
                .map(FileResult::file).toList();
        assertEquals(outcome.failing(), failing, "the findings fail the same models as the verdicts");
        assertEquals(ExitCodes.INPUT_ERROR, outcome.exitCode(), "a model that cannot be read makes the exit code 2");
    }

    @Test
    void withoutFindingsOrJsonTheRunCollectsNeither() {
        TimingBatch.Outcome outcome = run(List.of(MEETS), null, TimingFailOn.MISS, new Heard());

        assertNull(outcome.json(), "no JSON document unless asked for");
        assertNull(outcome.findings(), "no findings' report unless asked for");
    }

    @Test
    void theJsonDocumentHasAnEntryPerAnalysedModel() {
        Heard heard = new Heard();
        TimingJson.Document json = TimingBatch.run(TestRepository.root(), List.of(MEETS, MISSES),
                new TimingBatch.Request(null, TimingFailOn.MISS, true, false), heard).json();

        JsonArray document = JsonParser.parseString(json.text()).getAsJsonArray();
        assertEquals(heard.analysed.size(), document.size(), "one entry per analysed model: " + json.text());
        for (int i = 0; i < document.size(); i++) {
            JsonObject entry = document.get(i).getAsJsonObject();
            assertEquals(heard.analysed.get(i), entry.get("file").getAsString(), "entries in the order the models were analysed");
            assertEquals(heard.verdicts.get(i) == Verdict.MEETS ? "meets" : "misses", entry.get("verdict").getAsString(),
                    "the entry's verdict is the analysis's");
        }
    }
}
