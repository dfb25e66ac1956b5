/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import org.rsaml.analysis.plan.PlannedPort;
import org.rsaml.model.Connection;
import org.rsaml.model.support.RsamlLabels;

/**
 * The words of {@link ExecutionPlan#warnings()}: a model element that cannot execute as modeled,
 * what happens to it in generated code and why.
 */
final class PlanWarnings {

    private PlanWarnings() {
    }

    static String connectionWithoutPort(Connection c) {
        return "connection " + RsamlLabels.name(c.getSource()) + " -> " + RsamlLabels.name(c.getTarget())
                + " is not generated: it lacks a source or a target port in a layer";
    }

    static String connectionOfDifferentData(PlannedPort source, PlannedPort target) {
        return "connection " + source.qualifiedName() + " -> " + target.qualifiedName()
                + " is not generated: the ports carry different data (" + source.dataLabel() + " vs " + target.dataLabel() + ")";
    }

    static String linkWithoutTarget(String kind, String label) {
        return kind + " " + label + " is not generated: it has no target port";
    }

    static String linkWithoutTrigger(String kind, String label) {
        return kind + " " + label + " is not generated: it has no trigger port, so nothing can activate it";
    }

    static String suppressorWithoutData(String label, PlannedPort trigger, PlannedPort target) {
        return "suppressor " + label + " blocks " + target.qualifiedName() + " but cannot replace its data: its trigger "
                + trigger.qualifiedName() + " carries " + trigger.dataLabel() + ", the target " + target.dataLabel();
    }
}
