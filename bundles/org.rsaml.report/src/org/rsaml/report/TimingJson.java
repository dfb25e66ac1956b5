/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;

import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.BoundCheck;
import org.rsaml.analysis.Exclusion;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.Segment;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.Witness;
import org.rsaml.model.support.AtomicFiles;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;

/**
 * The timing of an architecture as JSON (what {@code rsaml analyze --format json} prints and the analyze
 * goal's {@code timingJson} file holds); times are integral nanoseconds.
 */
public final class TimingJson {

    private TimingJson() {
    }

    /** The timing of one model, named by the {@code file} it was read from, as one entry of {@link #document}. */
    public static JsonObject of(String file, ArchitectureTiming timing) {
        JsonObject o = of(timing);
        o.addProperty("file", file);
        return o;
    }

    /** The document written for a run: one entry per analysed model, in the order they were analysed. */
    public static final class Document {
        private final JsonArray entries = new JsonArray();

        /** Adds the timing of the model read from {@code file}. */
        public void add(String file, ArchitectureTiming timing) {
            entries.add(of(file, timing));
        }

        /** The document, indented, without a final line break. */
        public String text() {
            return new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create().toJson(entries);
        }

        /** Writes the document (with a final line break) to {@code file}, replaced whole or left as it was. */
        public void write(Path file) throws IOException {
            AtomicFiles.writeString(file, text() + "\n");
        }

        /** What a front end says once the document is written to {@code file} (as the user reads it). */
        public static String written(Path file) {
            return "timing analysis written: " + ModelFiles.display(file);
        }

        /**
         * Writes the document to {@code file} (relative to {@code base}, as the user named it or as the build log
         * shows it), replaced whole or left as it was.
         *
         * @return {@code null} when written, else the line that says why not
         *         ({@code FILE: error: cannot write the timing analysis: why}, as {@link ReportFiles#writeAll} says it of reports)
         */
        public String writeTo(Path base, Path file) {
            Path target = base.resolve(file);
            try {
                write(target);
                return null;
            } catch (IOException e) {
                return Text.line(ModelFiles.display(file) + ": error: cannot write the timing analysis: " + ReportFiles.reason(e, target));
            }
        }
    }

