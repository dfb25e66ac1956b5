/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.TimingText;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.TimingBatch;
import org.rsaml.report.TimingFailOn;

import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/** {@code rsaml analyze MODEL...}: schedulability per processor and end-to-end latency, with witnesses. */
final class AnalyzeCommand extends RsamlCommand {

    static final String NAME = "analyze";

    enum Format { text, json, sarif, junit }

    private final PositionalParamSpec paths = CommandSpecs.paths(Path.class, "MODEL", "Model files and directories.").build();

    private final OptionSpec format = CommandSpecs.option(Format.class, "FORMAT", "-f", "--format").defaultValue("text")
            .description("Format written to standard output: text or json (the verdicts and witnesses), sarif or junit",
                    "(the timing rules' findings, as validate reports them; 'rsaml rules' lists the rules) (default: ${DEFAULT-VALUE}).")
            .build();

    private final OptionSpec timeline = CommandSpecs.option(Path.class, "DIR", "--timeline")
            .description("Also write into DIR an SVG timeline of each witness: a missed deadline's critical-instant schedule, "
                    + "an overloaded processor's demand interval (EDF), a latency requirement's worst path.").build();

    private final OptionSpec failOn = CommandSpecs.option(TimingFailOn.class, "LEVEL", "--fail-on").defaultValue("miss")
            .description("Which verdicts make the exit code 1: miss (a deadline or requirement can be missed), not-analysed",
                    "(also a task, processor or requirement not analysed: only a proven model exits 0) or never (default: ${DEFAULT-VALUE}).")
            .build();

    AnalyzeCommand(RsamlCli parent) {
        super(parent, NAME, "Analyses the timing of models as the generated runtime runs them (see docs/timing.md): per processor",
                "the worst-case response time of every task, utilisation and bounds; per latency requirement the worst path.",
                "Every verdict is 'meets' (proven), 'MISSES' (with a witness) or 'not analysed' (with the reason).");
        spec.usageMessage().sortOptions(false);
        CommandSpecs.exitCodes(spec, "0:no deadline or requirement can be missed (with --fail-on not-analysed: every verdict is proven)",
                "1:a deadline or a latency requirement can be missed (with --fail-on not-analysed: or something is not analysed)",
                "2:usage error, a model that cannot be read or analysed, or output that cannot be written");
        spec.addPositional(paths).addOption(format).addOption(timeline).addOption(failOn);
        CommandSpecs.standardHelpOptions(spec);
    }

    @Override
    public Integer call() {
        Format format = this.format.getValue();
        ReportFormat findings = format == Format.sarif ? ReportFormat.SARIF : format == Format.junit ? ReportFormat.JUNIT : null;
        PrintWriter out = out();
        PrintWriter err = err();
        TimingBatch.Request request = new TimingBatch.Request(timeline.getValue(), failOn.getValue(), format == Format.json, findings != null);
        TimingBatch.Outcome outcome = TimingBatch.run(parent.workingDirectory, paths.getValue(), request, new TimingBatch.Listener() {
            @Override
            public void analysed(String displayName, ArchitectureTiming timing) {
                if (format == Format.text) {
                    out.print(TimingText.render(displayName, timing));
                }
            }

            @Override
            public void unanalysable(List<String> lines) {
                // Read or not, a model that cannot be analysed is an input error in every format; the
                // findings' report says it on standard error itself.
                if (findings == null) {
                    lines.forEach(err::println);
                }
            }

            @Override
            public void timeline(Path file, String line) {
                err.println(line);
            }

            @Override
            public void noTimeline(String displayName, String line) {
                err.println(line);
            }

            @Override
            public void timelineFailed(String line) {
                err.println(line);
            }
        });
        if (outcome.json() != null) {
            out.println(outcome.json().text());
        }
        if (findings != null) {
            // No report file is written: the findings' exit code is the report's, which the outcome's includes.
            ReportArgs.emit(outcome.findings(), findings, Map.of(), false, parent, spec);
        }
        out.flush();
        err.flush();
        return outcome.exitCode();
    }
}
