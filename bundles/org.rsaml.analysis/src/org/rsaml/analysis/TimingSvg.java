/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.rsaml.model.support.RsamlTimes;
import org.rsaml.model.support.AtomicFiles;
import org.rsaml.model.support.RsamlText;

/**
 * The witnesses of negative verdicts as SVG timelines: for a missed deadline one lane per task from
 * the critical instant; for a failed processor-demand test (EDF) one lane per task with its jobs due
 * within the overloaded interval, against the interval; for a latency requirement that can be exceeded one lane per stage of the
 * worst path, each waiting and then responding, against the requirement.
 */
public final class TimingSvg {

    private static final int WIDTH = 1000;
    private static final int LANE = 28;
    private static final int LEFT = 260;

    private TimingSvg() {
    }

    /**
     * Writes one file per task that misses its deadline and has a witness, one per processor whose
     * processor-demand test fails (its overloaded interval), and one per latency
     * requirement that can be exceeded along a bounded worst path; returns the files written.
     */
    public static List<Path> write(Path directory, ArchitectureTiming timing) throws IOException {
        List<Path> written = new ArrayList<>();
        for (ProcessorTiming p : timing.processors()) {
            for (TaskResult t : p.result().tasks()) {
                if (t.verdict() != Verdict.MISSES || t.witness() == null || t.witness().summary()) {
                    continue;
                }
                Files.createDirectories(directory);
                written.add(write(directory, timing.architecture() + "-" + p.name() + "-" + t.task().name(), svg(p.name(), t)));
            }
        }
        for (ProcessorTiming p : timing.processors()) {
            if (p.result().verdict() == Verdict.MISSES && p.result().demand() != null) {
                Files.createDirectories(directory);
                written.add(write(directory, timing.architecture() + "-" + p.name() + "-demand", svg(p.name(), p.result())));
            }
        }
        for (LatencyResult l : timing.latencies()) {
            if (l.verdict() == Verdict.MISSES && !l.worstPath().isEmpty()) {
                Files.createDirectories(directory);
                written.add(write(directory, timing.architecture() + "-latency-" + l.name(), svg(l)));
            }
        }
        return written;
    }

    /** Writes one timeline atomically, so that a failed run leaves no half-written file. */
    private static Path write(Path directory, String name, String svg) throws IOException {
        Path file = directory.resolve(fileName(name) + ".svg");
        AtomicFiles.writeString(file, svg);
        return file;
    }

    static String fileName(String s) {
        return s.replaceAll("[^A-Za-z0-9._-]+", "_");
    }

