/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.support.RsamlTimes;

/**
 * One path of a latency requirement and its bounds: the stages data passes (modules, and the
 * inhibitors whose block acts at once), its worst-case reaction time and maximum data age, both -1
 * when a stage has no bound ({@link #unbounded()} says which); {@code passes}: the elements it passes in order,
 * each module and, between two, the output port, the inhibitor or suppressor, and the entry port of the step taken
 * (which of two connections between the same modules the path uses).
 */
public record PathBound(List<Hop> hops, long reactionNs, long dataAgeNs, String unbounded, List<EObject> passes) {

    public PathBound {
        hops = List.copyOf(hops);
        passes = List.copyOf(passes);
    }

    /** Whether the path has a bound. */
    public boolean bounded() {
        return unbounded == null;
    }

    /** The path in one line, {@code perception/filter +15 ms -> control/drive +22 ms}. */
    public String text() {
        return String.join(" -> ", hops.stream().map(h -> h.label() + " +" + RsamlTimes.text(h.totalNs())).toList());
    }
}
