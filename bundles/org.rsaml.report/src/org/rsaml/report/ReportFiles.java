/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.rsaml.model.support.AtomicFiles;

/**
 * Writes report files whole or not at all: a failed run never leaves half a report behind. Files
 * get the permissions any compiler output gets (those the umask allows), since CI often reads them
 * as another user.
 */
public final class ReportFiles {

    private ReportFiles() {
    }

    /** Writes {@code report} in {@code format} to {@code file}, replacing it whole ({@link AtomicFiles}). */
    public static void write(Path file, ReportFormat format, Report report, ReportOptions options) throws IOException {
        AtomicFiles.write(file, out -> format.write(report, out, options));
    }

    /**
     * Writes {@code report} into every report file a run asked for: what {@code rsaml validate -o} and
     * {@code rsaml analyze} write, and the Maven goals' report files. A file that cannot be written costs
     * that file only; every file is complete, whatever {@link ReportOptions#quiet()} says (it is read later).
     *
     * @param base  the directory {@code files}' paths are relative to
     * @param files each file, as the user named it or as the build log shows it, with its format
     * @return one line per file that could not be written ({@code FILE: error: cannot write the FORMAT report: why}),
     *         empty when all were written
     */
    public static List<String> writeAll(Report report, Map<Path, ReportFormat> files, Path base, ReportOptions options) {
        ReportOptions complete = new ReportOptions(options.toolVersion(), options.baseDir(), false);
        List<String> failures = new ArrayList<>();
        for (Map.Entry<Path, ReportFormat> file : files.entrySet()) {
            Path target = base.resolve(file.getKey());
            try {
                write(target, file.getValue(), report, complete);
            } catch (IOException e) {
                failures.add(Text.line(ModelFiles.display(file.getKey()) + ": error: cannot write the " + file.getValue().id()
                        + " report: " + reason(e, target)));
            }
        }
        return List.copyOf(failures);
    }

    /**
     * The exit code of a run that wrote {@code report} to its report files with {@code failures} ({@link #writeAll}'s
     * lines): 2 when a report file could not be written, else the report's own.
     */
    public static int exitCode(Report report, List<String> failures) {
        return failures.isEmpty() ? report.exitCode() : ExitCodes.INPUT_ERROR;
    }

    /**
     * Why a run fails when report files could not be written ({@code cannot write 2 reports; see the errors above}),
     * or {@code null} when every one was.
     */
    public static String failure(List<String> failures) {
        return failures.isEmpty() ? null
                : "cannot write " + (failures.size() == 1 ? "a report" : failures.size() + " reports") + "; see the errors above";
    }

    /**
     * Why a file operation failed, as the operating system says it ({@code permission denied},
     * {@code not a directory}, ...), naming the file when it is not {@code target}.
     */
    public static String reason(IOException e, Path target) {
        return AtomicFiles.reason(e, target);
    }
}
