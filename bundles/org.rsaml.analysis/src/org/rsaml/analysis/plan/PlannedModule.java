/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.rsaml.model.Action;
import org.rsaml.model.Function;
import org.rsaml.model.Module;
import org.rsaml.model.Processor;
import org.rsaml.model.support.RsamlLabels;

public final class PlannedModule {
    final ExecutionPlan plan;
    final PlannedLayer layer;
    final Module module;
    final String name;
    final String qualifiedName;
    final List<PlannedFunction> functions = new ArrayList<>();
    final List<PlannedPort> ports = new ArrayList<>();
    final List<PlannedPort> inputs = new ArrayList<>();
    final List<PlannedPort> outputs = new ArrayList<>();
    final List<Release> releases = new ArrayList<>();
    final List<PlannedFunction> stepFunctions = new ArrayList<>();
    boolean periodic;
    boolean reactive;
    long minIntervalNs;
    Reaction reaction;
    Processor processor;

    PlannedModule(ExecutionPlan plan, PlannedLayer layer, Module module) {
        this.plan = plan;
        this.layer = layer;
        this.module = module;
        this.name = RsamlLabels.name(module);
        this.qualifiedName = layer.name + "/" + name;
        for (Function f : module.getFunctions()) {
            PlannedFunction pf = new PlannedFunction(this, f);
            functions.add(pf);
            for (Action a : f.getActions()) {
                pf.actions.add(new PlannedAction(pf, a));
            }
        }
    }

    public ExecutionPlan plan() {
        return plan;
    }

    public PlannedLayer layer() {
        return layer;
    }

    public Module module() {
        return module;
    }

    public String name() {
        return name;
    }

    /** {@code layer/module}, the model's names, as traces and messages show them. */
    public String qualifiedName() {
        return qualifiedName;
    }

    public String description() {
        return module.getDescription();
    }

    public List<PlannedFunction> functions() {
        return Collections.unmodifiableList(functions);
    }

    public List<PlannedPort> ports() {
        plan.requireConnected();
        return Collections.unmodifiableList(ports);
    }

    public List<PlannedPort> inputs() {
        plan.requireConnected();
        return Collections.unmodifiableList(inputs);
    }

    public List<PlannedPort> outputs() {
        plan.requireConnected();
        return Collections.unmodifiableList(outputs);
    }

    /** Its timed releases. */
    public List<Release> releases() {
        return Collections.unmodifiableList(releases);
    }

    /** Functions run when data arrives or when the module itself is released. */
    public List<PlannedFunction> stepFunctions() {
        return Collections.unmodifiableList(stepFunctions);
    }

    /** Whether the module has a period of its own. */
    public boolean periodic() {
        return periodic;
    }

    /** The processor the module is allocated to, or null: then it runs on the default processor. */
    public Processor processor() {
        return processor;
    }

    /** The CPU core the module's threads are pinned to, or -1 to leave the choice to the operating system. */
    public int core() {
        return processor == null ? -1 : processor.getCore();
    }

    /** Whether the module reacts to arriving data. */
    public boolean reactive() {
        return reactive;
    }

    /** Its reaction to data, or null when it does not react. */
    public Reaction reaction() {
        return reaction;
    }

    /** For a sporadic module, the minimum time between two reactions (0: none). */
    public long minIntervalNs() {
        return minIntervalNs;
    }

    public List<PlannedAction> actions() {
        List<PlannedAction> all = new ArrayList<>();
        functions.forEach(f -> all.addAll(f.actions));
        return all;
    }

    /** The module's timing as the model states it, for documentation. */
    public String timing() {
        return RsamlLabels.timing(module);
    }
}