    /** The timeline of one task's witness. */
    public static String svg(String processor, TaskResult t) {
        Witness w = t.witness();
        Map<String, Integer> lanes = new LinkedHashMap<>();
        lanes.put(w.task(), 0);
        for (Segment s : w.schedule()) {
            lanes.putIfAbsent(s.task(), lanes.size());
        }
        long due = w.release() + t.task().deadline();
        long end = Math.max(Math.max(w.completion(), due), 1);
        if (!w.schedule().isEmpty()) {
            end = Math.max(end, w.schedule().get(w.schedule().size() - 1).end());
        }
        double scale = (double) (WIDTH - LEFT - 20) / end;
        int height = 60 + LANE * lanes.size() + 30;
        StringBuilder b = new StringBuilder();
        b.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(WIDTH).append("\" height=\"").append(height)
                .append("\" font-family=\"sans-serif\" font-size=\"12\">\n");
        b.append("<title>").append(esc(w.task() + " on " + processor + ": response time "
                + (w.completion() < 0 ? "unbounded" : RsamlTimes.text(w.completion() - w.release())) + ", deadline "
                + RsamlTimes.text(t.task().deadline()))).append("</title>\n");
        b.append("<text x=\"10\" y=\"20\" font-weight=\"bold\">").append(esc(processor + ": " + w.task() + " misses its deadline"))
                .append("</text>\n");
        b.append("<text x=\"10\" y=\"38\">").append(esc("critical instant at 0; job " + (w.job() + 1) + " released at "
                + RsamlTimes.text(w.release()) + ", due at " + RsamlTimes.text(due) + ", completes at "
                + (w.completion() < 0 ? "(cut short)" : RsamlTimes.text(w.completion())))).append("</text>\n");
        for (Map.Entry<String, Integer> lane : lanes.entrySet()) {
            int y = 60 + LANE * lane.getValue();
            b.append("<text x=\"10\" y=\"").append(y + 17).append("\">").append(esc(lane.getKey())).append("</text>\n");
            b.append("<line x1=\"").append(LEFT).append("\" y1=\"").append(y + LANE - 4).append("\" x2=\"").append(WIDTH - 20)
                    .append("\" y2=\"").append(y + LANE - 4).append("\" stroke=\"#ccc\"/>\n");
        }
        for (Segment s : w.schedule()) {
            int y = 60 + LANE * lanes.get(s.task());
            boolean own = s.task().equals(w.task());
            b.append(String.format(Locale.ROOT, "<rect x=\"%.2f\" y=\"%d\" width=\"%.2f\" height=\"%d\" fill=\"%s\" stroke=\"#333\">",
                    LEFT + s.start() * scale, y + 4, Math.max(0.5, (s.end() - s.start()) * scale), LANE - 10, own ? "#d9534f" : "#5b9bd5"));
            b.append("<title>").append(esc(s.task() + " job " + (s.job() + 1) + ": " + RsamlTimes.text(s.start()) + " - "
                    + RsamlTimes.text(s.end()))).append("</title></rect>\n");
        }
        int bottom = 60 + LANE * lanes.size();
        b.append(String.format(Locale.ROOT, "<line x1=\"%.2f\" y1=\"50\" x2=\"%.2f\" y2=\"%d\" stroke=\"#d9534f\" stroke-dasharray=\"4 3\"/>\n",
                LEFT + due * scale, LEFT + due * scale, bottom));
        b.append(String.format(Locale.ROOT, "<text x=\"%.2f\" y=\"%d\" fill=\"#d9534f\">deadline %s</text>\n", LEFT + due * scale + 3,
                bottom + 14, esc(RsamlTimes.text(due))));
        b.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\">0</text>\n", LEFT, bottom + 14));
        b.append("</svg>\n");
        return b.toString();
    }

    /** Jobs drawn per lane of a demand witness; the rest are counted. */
    static final int MAX_JOBS_DRAWN = 200;

    /**
     * The witness of a failed processor-demand test: with every task released at 0, one lane per task
     * whose jobs are due within the interval, each job's window from its release to its deadline
     * (light) with its cost at the start of it (red), and below them the demand of all those jobs
     * against the interval's length (dashed), which it exceeds.
     */
    public static String svg(String processor, ProcessorResult r) {
        DemandWitness d = r.demand();
        List<Task> tasks = new ArrayList<>();
        for (TaskResult t : r.tasks()) {
            if (d.jobs().getOrDefault(t.task().name(), 0L) > 0) {
                tasks.add(t.task());
            }
        }
        long end = Math.max(Math.max(d.interval(), d.demand()), 1);
        double scale = (double) (WIDTH - LEFT - 20) / end;
        int height = 60 + LANE * (tasks.size() + 1) + 30;
        StringBuilder b = new StringBuilder();
        b.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(WIDTH).append("\" height=\"").append(height)
                .append("\" font-family=\"sans-serif\" font-size=\"12\">\n");
        String head = processor + ": the jobs released and due within the first " + RsamlTimes.text(d.interval()) + " need "
                + RsamlTimes.text(d.demand()) + ", more than the interval holds";
        b.append("<title>").append(esc(head)).append("</title>\n");
        b.append("<text x=\"10\" y=\"20\" font-weight=\"bold\">").append(esc(head)).append("</text>\n");
        b.append("<text x=\"10\" y=\"38\">").append(esc("every task released at 0; light: a job's window from its release to its"
                + " deadline, red: its cost; no scheduler fits them all (" + r.policy().label() + ")")).append("</text>\n");
        for (int i = 0; i < tasks.size(); i++) {
            Task t = tasks.get(i);
            long jobs = d.jobs().get(t.name());
            int y = 60 + LANE * i;
            b.append("<text x=\"10\" y=\"").append(y + 17).append("\">").append(esc(t.name() + " x" + jobs)).append("</text>\n");
            b.append("<line x1=\"").append(LEFT).append("\" y1=\"").append(y + LANE - 4).append("\" x2=\"").append(WIDTH - 20)
                    .append("\" y2=\"").append(y + LANE - 4).append("\" stroke=\"#ccc\"/>\n");
            for (long k = 0; k < Math.min(jobs, MAX_JOBS_DRAWN); k++) {
                long release = k * t.period();
                String job = t.name() + " job " + (k + 1) + ": released at " + RsamlTimes.text(release) + ", due at "
                        + RsamlTimes.text(release + t.deadline());
                bar(b, release, t.deadline(), y, scale, "#f0d9a8", job);
                bar(b, release, Math.min(t.cost(), t.deadline()), y, scale, "#d9534f", job + ", needs " + RsamlTimes.text(t.cost()));
            }
            if (jobs > MAX_JOBS_DRAWN) {
                b.append("<text x=\"").append(WIDTH - 200).append("\" y=\"").append(y + 17).append("\">")
                        .append(esc("... " + (jobs - MAX_JOBS_DRAWN) + " more jobs")).append("</text>\n");
            }
        }
        int y = 60 + LANE * tasks.size();
        b.append("<text x=\"10\" y=\"").append(y + 17).append("\">demand</text>\n");
        bar(b, 0, d.demand(), y, scale, "#d9534f", "demand of the jobs due within " + RsamlTimes.text(d.interval()) + ": "
                + RsamlTimes.text(d.demand()));
        int bottom = y + LANE;
        b.append(String.format(Locale.ROOT, "<line x1=\"%.2f\" y1=\"50\" x2=\"%.2f\" y2=\"%d\" stroke=\"#d9534f\" stroke-dasharray=\"4 3\"/>\n",
                LEFT + d.interval() * scale, LEFT + d.interval() * scale, bottom));
        b.append(String.format(Locale.ROOT, "<text x=\"%.2f\" y=\"%d\" fill=\"#d9534f\">interval %s</text>\n",
                LEFT + d.interval() * scale + 3, bottom + 14, esc(RsamlTimes.text(d.interval()))));
        b.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\">0</text>\n", LEFT, bottom + 14));
        b.append("</svg>\n");
        return b.toString();
    }

    /**
     * The worst path of a latency requirement that can be exceeded: one lane per stage, the data
     * waiting for the stage (light) and the stage responding (red) one after the other from the
     * change at the source at 0; for a data-age requirement the last output then stays in place
     * until replaced. The requirement is a dashed line.
     */
    public static String svg(LatencyResult l) {
        List<Hop> hops = l.worstPath();
        long reaction = 0;
        for (Hop h : hops) {
            reaction += h.totalNs();
        }
        long held = l.dataAge() && l.dataAgeNs() > reaction ? l.dataAgeNs() - reaction : 0;
        long end = Math.max(Math.max(reaction + held, l.maxNs()), 1);
        double scale = (double) (WIDTH - LEFT - 20) / end;
        int height = 60 + LANE * hops.size() + 30;
        String kind = l.dataAge() ? "data age" : "reaction time";
        StringBuilder b = new StringBuilder();
        b.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(WIDTH).append("\" height=\"").append(height)
                .append("\" font-family=\"sans-serif\" font-size=\"12\">\n");
        b.append("<title>").append(esc("latency requirement " + l.name() + ": " + kind + " up to "
                + RsamlTimes.text(l.boundNs()) + ", at most " + RsamlTimes.text(l.maxNs()) + " allowed")).append("</title>\n");
        b.append("<text x=\"10\" y=\"20\" font-weight=\"bold\">").append(esc("latency requirement '" + l.name()
                + "' can be exceeded: " + kind + " up to " + RsamlTimes.text(l.boundNs()) + ", at most " + RsamlTimes.text(l.maxNs())))
                .append("</text>\n");
        b.append("<text x=\"10\" y=\"38\">").append(esc("worst of " + l.pathsText() + " from "
                + l.from() + " to " + l.to() + "; the source changes at 0; light: waiting for the stage, red: the stage responding")).append("</text>\n");
        long t = 0;
        for (int i = 0; i < hops.size(); i++) {
            Hop h = hops.get(i);
            int y = 60 + LANE * i;
            b.append("<text x=\"10\" y=\"").append(y + 17).append("\">").append(esc(h.label())).append("</text>\n");
            b.append("<line x1=\"").append(LEFT).append("\" y1=\"").append(y + LANE - 4).append("\" x2=\"").append(WIDTH - 20)
                    .append("\" y2=\"").append(y + LANE - 4).append("\" stroke=\"#ccc\"/>\n");
            bar(b, t, h.waitNs(), y, scale, "#f0d9a8", h.label() + ": waits up to " + RsamlTimes.text(h.waitNs()) + " (" + h.activation() + ")");
            bar(b, t + h.waitNs(), h.responseNs(), y, scale, "#d9534f", h.label() + ": responds within " + RsamlTimes.text(h.responseNs()));
            t += h.totalNs();
            if (i == hops.size() - 1 && held > 0) {
                bar(b, t, held, y, scale, "#bbbbbb", h.label() + ": its output stays in place up to " + RsamlTimes.text(held) + " until replaced");
            }
        }
        int bottom = 60 + LANE * hops.size();
        b.append(String.format(Locale.ROOT, "<line x1=\"%.2f\" y1=\"50\" x2=\"%.2f\" y2=\"%d\" stroke=\"#d9534f\" stroke-dasharray=\"4 3\"/>\n",
                LEFT + l.maxNs() * scale, LEFT + l.maxNs() * scale, bottom));
        b.append(String.format(Locale.ROOT, "<text x=\"%.2f\" y=\"%d\" fill=\"#d9534f\">required %s</text>\n", LEFT + l.maxNs() * scale + 3,
                bottom + 14, esc(RsamlTimes.text(l.maxNs()))));
        b.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\">0</text>\n", LEFT, bottom + 14));
        b.append("</svg>\n");
        return b.toString();
    }

    private static void bar(StringBuilder b, long start, long length, int y, double scale, String fill, String title) {
        if (length <= 0) {
            return;
        }
        b.append(String.format(Locale.ROOT, "<rect x=\"%.2f\" y=\"%d\" width=\"%.2f\" height=\"%d\" fill=\"%s\" stroke=\"#333\">",
                LEFT + start * scale, y + 4, Math.max(0.5, length * scale), LANE - 10, fill));
        b.append("<title>").append(esc(title)).append("</title></rect>\n");
    }

    private static String esc(String s) {
        return RsamlText.xml(s);
    }
}
