/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.Action;
import org.rsaml.model.Activity;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.Database;
import org.rsaml.model.Device;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Function;
import org.rsaml.model.Goal;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Knowledge;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.Layer;
import org.rsaml.model.Mission;
import org.rsaml.model.Module;
import org.rsaml.model.NamedElement;
import org.rsaml.model.Order;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Plan;
import org.rsaml.model.Processor;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.Suppressor;
import org.rsaml.model.Supervisor;

/**
 * Seeded random architectures: every concept, every attribute set or not, odd names, odd numbers
 * (NaN, infinities, -0, the smallest and largest doubles), references of every kind. Names are
 * unique among all the children of one element, as the textual syntax needs to name references.
 */
final class RandomModels {

    private static final RsamlFactory F = RsamlFactory.eINSTANCE;
    private static final String[] NAMES = { "a", "b", "lidarDriver", "scan", "plan", "module", "s", "ms", "NaN", "x1",
            "caf\u00e9", "a b", "a.b", "\"quoted\"", "back\\slash", "", " ", "\u6a21\u5757", "\ud83e\udd16robot", "\u202eevil",
            "line\nbreak", "tab\there", "_", "Z9", "type", "connect", "lifecycle", "managed" };
    private static final double[] NUMBERS = { 0, 1, 2.5, 50, 1e-9, 1e21, -1, -0.0, Double.NaN, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.MIN_VALUE, Double.MAX_VALUE, 0.1, 1.0 / 3, 123456789012345.0, 1e15 };
    private static final int[] INTEGERS = { 0, 1, -1, 7, Integer.MAX_VALUE, Integer.MIN_VALUE };

    private final Random random;
    private final List<OutputPort> outputs = new ArrayList<>();
    private final List<EntryPort> entries = new ArrayList<>();
    private final List<Module> modules = new ArrayList<>();
    private final List<Action> actions = new ArrayList<>();
    private final List<Goal> goals = new ArrayList<>();
    private final List<Plan> plans = new ArrayList<>();
    private final List<Activity> activities = new ArrayList<>();
    private final List<NamedElement> named = new ArrayList<>();
    private final List<Device> sensors = new ArrayList<>();
    private final List<Device> actuators = new ArrayList<>();

    RandomModels(long seed) {
        this.random = new Random(seed);
    }

