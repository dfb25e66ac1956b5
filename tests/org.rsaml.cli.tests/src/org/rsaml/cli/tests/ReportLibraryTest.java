/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.rsaml.report.FileResult;
import org.rsaml.report.ModelBatch;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.ReportOptions;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Severity;
import org.xml.sax.InputSource;

import com.google.gson.JsonParser;

/** org.rsaml.report on a plain class path: the batch any front end runs, and a check of another kind through the same writers. */
class ReportLibraryTest {

    private static final List<Path> EXAMPLES = List.of(Path.of("examples/exp1-hybrid.rsaml"),
            Path.of("examples/exp2-defects.rsaml"), Path.of("examples/subsumption-brooks.rsaml"));

    @Test
    void aDefectInTheCheckCostsOneFileOnly() throws Exception {
        Report report = ModelBatch.run(Cli.ROOT, EXAMPLES, Severity.ERROR, org.rsaml.validation.Rules.all(), (file, shown) -> {
            if (shown.contains("exp2")) {
                throw new IllegalStateException("boom");
            }
            return RsamlModelValidator.validate(file, shown);
        });
        assertEquals(EXAMPLES.size(), report.results().size(), "one result per model named, the failing one included");
        assertTrue(report.results().get(0).readable(), "the model before the failing one is checked");
        FileResult failed = report.results().get(1);
        assertFalse(failed.readable(), "the model whose check failed has no findings, an error");
        assertEquals("examples/exp2-defects.rsaml: error: internal error while checking this file (a defect in RsaML, please report it): "
                + "java.lang.IllegalStateException: boom", failed.error().toString(), "the error names the file and says it is RsaML's defect");
        assertTrue(report.results().get(2).readable(), "the model after the failing one is still checked");
        assertEquals(2, report.exitCode(), "a file that could not be checked makes the exit code 2");
        assertWellFormed(report);
    }

    @Test
    void anotherKindOfCheckReusesEveryWriter() throws Exception {
        // As a timing analysis would: its own rule, its own findings, the same batch and formats.
        Rule latency = new Rule("RSA-T1", "end-to-end-latency", Severity.WARNING, "analysis", "Architecture",
                "A chain's end-to-end latency fits its deadline.", "every chain with a deadline",
                "chain {chain} takes {latency}, deadline {deadline}", "Shorten the chain or relax the deadline.");
        Report report = ModelBatch.run(Cli.ROOT, EXAMPLES.subList(0, 1), Severity.WARNING, List.of(latency),
                (file, shown) -> List.of(new Finding(latency, Severity.WARNING, "chain a -> b takes 12 ms, deadline 10 ms",
                        "robot/a", "//@layers.0", shown, 3, 5)));
        assertEquals(1, report.exitCode(), "a warning at or above the threshold makes the exit code 1");
        String text = write(ReportFormat.TEXT, report);
        assertEquals("examples/exp1-hybrid.rsaml:3:5: warning RSA-T1: chain a -> b takes 12 ms, deadline 10 ms\n"
                + "1 file checked: 0 errors, 1 warning\n", text, "the text report words the other check's finding as validate's");
        assertTrue(write(ReportFormat.SARIF, report).contains("\"id\": \"RSA-T1\""), "SARIF lists the other check's rule");
        assertTrue(write(ReportFormat.JUNIT, report).contains("RSA-T1 end-to-end-latency"), "JUnit has a test for the other check's rule");
        assertWellFormed(report);
    }

    static String write(ReportFormat format, Report report) throws Exception {
        StringWriter out = new StringWriter();
        format.write(report, out, new ReportOptions("test", Cli.ROOT, false));
        return out.toString();
    }

    /** JSON and SARIF parse (SARIF against its schema), JUnit XML parses. */
    static void assertWellFormed(Report report) throws Exception {
        JsonParser.parseString(write(ReportFormat.JSON, report));
        assertEquals(Set.of(), ReportFormatsTest.sarifProblems(write(ReportFormat.SARIF, report)), "the SARIF report conforms to the schema");
        DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new InputSource(new StringReader(write(ReportFormat.JUNIT, report))));
    }
}
