/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.rsaml.model.Architecture;
import org.rsaml.model.Port;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlTimes;

/**
 * How an architecture executes, independent of any target language: what is released when, what
 * reacts to what, and what flows where. Every code generator renders this plan; a timing analysis
 * can take its task set from {@link #releases()} and {@link #reactions()}. All times are integral
 * nanoseconds; everything is in model order, so the same model gives the same plan.
 *
 * <p>The execution model:
 * <ul>
 * <li>a periodic function is a {@link Release} every period; it runs its actions in order, each at
 * its start date within the period ({@link PlannedAction#offsetNs()});</li>
 * <li>a periodic action whose period differs from its function's (or whose function is not
 * periodic) is a release of its own, first at its start date;</li>
 * <li>a periodic module with functions that are not periodic (or with no timed activity at all) is
 * released every module period and runs those functions ({@link PlannedModule#stepFunctions()});</li>
 * <li>a module that is not periodic reacts to arriving data ({@link Reaction}): each arrival runs
 * its step functions, a sporadic module at most once per period, a sporadic function at most once
 * per its period;</li>
 * <li>after each activation the module sends its outputs along its {@link Flow}s; an
 * {@link LinkPlan inhibitor} blocks an output while active, a suppressor replaces an input;</li>
 * <li>at start every module runs once, lowest layer first, and sends its initial outputs.</li>
 * </ul>
 *
 * <p>Priorities follow the scheduling policy of the released element's function: rate monotonic
 * by period, deadline monotonic by deadline (shorter is higher); every other policy runs
 * first-in first-out at the base priority ({@link Release#rank()} 1).
 *
 * <p>A model is planned only when every time it uses can be represented: finite, not negative, a
 * period of at least 1 ns once converted, and at most {@link #MAX_TIME_NS}. Otherwise
 * {@link #of(Architecture)} throws an {@link UnplannableException} naming the element.
 *
 * <p>This class holds the plan; its types are the package's ({@link PlannedLayer},
 * {@link PlannedModule}, {@link PlannedFunction}, {@link PlannedAction}, {@link PlannedPort},
 * {@link Flow}, {@link LinkPlan}, {@link Release}, {@link Reaction}); {@code Planner} builds it,
 * {@link PlanTimes} reads the model's times, {@code PlanWarnings} words what cannot execute and
 * {@code ReactiveCycles} finds the reactive cycles.
 */
public final class ExecutionPlan {

    /**
     * The longest time a plan holds, 2^60 ns (about 36.5 years): generated code counts time in
     * signed 64-bit nanoseconds from the start of the run and must add a period and an offset to
     * it without overflow.
     */
    public static final long MAX_TIME_NS = RsamlTimes.MAX_NANOSECONDS.longValueExact();

    private final Architecture architecture;
    private final String name;
    final List<PlannedLayer> layers = new ArrayList<>();
    final List<PlannedModule> modules = new ArrayList<>();
    final List<Flow> flows = new ArrayList<>();
    final List<LinkPlan> links = new ArrayList<>();
    final List<Release> releases = new ArrayList<>();
    final List<Reaction> reactions = new ArrayList<>();
    final Set<String> messageTypes = new LinkedHashSet<>();
    final List<String> warnings = new ArrayList<>();
    final Map<Port, PlannedPort> ports;

    /** An empty plan, filled by the {@link Planner}, for about {@code ports} ports (its map sized once). */
    ExecutionPlan(Architecture architecture, int ports, boolean connected) {
        this.architecture = architecture;
        this.name = RsamlLabels.name(architecture);
        this.ports = new IdentityHashMap<>(ports);
        this.connected = connected;
    }

    /** Whether the plan holds what connects the modules: false for a plan of releases alone ({@link #releasesOf}). */
    final boolean connected;

    /** Refuses to answer what a plan of releases alone does not hold (rather than answer "nothing"). */
    void requireConnected() {
        if (!connected) {
            throw new IllegalStateException("a plan of releases alone (ExecutionPlan.releasesOf) holds no ports, flows or links:"
                    + " ExecutionPlan.of plans them");
        }
    }

    /**
     * The plan of an architecture.
     *
     * @throws UnplannableException a time of the model cannot be represented (not finite, negative,
     *                              a period below 1 ns, or longer than {@link #MAX_TIME_NS})
     */
    public static ExecutionPlan of(Architecture architecture) throws UnplannableException {
        return Planner.plan(architecture, true);
    }

    /**
     * The plan of an architecture's releases and reactions alone, as {@link #of} plans them (the same layers, modules,
     * releases, reactions and ranks, refused where it is refused), without what connects the modules: no ports, flows,
     * links, message types or the warnings about them (asking it for them, or a module for its ports, is an
     * {@link IllegalStateException}). What the timing analysis reads of an architecture without latency requirements,
     * without a pass over every port and connection.
     *
     * @throws UnplannableException where {@link #of} throws it
     */
    public static ExecutionPlan releasesOf(Architecture architecture) throws UnplannableException {
        return Planner.plan(architecture, false);
    }

    public Architecture architecture() {
        return architecture;
    }

    /** The architecture's name as the model spells it. */
    public String name() {
        return name;
    }

    public String description() {
        return architecture.getDescription();
    }

    /** Layers in model order. */
    public List<PlannedLayer> layers() {
        return Collections.unmodifiableList(layers);
    }

    /** Modules lowest layer first, then in model order: the order of the start steps. */
    public List<PlannedModule> modules() {
        return Collections.unmodifiableList(modules);
    }

    /** Every timed release of every module. */
    public List<Release> releases() {
        return Collections.unmodifiableList(releases);
    }

    /** Every module that reacts to arriving data. */
    public List<Reaction> reactions() {
        return Collections.unmodifiableList(reactions);
    }

    /** The connections that carry data (those that cannot are left out, with a warning). */
    public List<Flow> flows() {
        requireConnected();
        return Collections.unmodifiableList(flows);
    }

    /** Inhibitors and suppressors that can act (the others are left out, with a warning). */
    public List<LinkPlan> links() {
        requireConnected();
        return Collections.unmodifiableList(links);
    }

    /** Structured message type names as written on the ports, first use first. */
    public List<String> messageTypes() {
        requireConnected();
        return List.copyOf(messageTypes);
    }

    /** Model elements that cannot execute as modeled. */
    public List<String> warnings() {
        requireConnected();
        return Collections.unmodifiableList(warnings);
    }

    /** The plan of a port, or null when the port is not in a module of a layer. */
    public PlannedPort port(Port port) {
        requireConnected();
        return port == null ? null : ports.get(port);
    }

    /**
     * Modules that react to data (not timed) and to each other in a cycle, each cycle in module
     * order. Where data carries no wave (see {@link Reaction}), a message would go round for ever.
     */
    public List<List<PlannedModule>> reactiveCycles() {
        requireConnected();
        return ReactiveCycles.of(this);
    }

    /** A layer and its modules. */

    /** How a module is activated: its timed releases, its reaction to data, its functions and ports. */

    /** A function of a module: released on its own when periodic, otherwise run by its module. */

    /** An action of a function: run by it in order, or released on its own. */

    /** The kind of data a port carries. */

    /** An entry or output port and the flows and links that touch it. */

    /** Data flowing along a connection from an output port to an entry port. */

    /** An inhibitor or a suppressor: active for its duration after each message on its trigger. */

    /** What a release runs. */

}
