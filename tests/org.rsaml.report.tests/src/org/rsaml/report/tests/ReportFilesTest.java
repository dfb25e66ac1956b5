/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.report.ExitCodes;
import org.rsaml.report.ModelBatch;
import org.rsaml.report.Report;
import org.rsaml.report.ReportFiles;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.ReportOptions;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Severity;

/** Report files are replaced whole, never left half written, and a path that cannot take one is refused with the reason. */
class ReportFilesTest {

    private static final Report REPORT = ModelBatch.validate(TestRepository.root(), List.of(Path.of("examples/exp2-defects.rsaml")),
            Severity.ERROR);
    private static final ReportOptions OPTIONS = new ReportOptions("0.0.0-test", TestRepository.root(), false);

    @Test
    void aReportFileIsReplacedWholeAndNoTemporaryFileIsLeft(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("reports/rsaml.sarif");
        Files.createDirectories(file.getParent());
        Files.writeString(file, "an older report, longer than nothing".repeat(1000));
        ReportFiles.write(file, ReportFormat.SARIF, REPORT, OPTIONS);
        StringWriter expected = new StringWriter();
        ReportFormat.SARIF.write(REPORT, expected, OPTIONS);
        assertEquals(expected.toString(), Files.readString(file), "the file holds the new report and nothing of the old one");
        try (Stream<Path> files = Files.list(file.getParent())) {
            assertEquals(List.of(file), files.toList(), "no temporary file is left beside the report");
        }
    }

    @Test
    void missingFoldersAreCreated(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("a/b/c/rsaml.xml");
        ReportFiles.write(file, ReportFormat.JUNIT, REPORT, OPTIONS);
        assertTrue(Files.readString(file).contains("<testsuites"), "the JUnit report is written where asked");
    }

    @Test
    void aDirectoryWhereTheReportGoesIsRefusedWithTheReason(@TempDir Path dir) throws Exception {
        Path taken = Files.createDirectories(dir.resolve("rsaml.json"));
        IOException e = assertThrows(IOException.class, () -> ReportFiles.write(taken, ReportFormat.JSON, REPORT, OPTIONS),
                "a report is not written over a directory");
        assertEquals("it is a directory", ReportFiles.reason(e, taken), "the reason a user reads");
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(taken), files.toList(), "nothing is written beside it");
        }
    }

    @Test
    void everyReportFileOfARunIsWrittenCompleteAndOneThatCannotBeCostsOnlyItself(@TempDir Path dir) throws Exception {
        Files.createDirectories(dir.resolve("taken.sarif"));
        Map<Path, ReportFormat> files = new LinkedHashMap<>();
        files.put(Path.of("taken.sarif"), ReportFormat.SARIF);
        files.put(Path.of("out/rsaml.txt"), ReportFormat.TEXT);
        ReportOptions quiet = new ReportOptions(OPTIONS.toolVersion(), OPTIONS.baseDir(), true);

        // Findings that fail nothing: a quiet text report leaves them out.
        Report report = ModelBatch.validate(TestRepository.root(), List.of(Path.of("examples/exp2-defects.rsaml")), null);
        List<String> failures = ReportFiles.writeAll(report, files, dir, quiet);

        assertEquals(List.of("taken.sarif: error: cannot write the sarif report: it is a directory"), failures,
                "the file that cannot be written is named, with the reason, as the user named it");
        assertEquals(ExitCodes.INPUT_ERROR, ReportFiles.exitCode(report, failures), "a report file not written makes the exit code 2");
        assertEquals("cannot write a report; see the errors above", ReportFiles.failure(failures), "what a goal fails the build with");
        assertEquals(report.exitCode(), ReportFiles.exitCode(report, List.of()), "every file written: the report's own exit code");
        assertEquals(null, ReportFiles.failure(List.of()), "every file written: no failure");
        StringWriter complete = new StringWriter();
        ReportFormat.TEXT.write(report, complete, OPTIONS);
        StringWriter shortened = new StringWriter();
        ReportFormat.TEXT.write(report, shortened, quiet);
        assertNotEquals(complete.toString(), shortened.toString(), "a quiet text report leaves something out of this report");
        assertEquals(complete.toString(), Files.readString(dir.resolve("out/rsaml.txt")),
                "the other file is written, and complete although the run is quiet");
    }

    @Test
    void aBuildsReportFilesAreNamedByOneRuleAndReadBackAsTheirFormat() {
        for (ReportFormat format : ReportFormat.values()) {
            String name = format.fileName("rsaml-timing");
            assertEquals(format, ReportFormat.ofFileName(name), name + " is read back as " + format);
        }
        assertEquals("TEST-rsaml.xml", ReportFormat.JUNIT.fileName("rsaml"), "JUnit reports carry the TEST- prefix CI servers look for");
        assertEquals("rsaml.sarif", ReportFormat.SARIF.fileName("rsaml"), "other reports are the stem and the format's extension");
    }
}
