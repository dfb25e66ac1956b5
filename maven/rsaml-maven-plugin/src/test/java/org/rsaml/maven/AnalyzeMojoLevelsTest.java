/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.logging.Log;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.tests.support.TestRepository;

/**
 * The analyze goal's log levels, on real models: a verdict that fails the build is logged as an error, one short of
 * "meets" that does not fail it (a miss with {@code failOnMiss} false, a model not analysed under {@code failOn} miss)
 * as a warning, a proven one as information; and the build fails with the batch's own words. (The invoker tests
 * analyze-missed and analyze-unanalysable run the failing cases in a real build.)
 */
class AnalyzeMojoLevelsTest {

    @TempDir
    Path project;

    /** What the goal logged, one entry a line, as "LEVEL text". */
    private static final class Recorded implements Log {
        final List<String> lines = new ArrayList<>();

        private void add(String level, CharSequence text) {
            lines.add(level + " " + text);
        }

        List<String> at(String level) {
            return lines.stream().filter(l -> l.startsWith(level + " ")).toList();
        }

        @Override public boolean isDebugEnabled() { return false; }
        @Override public void debug(CharSequence c) { }
        @Override public void debug(CharSequence c, Throwable t) { }
        @Override public void debug(Throwable t) { }
        @Override public boolean isInfoEnabled() { return true; }
        @Override public void info(CharSequence c) { add("INFO", c); }
        @Override public void info(CharSequence c, Throwable t) { add("INFO", c); }
        @Override public void info(Throwable t) { add("INFO", t.toString()); }
        @Override public boolean isWarnEnabled() { return true; }
        @Override public void warn(CharSequence c) { add("WARNING", c); }
        @Override public void warn(CharSequence c, Throwable t) { add("WARNING", c); }
        @Override public void warn(Throwable t) { add("WARNING", t.toString()); }
        @Override public boolean isErrorEnabled() { return true; }
        @Override public void error(CharSequence c) { add("ERROR", c); }
        @Override public void error(CharSequence c, Throwable t) { add("ERROR", c); }
        @Override public void error(Throwable t) { add("ERROR", t.toString()); }
    }

    private AnalyzeMojo goal(String model, boolean failOnMiss, String failOn, Recorded log) {
        AnalyzeMojo goal = new AnalyzeMojo();
        goal.setLog(log);
        goal.baseDirectory = project.toFile();
        goal.models = List.of(new File(project.toFile(), model));
        goal.failOnMiss = failOnMiss;
        goal.failOn = failOn;
        goal.formats = List.of();
        goal.reportDirectory = project.resolve("target/rsaml").toFile();
        return goal;
    }

    private void copy(String example, String as) throws Exception {
        Files.copy(TestRepository.example(example), project.resolve(as));
    }

    /** A copy of the proven latency example whose two processors are declared LLF, which the analysis does not analyse. */
    private void notAnalysed(String as) throws Exception {
        String model = Files.readString(TestRepository.example("mobile-base-latency.rsaml"));
        String llf = model.replace("core=\"0\" modules", "core=\"0\" schedPolicy=\"LLF\" modules")
                .replace("core=\"1\" modules", "core=\"1\" schedPolicy=\"LLF\" modules");
        assertTrue(!llf.equals(model), "both processors declared LLF");
        Files.writeString(project.resolve(as), llf);
    }

    @Test
    void aMissThatDoesNotFailTheBuildIsAWarning() throws Exception {
        copy("mobile-base-latency-missed.rsaml", "missed.rsaml");
        Recorded log = new Recorded();
        goal("missed.rsaml", false, "miss", log).execute();
        assertTrue(log.at("WARNING").stream().anyMatch(l -> l.contains("verdict: MISSES: the worst-case reaction time can reach 57 ms")),
                () -> "the miss is logged as a warning:\n" + String.join("\n", log.lines));
        assertEquals(List.of(), log.at("ERROR"), "nothing is an error when the miss does not fail the build");
    }

    @Test
    void aMissThatFailsTheBuildIsAnErrorAndNamesTheModel() throws Exception {
        copy("mobile-base-latency-missed.rsaml", "missed.rsaml");
        Recorded log = new Recorded();
        MojoFailureException failure = assertThrows(MojoFailureException.class, () -> goal("missed.rsaml", true, "miss", log).execute(),
                "a possible miss fails the build by default");
        assertEquals("RsaML timing: a deadline or a latency requirement can be missed in missed.rsaml (fail on miss)", failure.getMessage(),
                "the failure names the model");
        assertTrue(log.at("ERROR").stream().anyMatch(l -> l.contains("verdict: MISSES")),
                () -> "the miss is logged as an error:\n" + String.join("\n", log.lines));
        assertEquals(List.of(), log.at("WARNING"), "the verdicts of a failing model are errors, not warnings");
    }

    @Test
    void aModelNotAnalysedIsAWarningUnlessFailOnNotAnalysed() throws Exception {
        notAnalysed("llf.rsaml");
        Recorded lenient = new Recorded();
        goal("llf.rsaml", true, "miss", lenient).execute();
        assertTrue(lenient.at("WARNING").stream().anyMatch(l -> l.contains("llf.rsaml: timing not analysed")),
                () -> "not analysed is a warning under failOn miss:\n" + String.join("\n", lenient.lines));
        assertEquals(List.of(), lenient.at("ERROR"), "nothing is an error under failOn miss");

        Recorded strict = new Recorded();
        MojoFailureException failure = assertThrows(MojoFailureException.class,
                () -> goal("llf.rsaml", true, "not-analysed", strict).execute(), "failOn not-analysed fails a model not proven");
        assertEquals("RsaML timing: the timing is not proven in llf.rsaml (not analysed) (fail on not-analysed)", failure.getMessage(),
                "the failure says why and names the model");
        assertTrue(strict.at("ERROR").stream().anyMatch(l -> l.contains("llf.rsaml: timing not analysed")),
                () -> "not analysed is an error under failOn not-analysed:\n" + String.join("\n", strict.lines));
    }

    @Test
    void aProvenModelIsInformation() throws Exception {
        copy("mobile-base-latency.rsaml", "proven.rsaml");
        Recorded log = new Recorded();
        goal("proven.rsaml", true, "not-analysed", log).execute();
        assertTrue(log.at("INFO").contains("INFO proven.rsaml: timing meets"),
                () -> "the proven verdict is logged as information:\n" + String.join("\n", log.lines));
        assertEquals(List.of(), log.at("WARNING"), "a proven model has no warning");
        assertEquals(List.of(), log.at("ERROR"), "a proven model has no error");
    }
}
