/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.List;

import org.rsaml.model.support.RsamlTimes;
import org.rsaml.model.LatencyRequirement;

/**
 * An end-to-end latency requirement checked against every path between its source and its target
 * (or the paths through the elements it names).
 *
 * @param requirement  the model's requirement
 * @param name         its name
 * @param from         the source as {@code sensor 'x'} or {@code layer/module.port}
 * @param to           the target likewise
 * @param maxNs        the latency allowed
 * @param dataAge      true when the requirement bounds the data age, false for the reaction time
 * @param verdict      MEETS when every path is proven within maxNs
 * @param reactionNs   the worst-case reaction time over all paths (-1 when not bounded)
 * @param dataAgeNs    the maximum data age over all paths (-1 when not bounded)
 * @param worstPath    the hops of the path with the largest bounded latency (empty when there is none)
 * @param paths        how many paths were examined; {@link Integer#MAX_VALUE} stands for at least that many
 *                     ({@link #pathsAtLeast()})
 * @param explanation  what decided the verdict
 * @param via          the elements the paths must pass through, in order, as labels (empty: every path)
 * @param pathBounds   every path examined with its own bounds, the longest first (at most
 *                     {@link #MAX_LISTED_PATHS}; {@code paths} counts them all)
 * @param unlisted     empty when {@code pathBounds} holds every path counted in {@code paths}; else which
 *                     paths it holds and why not all
 */
public record LatencyResult(LatencyRequirement requirement, String name, String from, String to, long maxNs, boolean dataAge,
        Verdict verdict, long reactionNs, long dataAgeNs, List<Hop> worstPath, int paths, String explanation, List<String> via,
        List<PathBound> pathBounds, String unlisted) {

    /**
     * Paths listed with their bounds per requirement (in {@link #pathBounds()}, JSON's {@code everyPath}); past
     * it the longest are kept and the others counted, and {@link #unlisted()} says so.
     */
    public static final int MAX_LISTED_PATHS = 10_000;

    /**
     * Stages of the paths listed per requirement, in all: long paths are listed fewer (the longest at least). Each
     * stage is some 300 bytes of JSON, so that a requirement's {@code everyPath} stays within some 30 MB.
     */
    public static final int MAX_LISTED_STAGES = 100_000;

    /** Whether a list of {@code paths} paths of {@code stages} stages in all is more than a requirement lists. */
    public static boolean overListed(int paths, long stages) {
        return paths > MAX_LISTED_PATHS || stages > MAX_LISTED_STAGES;
    }

    /** Paths the text report and the diagram overlay show one by one, the longest first; JSON lists them all. */
    public static final int SHOWN_PATHS = 10;

    public LatencyResult {
        worstPath = List.copyOf(worstPath);
        via = List.copyOf(via);
        pathBounds = List.copyOf(pathBounds);
        unlisted = unlisted == null ? "" : unlisted;
    }

    /** A result without the paths listed one by one. */
    public LatencyResult(LatencyRequirement requirement, String name, String from, String to, long maxNs, boolean dataAge,
            Verdict verdict, long reactionNs, long dataAgeNs, List<Hop> worstPath, int paths, String explanation) {
        this(requirement, name, from, to, maxNs, dataAge, verdict, reactionNs, dataAgeNs, worstPath, paths, explanation, List.of(),
                List.of(), "");
    }

    /**
     * The heading of the list of the first {@code shown} paths of {@link #pathBounds()}, as the text report
     * and the diagram overlay word it: {@code every path, the longest first:} when they are all, else how
     * many paths there are and where the others are listed ({@code rsaml analyze --format json}), or why
     * they are not.
     */
    public String pathsHeading(int shown) {
        int listed = pathBounds.size();
        int n = Math.min(shown, listed);
        if (unlisted.isEmpty() && n == listed) {
            return "every path, the longest first:";
        }
        if (unlisted.isEmpty()) {
            return "the " + n + " longest of " + pathsText() + " (rsaml analyze --format json lists all " + paths + "):";
        }
        return "the " + n + " longest paths listed (" + (n < listed ? "rsaml analyze --format json lists " + listed + "; " : "")
                + unlisted + "):";
    }

    /** The worst path in one line, {@code perception/filter +15 ms -> control/drive +22 ms}; empty without one. */
    public String worstPathText() {
        return String.join(" -> ", worstPathHops());
    }

    /** Each hop of the worst path as {@link #worstPathText()} writes it, {@code perception/filter +15 ms}. */
    public List<String> worstPathHops() {
        return worstPath.stream().map(h -> h.label() + " +" + RsamlTimes.text(h.totalNs())).toList();
    }

    /** Whether {@link #paths()} stopped at its largest, {@link Integer#MAX_VALUE}, and stands for at least that many. */
    public boolean pathsAtLeast() {
        return paths == Integer.MAX_VALUE;
    }

    /** {@link #paths()} as the reports word it: {@code 12 paths}, {@code 1 path}, {@code at least 2147483647 paths}. */
    public String pathsText() {
        return (pathsAtLeast() ? "at least " : "") + paths + (paths == 1 ? " path" : " paths");
    }

    /** The latency the requirement bounds (-1 when not bounded). */
    public long boundNs() {
        return dataAge ? dataAgeNs : reactionNs;
    }
}