    public static JsonObject of(ArchitectureTiming timing) {
        JsonObject o = new JsonObject();
        o.addProperty("architecture", timing.architecture());
        o.addProperty("verdict", verdict(timing.verdict()));
        JsonArray processors = new JsonArray();
        for (ProcessorTiming p : timing.processors()) {
            JsonObject j = new JsonObject();
            j.addProperty("name", p.name());
            j.addProperty("policy", p.result().policy().label());
            j.addProperty("utilisation", p.result().utilisation());
            j.addProperty("verdict", verdict(p.result().verdict()));
            j.addProperty("explanation", p.result().explanation());
            JsonArray tasks = new JsonArray();
            for (int i = 0; i < p.result().tasks().size(); i++) {
                TaskResult t = p.result().tasks().get(i);
                JsonObject k = new JsonObject();
                k.addProperty("task", t.task().name());
                k.addProperty("kind", p.sources().get(i).kind());
                k.addProperty("periodNs", t.task().period());
                k.addProperty("deadlineNs", t.task().deadline());
                k.addProperty("costNs", t.task().cost());
                k.addProperty("priority", t.task().priority());
                if (t.responseTime().isPresent()) {
                    k.addProperty("responseTimeNs", t.responseTime().getAsLong());
                    k.addProperty("slackNs", t.slack().getAsLong());
                }
                k.addProperty("verdict", verdict(t.verdict()));
                k.addProperty("explanation", t.explanation());
                if (!p.sources().get(i).note().isEmpty()) {
                    k.addProperty("note", p.sources().get(i).note());
                }
                if (t.witness() != null && t.verdict() == Verdict.MISSES) {
                    k.add("witness", witness(t.witness()));
                }
                tasks.add(k);
            }
            j.add("tasks", tasks);
            JsonArray bounds = new JsonArray();
            for (BoundCheck b : p.result().bounds()) {
                JsonObject k = new JsonObject();
                k.addProperty("name", b.name());
                k.addProperty("kind", b.sufficient() ? "sufficient" : "necessary");
                k.addProperty("limit", b.limit());
                k.addProperty("applicable", b.applicable());
                k.addProperty("holds", b.holds());
                k.addProperty("note", b.note());
                bounds.add(k);
            }
            j.add("bounds", bounds);
            if (p.result().demand() != null) {
                JsonObject d = new JsonObject();
                d.addProperty("intervalNs", p.result().demand().interval());
                d.addProperty("demandNs", p.result().demand().demand());
                d.add("jobs", counts(p.result().demand().jobs()));
                j.add("demandWitness", d);
            }
            JsonArray notes = new JsonArray();
            p.notes().forEach(notes::add);
            j.add("notes", notes);
            processors.add(j);
        }
        o.add("processors", processors);
        JsonArray excluded = new JsonArray();
        for (Exclusion x : timing.excluded()) {
            JsonObject k = new JsonObject();
            k.addProperty("element", x.label());
            k.addProperty("processor", x.processor());
            k.addProperty("reason", x.reason());
            excluded.add(k);
        }
        o.add("excluded", excluded);
        JsonArray latencies = new JsonArray();
        for (LatencyResult l : timing.latencies()) {
            JsonObject k = new JsonObject();
            k.addProperty("requirement", l.name());
            k.addProperty("from", l.from());
            k.addProperty("to", l.to());
            k.addProperty("kind", l.dataAge() ? "dataAge" : "reactionTime");
            k.addProperty("maxNs", l.maxNs());
            k.addProperty("verdict", verdict(l.verdict()));
            k.addProperty("explanation", l.explanation());
            if (l.reactionNs() >= 0) {
                k.addProperty("reactionTimeNs", l.reactionNs());
            }
            if (l.dataAgeNs() >= 0) {
                k.addProperty("dataAgeNs", l.dataAgeNs());
            }
            k.addProperty("paths", l.paths());
            // paths stops at 2,147,483,647: then it stands for at least that many
            k.addProperty("pathsAtLeast", l.pathsAtLeast());
            JsonArray hops = new JsonArray();
            l.worstPath().forEach(h -> hops.add(hop(h)));
            k.add("worstPath", hops);
            JsonArray via = new JsonArray();
            l.via().forEach(via::add);
            k.add("via", via);
            JsonArray every = new JsonArray();
            for (org.rsaml.analysis.PathBound b : l.pathBounds()) {
                JsonObject path = new JsonObject();
                JsonArray stages = new JsonArray();
                b.hops().forEach(h -> stages.add(hop(h)));
                path.add("stages", stages);
                if (b.bounded()) {
                    path.addProperty("reactionTimeNs", b.reactionNs());
                    path.addProperty("dataAgeNs", b.dataAgeNs());
                } else {
                    path.addProperty("unbounded", b.unbounded());
                }
                every.add(path);
            }
            k.add("everyPath", every);
            // everyPath holds every path counted in paths, or says which it holds and why not all
            k.addProperty("pathsListed", l.pathBounds().size());
            if (!l.unlisted().isEmpty()) {
                k.addProperty("pathsNotListed", l.unlisted());
            }
            latencies.add(k);
        }
        o.add("latencies", latencies);
        return o;
    }

    private static JsonObject hop(Hop h) {
        JsonObject hop = new JsonObject();
        hop.addProperty("stage", h.label());
        hop.addProperty("activation", h.activation());
        hop.addProperty("waitNs", h.waitNs());
        hop.addProperty("responseNs", h.responseNs());
        return hop;
    }

    private static JsonObject witness(Witness w) {
        JsonObject o = new JsonObject();
        o.addProperty("job", w.job() + 1);
        o.addProperty("releaseNs", w.release());
        o.addProperty("completionNs", w.completion());
        o.add("preemptions", counts(w.preemptions()));
        if (w.unlisted() > 0) {
            o.addProperty("unlistedTasks", w.unlisted());
        }
        if (w.blockedBy() != null) {
            o.addProperty("blockedBy", w.blockedBy());
        }
        JsonArray schedule = new JsonArray();
        for (Segment s : w.schedule()) {
            JsonObject k = new JsonObject();
            k.addProperty("task", s.task());
            k.addProperty("job", s.job() + 1);
            k.addProperty("startNs", s.start());
            k.addProperty("endNs", s.end());
            schedule.add(k);
        }
        o.add("schedule", schedule);
        o.addProperty("truncated", w.truncated());
        return o;
    }

    private static JsonObject counts(Map<String, Long> m) {
        JsonObject o = new JsonObject();
        m.forEach(o::addProperty);
        return o;
    }

    static String verdict(Verdict v) {
        return switch (v) {
            case MEETS -> "meets";
            case MISSES -> "misses";
            case NOT_ANALYSED -> "not analysed";
        };
    }
}
