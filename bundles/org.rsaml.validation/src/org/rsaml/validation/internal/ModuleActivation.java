/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.rsaml.model.Action;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Port;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.Suppressor;

/**
 * RSA-19's least fixpoint, computed once per validation instead of once per module. The invariant
 * {@code RSA19_activatedModule} of {@code rsaml.ecore} stays the rule's definition: a module is
 * activated when it or a module in the closure of its feeders (modules whose output ports deliver
 * data to its entry ports, through a connection or a suppressor whose two ports carry the same
 * data; the closure goes on through modules that are not timed themselves) is timed, i.e.
 * periodic with a period above 0 or with such a function or action. Evaluated literally, classic
 * OCL runs one {@code closure()} per module, recursively, so a chain of n modules costs n² and a
 * stack frame per hop. Here the same set is found by graph traversals without recursion: each
 * module's feeders are collected once, and activation spreads forward from the timed modules, so
 * every module and every feeding edge is visited a bounded number of times. The interpreter
 * remains the oracle: the validation tests compare the two on every example, rule fixture and
 * random model.
 */
public final class ModuleActivation {

    /** The constraint this evaluates, as named in rsaml.ecore. */
    public static final String CONSTRAINT = "RSA19_activatedModule";

    /** Decided modules: activated or not. */
    private final Map<Module, Boolean> decided = new IdentityHashMap<>();

    /** Facts of their own, for one question or for a test; {@link #of} shares them in a validation. */
    public ModuleActivation() {
    }

    /** The activation facts of one validation, shared through EMF's validation context. */
    public static ModuleActivation of(Map<Object, Object> context) {
        if (context == null) {
            return new ModuleActivation();
        }
        return (ModuleActivation) context.computeIfAbsent(ModuleActivation.class, k -> new ModuleActivation());
    }

    /** Whether RSA-19 holds for the module: something activates it. */
    public boolean isActivated(Module module) {
        Boolean known = decided.get(module);
        if (known == null) {
            decideAround(module);
            known = decided.get(module);
        }
        return known;
    }

    /**
     * Decides every module the start module's activation depends on: the modules that feed it,
     * transitively (collected breadth first, each with its feeders), then activation spread from
     * the timed ones (and from feeders decided by an earlier call) along the feeding edges.
     */
    private void decideAround(Module start) {
        Map<Module, List<Module>> feeders = new HashMap<>();
        ArrayDeque<Module> work = new ArrayDeque<>();
        feeders.put(start, null);
        work.add(start);
        List<Module> pending = new ArrayList<>();
        while (!work.isEmpty()) {
            Module m = work.poll();
            pending.add(m);
            List<Module> from = feedersOf(m);
            feeders.put(m, from);
            for (Module f : from) {
                if (!decided.containsKey(f) && !feeders.containsKey(f)) {
                    feeders.put(f, null);
                    work.add(f);
                }
            }
        }
        // Who each pending module feeds, and the modules activation starts from.
        Map<Module, List<Module>> feeds = new HashMap<>();
        ArrayDeque<Module> activated = new ArrayDeque<>();
        Map<Module, Boolean> result = new IdentityHashMap<>();
        for (Module m : pending) {
            boolean on = timed(m);
            for (Module f : feeders.get(m)) {
                if (Boolean.TRUE.equals(decided.get(f))) {
                    on = true;
                } else if (!decided.containsKey(f)) {
                    feeds.computeIfAbsent(f, k -> new ArrayList<>()).add(m);
                }
            }
            if (on) {
                result.put(m, Boolean.TRUE);
                activated.add(m);
            }
        }
        while (!activated.isEmpty()) {
            for (Module next : feeds.getOrDefault(activated.poll(), List.of())) {
                if (result.putIfAbsent(next, Boolean.TRUE) == null) {
                    activated.add(next);
                }
            }
        }
        for (Module m : pending) {
            decided.put(m, result.getOrDefault(m, Boolean.FALSE));
        }
    }

    /**
     * The modules whose data reaches the module's entry ports, as the invariant's closure step
     * collects them: through incoming connections and suppressors whose trigger carries the
     * entry port's data type (and, for structured data, its message type).
     */
    private static List<Module> feedersOf(Module m) {
        List<Module> from = new ArrayList<>();
        for (Port p : m.getPorts()) {
            if (p instanceof EntryPort e) {
                for (Connection c : e.getIncoming()) {
                    add(from, c.getSource(), e);
                }
                for (Suppressor s : e.getSuppressedBy()) {
                    add(from, s.getTrigger(), e);
                }
            }
        }
        return from;
    }

    private static void add(List<Module> from, OutputPort source, EntryPort e) {
        if (source != null && source.getModule() != null && source.getDataType() == e.getDataType()
                && (e.getDataType() != DataType.STRUCTURED
                        || Objects.equals(source.normalizedMessageType(), e.normalizedMessageType()))) {
            from.add(source.getModule());
        }
    }

    /** Periodic with a period above 0, or a function or action of it is. */
    private static boolean timed(Module m) {
        if (periodic(m)) {
            return true;
        }
        for (Function f : m.getFunctions()) {
            if (periodic(f)) {
                return true;
            }
            for (Action a : f.getActions()) {
                if (periodic(a)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean periodic(RealTimeElement e) {
        return e.getExecType() == ExecutionType.PERIODIC && e.getPeriod() > 0;
    }
}
