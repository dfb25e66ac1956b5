/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The catalog of RsaML rules. RSA-01 to RSA-08 are the paper's eight semantic rules; the others are
 * the checks an architect expects next to them. Every rule but RSA-00 is an OCL invariant in
 * {@code rsaml.ecore}, named {@code RSAnn_camelCaseName}.
 */
public final class Rules {

    public static final Rule STRUCTURE = new Rule("RSA-00", "model-structure", Severity.ERROR, "EMF",
            "The model is structurally sound: required features are set, references resolve, values are legal.",
            "Set the missing feature or fix the reference the message names.");

    private static final Map<String, Rule> BY_ID = new LinkedHashMap<>();

    static {
        add(STRUCTURE);
        add(new Rule("RSA-01", "declared-layer-count", Severity.ERROR, "paper",
                "The declared number of layers equals the number of layers actually in the architecture.",
                "Set declaredLayers to the number of layers, or add or remove layers."));
        add(new Rule("RSA-02", "connected-port-types", Severity.ERROR, "paper",
                "Two connected ports exchange the same data type (and, for structured data, the same message type).",
                "Give the output port and the entry port the same data type, or connect a port of the right type."));
        add(new Rule("RSA-03", "adjacent-layer-communication", Severity.ERROR, "paper",
                "A module communicates only with modules of its own layer or of the layer directly above or below.",
                "Route the data through a module of the layer in between, or move one of the modules."));
        add(new Rule("RSA-04", "subsume-layer-below", Severity.ERROR, "paper",
                "A module may inhibit outputs or suppress inputs only of modules of the layer immediately below its own.",
                "Target a port of a module one level below, or move the inhibitor or suppressor to the layer above the target."));
        add(new Rule("RSA-05", "real-time-module-timing", Severity.ERROR, "paper",
                "A real-time module has a non-zero period and a non-zero delay.",
                "Set the module's period and delay, or declare it simple."));
        add(new Rule("RSA-06", "real-time-module-functions", Severity.ERROR, "paper",
                "A module declared real-time has only real-time functions.",
                "Declare the functions real-time, or the module simple."));
        add(new Rule("RSA-07", "real-time-function-actions", Severity.ERROR, "paper",
                "A function declared real-time has only real-time actions.",
                "Declare the actions real-time, or the function simple."));
        add(new Rule("RSA-08", "layer-execution-budget", Severity.ERROR, "paper",
                "Every module's execution duration stays within its layer's maximum execution time (compared in one time unit).",
                "Shorten the module's execution duration, raise the layer's maximum, or move the module."));
        add(new Rule("RSA-09", "unique-names", Severity.ERROR, "RsaML",
                "Elements of the same kind in the same container have distinct names (references and generated code use them).",
                "Rename one of the elements."));
        add(new Rule("RSA-10", "execution-within-period", Severity.ERROR, "RsaML",
                "A periodic element's execution duration does not exceed its period.",
                "Shorten the execution duration or lengthen the period."));
        add(new Rule("RSA-11", "deadline-within-period", Severity.WARNING, "RsaML",
                "A periodic element's delay (deadline) does not exceed its period, so activations do not overlap.",
                "Shorten the delay, or lengthen the period if overlapping activations are really intended."));
        add(new Rule("RSA-12", "periodic-has-period", Severity.ERROR, "RsaML",
                "A periodic element has a period above zero.",
                "Set the period, or make the element sporadic or aperiodic."));
        add(new Rule("RSA-13", "non-negative-times", Severity.ERROR, "RsaML",
                "Periods, delays, execution durations, layer budgets and subsumption durations are not negative.",
                "Use zero for 'not set' and positive values otherwise."));
        add(new Rule("RSA-14", "layer-levels", Severity.ERROR, "RsaML",
                "Layer levels run from 0 upwards without gaps or duplicates.",
                "Renumber the layers 0, 1, 2, ... from the lowest."));
        add(new Rule("RSA-15", "rt-action-is-real-time", Severity.ERROR, "RsaML",
                "An RTAction is real-time.",
                "Set the RTAction's type to realTime, or make it a plain Action."));
        add(new Rule("RSA-16", "trigger-of-own-module", Severity.ERROR, "RsaML",
                "An inhibitor's or suppressor's trigger is an output port of the module that owns it.",
                "Choose an output port of the owning module as trigger."));
        add(new Rule("RSA-17", "execution-within-deadline", Severity.WARNING, "RsaML",
                "A real-time element's execution duration does not exceed its delay (it could never meet its deadline).",
                "Shorten the execution duration or relax the delay."));
        add(new Rule("RSA-18", "structured-port-message-type", Severity.WARNING, "RsaML",
                "A port of structured data names its message type.",
                "Set the port's messageType (for example geometry_msgs/msg/Twist)."));
    }

    private Rules() {
    }

    private static void add(Rule rule) {
        BY_ID.put(rule.id(), rule);
    }

    /** All rules, in id order. */
    public static List<Rule> all() {
        return List.copyOf(BY_ID.values());
    }

    public static Optional<Rule> byId(String id) {
        return Optional.ofNullable(BY_ID.get(id));
    }

    /** The rule an OCL constraint of rsaml.ecore implements: {@code RSA08_layerExecutionBudget} is RSA-08. */
    public static Optional<Rule> forConstraint(String constraintName) {
        if (constraintName == null || !constraintName.matches("RSA\\d\\d_.*")) {
            return Optional.empty();
        }
        return byId("RSA-" + constraintName.substring(3, 5));
    }
}