    Architecture architecture() {
        Architecture a = F.createArchitecture();
        Set<String> used = new HashSet<>();
        common(a, used, true);
        for (int i = count(3); i > 0; i--) {
            Layer l = F.createLayer();
            a.getLayers().add(name(l, used));
            layer(l);
        }
        for (int i = count(3); i > 0; i--) {
            var s = F.createSensor();
            a.getSensors().add(name(s, used));
            sensors.add(s);
        }
        for (int i = count(2); i > 0; i--) {
            var s = F.createActuator();
            a.getActuators().add(name(s, used));
            actuators.add(s);
        }
        for (int i = count(2); i > 0; i--) {
            Mission m = F.createMission();
            a.getMissions().add(name(m, used));
            mission(m);
        }
        for (int i = count(2); i > 0; i--) {
            Database d = F.createDatabase();
            a.getDatabases().add(name(d, used));
            Set<String> inner = new HashSet<>();
            for (int k = count(2); k > 0; k--) {
                Knowledge kn = F.createKnowledge();
                d.getKnowledge().add(name(kn, inner));
            }
        }
        for (Module m : modules) {
            pick(sensors, 2).forEach(s -> m.getSensors().add((org.rsaml.model.Sensor) s));
            pick(actuators, 2).forEach(s -> m.getActuators().add((org.rsaml.model.Actuator) s));
        }
        for (int i = count(4); i > 0; i--) {
            Connection c = F.createConnection();
            a.getConnections().add(c);
            if (random.nextInt(8) > 0 && !outputs.isEmpty()) {
                c.setSource(outputs.get(random.nextInt(outputs.size())));
            }
            if (random.nextInt(8) > 0 && !entries.isEmpty()) {
                c.setTarget(entries.get(random.nextInt(entries.size())));
            }
        }
        for (Module m : modules) {
            Set<String> inner = new HashSet<>();
            m.getPorts().forEach(p -> inner.add(p.getName()));
            m.getFunctions().forEach(p -> inner.add(p.getName()));
            for (int i = count(1); i > 0; i--) {
                Inhibitor in = F.createInhibitor();
                m.getInhibitors().add(name(in, inner));
                timeScaled(in);
                maybe(() -> in.setDuration(number()));
                maybe(() -> in.setTrigger(one(outputs)));
                maybe(() -> in.setTarget(one(outputs)));
            }
            for (int i = count(1); i > 0; i--) {
                Suppressor su = F.createSuppressor();
                m.getSuppressors().add(name(su, inner));
                timeScaled(su);
                maybe(() -> su.setDuration(number()));
                maybe(() -> su.setTrigger(one(outputs)));
                maybe(() -> su.setTarget(one(entries)));
            }
        }
        for (int i = count(2); i > 0; i--) {
            Supervisor s = F.createSupervisor();
            a.getSupervisors().add(name(s, used));
            pick(plans, 2).forEach(p -> s.getPlans().add((Plan) p));
            maybe(() -> s.setRealisedBy(one(modules)));
        }
        for (int i = count(2); i > 0; i--) {
            Order o = F.createOrder();
            a.getOrders().add(name(o, used));
            maybe(() -> o.setIssuer(text()));
            maybe(() -> o.setReceiver(one(modules)));
            maybe(() -> o.setRequests(one(activities)));
        }
        for (Database d : a.getDatabases()) {
            for (Knowledge k : d.getKnowledge()) {
                enumAttribute(k);
                pick(modules, 2).forEach(m -> k.getUsedBy().add((Module) m));
            }
        }
        for (int i = count(2); i > 0; i--) {
            Processor p = F.createProcessor();
            a.getProcessors().add(name(p, used));
            if (random.nextBoolean()) {
                p.setSchedPolicy(org.rsaml.model.SchedulingPolicy.get(random.nextInt(8)));
            }
            maybe(() -> p.setCore(integer()));
            maybe(() -> p.setHost(text()));
            timeScaled(p);
            maybe(() -> p.setLinkLatency(number()));
            pick(modules, 3).forEach(m -> p.getModules().add((Module) m));
        }
        for (int i = count(2); i > 0; i--) {
            LatencyRequirement r = F.createLatencyRequirement();
            a.getLatencyRequirements().add(name(r, used));
            timeScaled(r);
            enumAttribute(r);
            maybe(() -> r.setMaxLatency(number()));
            maybe(() -> r.setSource(one(named)));
            maybe(() -> r.setTarget(one(named)));
            pick(named, 3).forEach(x -> r.getVia().add((NamedElement) x));
        }
        return a;
    }

    private void layer(Layer l) {
        timeScaled(l);
        maybe(() -> l.setLevel(integer()));
        maybe(() -> l.setMaxExecTime(number()));
        Set<String> used = new HashSet<>();
        for (int i = count(3); i > 0; i--) {
            Module m = F.createModule();
            l.getModules().add(name(m, used));
            modules.add(m);
            realTime(m);
            Set<String> inner = new HashSet<>();
            for (int k = count(3); k > 0; k--) {
                if (random.nextBoolean()) {
                    OutputPort p = F.createOutputPort();
                    m.getPorts().add(name(p, inner));
                    outputs.add(p);
                    port(p);
                } else {
                    EntryPort p = F.createEntryPort();
                    m.getPorts().add(name(p, inner));
                    entries.add(p);
                    port(p);
                }
            }
            for (int k = count(2); k > 0; k--) {
                Function f = F.createFunction();
                m.getFunctions().add(name(f, inner));
                realTime(f);
                enumAttribute(f);
                maybe(() -> f.setOtherPolicy(text()));
                Set<String> acts = new HashSet<>();
                for (int j = count(2); j > 0; j--) {
                    Action a = random.nextBoolean() ? F.createAction() : F.createRTAction();
                    f.getActions().add(name(a, acts));
                    realTime(a);
                    maybe(() -> a.setStartDate(number()));
                    actions.add(a);
                }
            }
        }
    }

