/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.Verdict;
import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.TimingMode;
import org.rsaml.report.FindingFailOn;
import org.rsaml.report.ModelBatch;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.Report;
import org.rsaml.report.TimingBatch;
import org.rsaml.report.TimingFailOn;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Severity;

/** The levels a user writes for {@code --fail-on} and {@code failOn}, and what each makes fail. */
class FailOnTest {

    @Test
    void findingLevelsAreReadInAnyCaseAndMapToTheLowestFailingSeverity() {
        assertEquals(Severity.ERROR, FindingFailOn.parse("error").threshold(), "error: only errors fail");
        assertEquals(Severity.WARNING, FindingFailOn.parse(" Warning ").threshold(), "warning, any case and blanks: warnings fail too");
        assertNull(FindingFailOn.parse("NEVER").threshold(), "never: no severity fails");
        assertEquals("warning", FindingFailOn.WARNING.toString(), "a level prints as the user writes it");
    }

    @Test
    void anUnknownFindingLevelIsRefusedNamingTheValueAndTheLevels() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FindingFailOn.parse("warnings"),
                "an unknown finding level is refused");
        assertEquals("'warnings' is not a level; it is one of error, warning, never", e.getMessage(),
                "the message says what was written and what can be");
        assertThrows(IllegalArgumentException.class, () -> FindingFailOn.parse(null), "no level is not a level");
    }

    @Test
    void missFailsOnlyAMiss() {
        TimingFailOn miss = TimingFailOn.parse("miss");
        assertTrue(miss.fails(Verdict.MISSES), "a possible miss fails");
        assertFalse(miss.fails(Verdict.NOT_ANALYSED), "what is not analysed does not fail by default");
        assertFalse(miss.fails(Verdict.MEETS), "a proven model passes");
        assertEquals(Severity.ERROR, miss.findingThreshold(), "in SARIF and JUnit, the timing rules' errors (the misses) fail");
        assertEquals(Severity.ERROR, miss.shown(Verdict.MISSES), "a verdict that fails the run is shown as an error");
        assertEquals(Severity.WARNING, miss.shown(Verdict.NOT_ANALYSED), "short of meets without failing: a warning");
        assertEquals(Severity.INFO, miss.shown(Verdict.MEETS), "a proven model: information");
        assertEquals(Severity.WARNING, TimingFailOn.NEVER.shown(Verdict.MISSES), "a miss that fails nothing is a warning");
    }

    @Test
    void notAnalysedFailsAllButAProvenModel() {
        TimingFailOn strict = TimingFailOn.parse(" Not-Analysed");
        assertTrue(strict.fails(Verdict.MISSES), "a possible miss fails");
        assertTrue(strict.fails(Verdict.NOT_ANALYSED), "what is not analysed fails");
        assertFalse(strict.fails(Verdict.MEETS), "a proven model passes");
        assertEquals(Severity.WARNING, strict.findingThreshold(), "RSA-24, a warning, fails the reports too");
    }

    @Test
    void neverFailsNothingAndUnknownTimingLevelsAreNone() {
        TimingFailOn never = TimingFailOn.parse("never");
        for (Verdict verdict : Verdict.values()) {
            assertFalse(never.fails(verdict), "never fails no verdict, not " + verdict);
        }
        assertNull(never.findingThreshold(), "never: no finding fails the reports");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TimingFailOn.parse("misses"),
                "an unknown timing level is refused");
        assertEquals("'misses' is not a level; it is one of miss, not-analysed, never", e.getMessage(),
                "a level that does not exist is refused, naming the levels there are");
        assertEquals("not-analysed", TimingFailOn.NOT_ANALYSED.toString(), "a level prints as the user writes it");
    }

    @Test
    void aFailedRunNamesTheLevelThatFailedItAlikeForFindingsAndVerdicts() {
        Path exp2 = Path.of("examples/exp2-defects.rsaml");
        Report errors = ModelBatch.validate(TestRepository.root(), List.of(exp2), FindingFailOn.parse("error").threshold());
        assertEquals("validation failed: " + errors.summary() + " (fail on error)", errors.failure(),
                "what the validate goal fails the build with: the summary and the level, as the user wrote it");
        Report warnings = ModelBatch.validate(TestRepository.root(), List.of(exp2), FindingFailOn.parse("warning").threshold());
        assertTrue(warnings.failure().endsWith(" (fail on warning)"), "the level that failed the run: " + warnings.failure());
        assertNull(ModelBatch.validate(TestRepository.root(), List.of(exp2), FindingFailOn.parse("never").threshold()).failure(),
                "never: the findings fail nothing");
        Report unreadable = ModelBatch.validate(TestRepository.root(), List.of(exp2, Path.of("examples/no-such-model.rsaml")), null);
        assertEquals("could not read 1 model file; see the errors above", unreadable.failure(),
                "a model that cannot be read fails the run whatever the level, and the failure says so");

        TimingBatch.Listener quiet = new TimingBatch.Listener() {
            @Override
            public void analysed(String displayName, ArchitectureTiming timing) {
            }

            @Override
            public void unanalysable(List<String> lines) {
            }

            @Override
            public void timelineFailed(String line) {
            }

            @Override
            public void timeline(Path file, String line) {
            }

            @Override
            public void noTimeline(String displayName, String line) {
            }
        };
        String missed = TimingBatch.run(TestRepository.root(), List.of(Path.of("examples/mobile-base-latency-missed.rsaml")), null,
                TimingFailOn.parse("not-analysed"), quiet).verdictFailure();
        assertEquals("a deadline or a latency requirement can be missed in examples/mobile-base-latency-missed.rsaml (fail on not-analysed)",
                missed, "under not-analysed a miss is still worded as a miss, and the failure names its level as validate's does");
    }

    @Test
    void everyChoiceAUserWritesIsReadAndRefusedAlike() {
        assertEquals(ReportFormat.SARIF, ReportFormat.parse(" SARIF "), "a report format, any case and blanks");
        IllegalArgumentException format = assertThrows(IllegalArgumentException.class, () -> ReportFormat.parse(null),
                "no format is refused");
        assertEquals("'null' is not a report format; it is one of text, json, sarif, junit", format.getMessage(),
                "no format is refused as levels are, naming the formats there are");
        IllegalArgumentException view = assertThrows(IllegalArgumentException.class, () -> DiagramView.parse("deployment"),
                "an unknown view is refused");
        assertEquals("'deployment' is not a view; it is one of architecture, mission", view.getMessage(),
                "a diagram's view is refused in the same words");
        assertEquals(TimingMode.OFF, TimingMode.parse("Off"), "a timing mode, any case");
    }
}
