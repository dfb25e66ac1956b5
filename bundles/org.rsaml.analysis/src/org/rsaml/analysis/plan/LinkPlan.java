/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.support.RsamlLabels;

public final class LinkPlan {
    final SubsumptionLink link;
    final boolean inhibitor;
    final PlannedModule owner;
    final String name;
    final String qualifiedName;
    final PlannedPort trigger;
    final PlannedPort target;
    final long durationNs;
    final boolean deliversData;

    LinkPlan(SubsumptionLink link, boolean inhibitor, PlannedModule owner, String qualifiedName, PlannedPort trigger,
            PlannedPort target, long durationNs) {
        this.link = link;
        this.inhibitor = inhibitor;
        this.owner = owner;
        this.name = RsamlLabels.name(link);
        this.qualifiedName = qualifiedName;
        this.trigger = trigger;
        this.target = target;
        this.durationNs = durationNs;
        this.deliversData = !inhibitor && trigger.sameData(target);
    }

    public SubsumptionLink link() {
        return link;
    }

    public boolean inhibitor() {
        return inhibitor;
    }

    public PlannedModule owner() {
        return owner;
    }

    public String name() {
        return name;
    }

    /** {@code layer/module.link}. */
    public String qualifiedName() {
        return qualifiedName;
    }

    public PlannedPort trigger() {
        return trigger;
    }

    public PlannedPort target() {
        return target;
    }

    public long durationNs() {
        return durationNs;
    }

    /** For a suppressor, whether the trigger's messages replace the target's input (same data). */
    public boolean deliversData() {
        return deliversData;
    }

    public String description() {
        return link.getDescription();
    }
}