    private void mission(Mission m) {
        Set<String> used = new HashSet<>();
        for (int i = count(2); i > 0; i--) {
            Goal g = F.createGoal();
            m.getGoals().add(name(g, used));
            goal(g, 0);
        }
        for (int i = count(2); i > 0; i--) {
            Plan p = F.createPlan();
            m.getPlans().add(name(p, used));
            plans.add(p);
            pick(goals, 2).forEach(g -> p.getAchieves().add((Goal) g));
            Set<String> inner = new HashSet<>();
            for (int k = count(2); k > 0; k--) {
                Activity a = F.createActivity();
                p.getActivities().add(name(a, inner));
                realTime(a);
                activities.add(a);
                pick(actions, 2).forEach(x -> a.getActions().add((Action) x));
            }
        }
    }

    private void goal(Goal g, int depth) {
        goals.add(g);
        maybe(() -> g.setPriority(integer()));
        Set<String> used = new HashSet<>();
        for (int i = depth < 3 ? count(2) : 0; i > 0; i--) {
            Goal sub = F.createGoal();
            g.getSubGoals().add(name(sub, used));
            goal(sub, depth + 1);
        }
    }

    private void port(org.rsaml.model.Port p) {
        enumAttribute(p);
        maybe(() -> p.setMessageType(text()));
    }

    private void realTime(org.rsaml.model.RealTimeElement e) {
        timeScaled(e);
        enumAttribute(e);
        maybe(() -> e.setPeriod(number()));
        maybe(() -> e.setDelay(number()));
        maybe(() -> e.setExecDuration(number()));
    }

    private void timeScaled(org.rsaml.model.TimeScaled e) {
        if (random.nextInt(3) == 0) {
            e.setTimeUnit(org.rsaml.model.TimeUnit.VALUES.get(random.nextInt(4)));
        }
    }

    /** Sets some of the element's enumeration attributes (other than the time unit) to random literals. */
    private void enumAttribute(EObject e) {
        for (EAttribute attribute : e.eClass().getEAllAttributes()) {
            if (attribute.getEType() instanceof EEnum type && !attribute.getName().equals("timeUnit") && random.nextBoolean()) {
                e.eSet(attribute, type.getELiterals().get(random.nextInt(type.getELiterals().size())).getInstance());
            }
        }
    }

    private void common(NamedElement e, Set<String> used, boolean architecture) {
        if (architecture) {
            e.setName(random.nextInt(5) == 0 ? null : NAMES[random.nextInt(NAMES.length)]);
            maybe(() -> ((Architecture) e).setDeclaredLayers(integer()));
            if (random.nextBoolean()) {
                enumAttribute(e);
            }
        }
        maybe(() -> e.setDescription(text()));
    }

    private <T extends NamedElement> T name(T e, Set<String> used) {
        String name;
        int tries = 0;
        do {
            name = NAMES[random.nextInt(NAMES.length)] + (tries++ > 3 ? tries : "");
        } while (!used.add(name));
        e.setName(name);
        maybe(() -> e.setDescription(text()));
        named.add(e);
        return e;
    }

    private String text() {
        return random.nextInt(4) == 0 ? "" : NAMES[random.nextInt(NAMES.length)] + " " + NAMES[random.nextInt(NAMES.length)];
    }

    private double number() {
        return random.nextInt(4) == 0 ? random.nextDouble() * Math.pow(10, random.nextInt(40) - 20) : NUMBERS[random.nextInt(NUMBERS.length)];
    }

    private int integer() {
        return random.nextBoolean() ? random.nextInt(100) - 10 : INTEGERS[random.nextInt(INTEGERS.length)];
    }

    private int count(int max) {
        return random.nextInt(max + 1);
    }

    private void maybe(Runnable r) {
        if (random.nextBoolean()) {
            r.run();
        }
    }

    private <T> T one(List<T> list) {
        return list.isEmpty() ? null : list.get(random.nextInt(list.size()));
    }

    private List<Object> pick(List<?> list, int max) {
        List<Object> picked = new ArrayList<>();
        for (int i = count(max); i > 0 && !list.isEmpty(); i--) {
            Object o = list.get(random.nextInt(list.size()));
            if (!picked.contains(o)) {
                picked.add(o);
            }
        }
        return picked;
    }
}
