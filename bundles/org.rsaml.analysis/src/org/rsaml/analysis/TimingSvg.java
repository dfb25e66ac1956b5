/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.rsaml.analysis.internal.Durations;

/**
 * The witnesses of negative verdicts as SVG timelines: for a missed deadline one lane per task from
 * the critical instant; for a latency requirement that can be exceeded one lane per stage of the
 * worst path, each waiting and then responding, against the requirement.
 */
public final class TimingSvg {

    private static final int WIDTH = 1000;
    private static final int LANE = 28;
    private static final int LEFT = 260;

    private TimingSvg() {
    }

    /**
     * Writes one file per task that misses its deadline and has a witness, and one per latency
     * requirement that can be exceeded along a bounded worst path; returns the files written.
     */
    public static List<Path> write(Path directory, ArchitectureTiming timing) throws IOException {
        List<Path> written = new ArrayList<>();
        for (ProcessorTiming p : timing.processors()) {
            for (TaskResult t : p.result().tasks()) {
                if (t.verdict() != Verdict.MISSES || t.witness() == null) {
                    continue;
                }
                Files.createDirectories(directory);
                written.add(write(directory, timing.architecture() + "-" + p.name() + "-" + t.task().name(), svg(p.name(), t)));
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
        Path temp = Files.createTempFile(directory, ".timeline", ".svg");
        try {
            Files.writeString(temp, svg, StandardCharsets.UTF_8);
            Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temp);
        }
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
                + (w.completion() < 0 ? "unbounded" : Durations.format(w.completion() - w.release())) + ", deadline "
                + Durations.format(t.task().deadline()))).append("</title>\n");
        b.append("<text x=\"10\" y=\"20\" font-weight=\"bold\">").append(esc(processor + ": " + w.task() + " misses its deadline"))
                .append("</text>\n");
        b.append("<text x=\"10\" y=\"38\">").append(esc("critical instant at 0; job " + (w.job() + 1) + " released at "
                + Durations.format(w.release()) + ", due at " + Durations.format(due) + ", completes at "
                + (w.completion() < 0 ? "(cut short)" : Durations.format(w.completion())))).append("</text>\n");
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
            b.append("<title>").append(esc(s.task() + " job " + (s.job() + 1) + ": " + Durations.format(s.start()) + " - "
                    + Durations.format(s.end()))).append("</title></rect>\n");
        }
        int bottom = 60 + LANE * lanes.size();
        b.append(String.format(Locale.ROOT, "<line x1=\"%.2f\" y1=\"50\" x2=\"%.2f\" y2=\"%d\" stroke=\"#d9534f\" stroke-dasharray=\"4 3\"/>\n",
                LEFT + due * scale, LEFT + due * scale, bottom));
        b.append(String.format(Locale.ROOT, "<text x=\"%.2f\" y=\"%d\" fill=\"#d9534f\">deadline %s</text>\n", LEFT + due * scale + 3,
                bottom + 14, esc(Durations.format(due))));
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
                + Durations.format(l.boundNs()) + ", at most " + Durations.format(l.maxNs()) + " allowed")).append("</title>\n");
        b.append("<text x=\"10\" y=\"20\" font-weight=\"bold\">").append(esc("latency requirement '" + l.name()
                + "' can be exceeded: " + kind + " up to " + Durations.format(l.boundNs()) + ", at most " + Durations.format(l.maxNs())))
                .append("</text>\n");
        b.append("<text x=\"10\" y=\"38\">").append(esc("worst of " + l.paths() + (l.paths() == 1 ? " path" : " paths") + " from "
                + l.from() + " to " + l.to() + "; the source changes at 0; light: waiting for the stage, red: the stage responding")).append("</text>\n");
        long t = 0;
        for (int i = 0; i < hops.size(); i++) {
            Hop h = hops.get(i);
            int y = 60 + LANE * i;
            b.append("<text x=\"10\" y=\"").append(y + 17).append("\">").append(esc(h.label())).append("</text>\n");
            b.append("<line x1=\"").append(LEFT).append("\" y1=\"").append(y + LANE - 4).append("\" x2=\"").append(WIDTH - 20)
                    .append("\" y2=\"").append(y + LANE - 4).append("\" stroke=\"#ccc\"/>\n");
            bar(b, t, h.waitNs(), y, scale, "#f0d9a8", h.label() + ": waits up to " + Durations.format(h.waitNs()) + " (" + h.activation() + ")");
            bar(b, t + h.waitNs(), h.responseNs(), y, scale, "#d9534f", h.label() + ": responds within " + Durations.format(h.responseNs()));
            t += h.totalNs();
            if (i == hops.size() - 1 && held > 0) {
                bar(b, t, held, y, scale, "#bbbbbb", h.label() + ": its output stays in place up to " + Durations.format(held) + " until replaced");
            }
        }
        int bottom = 60 + LANE * hops.size();
        b.append(String.format(Locale.ROOT, "<line x1=\"%.2f\" y1=\"50\" x2=\"%.2f\" y2=\"%d\" stroke=\"#d9534f\" stroke-dasharray=\"4 3\"/>\n",
                LEFT + l.maxNs() * scale, LEFT + l.maxNs() * scale, bottom));
        b.append(String.format(Locale.ROOT, "<text x=\"%.2f\" y=\"%d\" fill=\"#d9534f\">required %s</text>\n", LEFT + l.maxNs() * scale + 3,
                bottom + 14, esc(Durations.format(l.maxNs()))));
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
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
