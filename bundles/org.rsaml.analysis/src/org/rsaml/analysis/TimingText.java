/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.rsaml.model.support.RsamlTimes;

/** The timing of an architecture as text: a table per processor, the witnesses, the latencies. */
public final class TimingText {

    /** Segments of a witness printed before the rest is summarised. */
    private static final int MAX_SEGMENTS = 40;

    private TimingText() {
    }

    public static String render(String file, ArchitectureTiming timing) {
        StringBuilder out = new StringBuilder();
        out.append(file).append(": architecture '").append(timing.architecture()).append("'\n");
        for (ProcessorTiming p : timing.processors()) {
            processor(out, p);
        }
        for (Exclusion x : timing.excluded()) {
            out.append("  excluded ").append(x.label()).append(" (processor ").append(x.processor()).append("): ")
                    .append(x.reason()).append('\n');
        }
        for (LatencyResult l : timing.latencies()) {
            latency(out, l);
        }
        out.append(file).append(": timing ").append(word(timing.verdict())).append('\n');
        return out.toString();
    }

    private static void processor(StringBuilder out, ProcessorTiming p) {
        ProcessorResult r = p.result();
        out.append("processor ").append(p.name()).append(" (").append(r.policy().label()).append("): ").append(r.tasks().size())
                .append(r.tasks().size() == 1 ? " task" : " tasks").append(", utilisation ").append(r.utilisationText()).append('\n');
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] { "task", "period", "deadline", "cost", "priority", "WCRT", "slack", "verdict" });
        for (TaskResult t : r.tasks()) {
            Task k = t.task();
            rows.add(new String[] { k.name(), RsamlTimes.text(k.period()), RsamlTimes.text(k.deadline()), RsamlTimes.text(k.cost()),
                    r.policy() == SchedulingPolicy.EDF ? "-" : Integer.toString(k.priority()),
                    t.responseTime().isPresent() ? RsamlTimes.text(t.responseTime().getAsLong()) : "-",
                    t.slack().isPresent() ? RsamlTimes.text(t.slack().getAsLong()) : "-", word(t.verdict()) });
        }
        table(out, rows);
        for (BoundCheck b : r.bounds()) {
            out.append("  bound ").append(b.name()).append(" (").append(b.sufficient() ? "sufficient" : "necessary").append("): ")
                    .append(b.limit()).append(" ");
            out.append(!b.applicable() ? b.note() : b.holds() ? "holds" : "does not hold").append('\n');
        }
        // an explanation that starts with its verdict ("not analysed: ...") is not prefixed twice
        String verdict = word(r.verdict()) + ": ";
        out.append("  verdict: ").append(r.explanation().startsWith(verdict) ? "" : verdict).append(r.explanation()).append('\n');
        for (int i = 0; i < r.tasks().size(); i++) {
            TaskResult t = r.tasks().get(i);
            String note = i < p.sources().size() ? p.sources().get(i).note() : "";
            if (t.verdict() != Verdict.MEETS || !note.isEmpty()) {
                out.append("  ").append(t.task().name()).append(": ").append(t.explanation());
                if (!note.isEmpty()) {
                    out.append(" (").append(note).append(')');
                }
                out.append('\n');
            }
            if (t.witness() != null && t.verdict() == Verdict.MISSES) {
                witness(out, t.witness());
            }
        }
        if (r.demand() != null) {
            DemandWitness d = r.demand();
            out.append("  witness: in the first ").append(RsamlTimes.text(d.interval())).append(" the jobs due need ")
                    .append(RsamlTimes.text(d.demand())).append(": ").append(jobs(d.jobs())).append('\n');
        }
        for (String n : p.notes()) {
            out.append("  note: ").append(n).append('\n');
        }
    }

    private static void witness(StringBuilder out, Witness w) {
        out.append("    witness: critical instant at 0; job ").append(w.job() + 1).append(" of ").append(w.task()).append(" released at ")
                .append(RsamlTimes.text(w.release())).append(w.summary() ? ", completes by " : ", completes at ")
                .append(w.completion() < 0 ? "(cut short)" : RsamlTimes.text(w.completion()));
        if (w.blockedBy() != null) {
            out.append(", blocked first by ").append(w.blockedBy());
        }
        if (w.summary()) {
            out.append("; delayed by at most ").append(w.preemptions().isEmpty() ? "nothing" : jobs(w.preemptions()));
            if (w.unlisted() > 0) {
                out.append(" and ").append(String.format(Locale.ROOT, "%,d", w.unlisted())).append(" other tasks");
            }
            out.append(" (only the highest-priority task that misses on a processor gets its schedule)\n");
            return;
        }
        out.append("; delayed by ").append(w.preemptions().isEmpty() ? "nothing" : jobs(w.preemptions())).append('\n');
        int shown = 0;
        for (Segment s : w.schedule()) {
            if (shown++ == MAX_SEGMENTS) {
                out.append("      ... ").append(w.schedule().size() - MAX_SEGMENTS).append(" more\n");
                break;
            }
            out.append("      ").append(RsamlTimes.text(s.start())).append(" - ").append(RsamlTimes.text(s.end())).append("  ")
                    .append(s.task()).append(" job ").append(s.job() + 1).append('\n');
        }
    }

    private static String jobs(Map<String, Long> jobs) {
        List<String> parts = new ArrayList<>();
        jobs.forEach((k, v) -> parts.add(k + " x" + v));
        return String.join(", ", parts);
    }

    private static void latency(StringBuilder out, LatencyResult l) {
        out.append("latency requirement '").append(l.name()).append("' from ").append(l.from()).append(" to ").append(l.to()).append(": ")
                .append(l.dataAge() ? "data age" : "reaction time").append(" at most ").append(RsamlTimes.text(l.maxNs()))
                .append(l.via().isEmpty() ? "" : ", the paths through " + String.join(", then ", l.via())).append('\n');
        String said = word(l.verdict()) + ": ";
        out.append("  verdict: ").append(l.explanation().startsWith(said) ? "" : said).append(l.explanation()).append('\n');
        if (!l.worstPath().isEmpty()) {
            out.append("  worst path (").append(l.pathsText()).append(" examined; reaction time ")
                    .append(l.reactionNs() < 0 ? "-" : RsamlTimes.text(l.reactionNs())).append(", data age ")
                    .append(l.dataAgeNs() < 0 ? "-" : RsamlTimes.text(l.dataAgeNs())).append("):\n");
            for (Hop h : l.worstPath()) {
                out.append("    ").append(h.label()).append(": ").append(h.contribution()).append(": ").append(h.activation()).append('\n');
            }
        }
        if (!l.pathBounds().isEmpty()) {
            out.append("  ").append(l.pathsHeading(LatencyResult.SHOWN_PATHS)).append('\n');
            for (PathBound b : l.pathBounds().subList(0, Math.min(LatencyResult.SHOWN_PATHS, l.pathBounds().size()))) {
                out.append("    ").append(b.text().isEmpty() ? "(no stage)" : b.text()).append(": ");
                if (b.bounded()) {
                    out.append("reaction time ").append(RsamlTimes.text(b.reactionNs())).append(", data age ")
                            .append(RsamlTimes.text(b.dataAgeNs()));
                } else {
                    out.append("no bound (").append(b.unbounded()).append(')');
                }
                out.append('\n');
            }
        }
    }

    /** meets, MISSES, not analysed: the words users read. */
    public static String word(Verdict v) {
        return switch (v) {
            case MEETS -> "meets";
            case MISSES -> "MISSES";
            case NOT_ANALYSED -> "not analysed";
        };
    }

    private static void table(StringBuilder out, List<String[]> rows) {
        int[] width = new int[rows.get(0).length];
        for (String[] row : rows) {
            for (int i = 0; i < row.length; i++) {
                width[i] = Math.max(width[i], row[i].length());
            }
        }
        for (String[] row : rows) {
            StringBuilder line = new StringBuilder("  ");
            for (int i = 0; i < row.length; i++) {
                line.append(String.format(Locale.ROOT, i == 0 ? "%-" + width[i] + "s" : "  %" + width[i] + "s", row[i]));
            }
            out.append(line.toString().stripTrailing()).append('\n');
        }
    }
}
