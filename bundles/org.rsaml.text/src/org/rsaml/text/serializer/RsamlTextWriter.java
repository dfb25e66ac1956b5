/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.serializer;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.naming.QualifiedName;
import org.rsaml.model.Action;
import org.rsaml.model.Activity;
import org.rsaml.model.Actuator;
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
import org.rsaml.model.Plan;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.RTAction;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.RsamlPackage.Literals;
import org.rsaml.model.Sensor;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Supervisor;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.support.RsamlTimes;
import org.rsaml.text.naming.RsamlTextNameIndex;
import org.rsaml.text.naming.RsamlTextQualifiedNameProvider;
import org.rsaml.text.naming.RsamlTextSyntax;

import com.google.inject.Inject;

/**
 * Writes a model in the textual syntax, in its canonical layout (two spaces of indentation, one
 * attribute a line, a blank line before each element with a body). What is written is exactly what
 * is set, so reading the text back gives an equal model. References are written with the shortest
 * name that is unambiguous ({@link RsamlTextNameIndex}), but never shorter than {@code module.port}
 * for a port or {@code function.action} for an action.
 */
public class RsamlTextWriter {

    /** A model that the textual syntax cannot express (a reference into another file, two elements of one full name). */
    public static class UnwritableModelException extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        public UnwritableModelException(String message) {
            super(message);
        }
    }

    private static final String INDENT = "  ";

    @Inject
    private RsamlTextSyntax syntax;

    private StringBuilder out;
    private int depth;
    private Resource resource;
    private final Map<EClass, Map<EObject, QualifiedName>> referenceNames = new HashMap<>();

    /** The text of the architecture, ending with a line break. */
    public synchronized String write(Architecture architecture) {
        out = new StringBuilder(4096);
        depth = 0;
        resource = architecture.eResource();
        referenceNames.clear();
        try {
            architecture(architecture);
            return out.toString();
        } finally {
            out = null;
            referenceNames.clear();
            resource = null;
        }
    }

    /** A number as the text writes it: whole numbers without a fraction, others as Java writes doubles (exact). */
    public static String number(double d) {
        if (Double.isNaN(d)) {
            return "NaN";
        }
        if (Double.isInfinite(d)) {
            return d > 0 ? "Infinity" : "-Infinity";
        }
        if (d == Math.rint(d) && Math.abs(d) < 1e15 && !(d == 0 && 1 / d < 0)) {
            return Long.toString((long) d);
        }
        return Double.toString(d);
    }

    private void architecture(Architecture a) {
        open("architecture", a);
        attribute(a, Literals.ARCHITECTURE__CATEGORY, "category", () -> a.getCategory().getLiteral());
        attribute(a, Literals.ARCHITECTURE__DECLARED_LAYERS, "declaredLayers", () -> Integer.toString(a.getDeclaredLayers()));
        attribute(a, Literals.ARCHITECTURE__LIFECYCLE, "lifecycle", () -> a.getLifecycle().getLiteral());
        attribute(a, Literals.ARCHITECTURE__PACKAGES, "packages", () -> a.getPackages().getLiteral());
        a.getLayers().forEach(this::layer);
        if (!a.getConnections().isEmpty()) {
            blankLine();
            a.getConnections().forEach(this::connection);
        }
        a.getSensors().forEach(s -> device("sensor", s));
        a.getActuators().forEach(s -> device("actuator", s));
        a.getMissions().forEach(this::mission);
        a.getSupervisors().forEach(this::supervisor);
        a.getOrders().forEach(this::order);
        a.getDatabases().forEach(this::database);
        a.getProcessors().forEach(this::processor);
        a.getLatencyRequirements().forEach(this::latency);
        close();
    }

    private void layer(Layer l) {
        open("layer", l);
        attribute(l, Literals.LAYER__LEVEL, "level", () -> Integer.toString(l.getLevel()));
        boolean timed = time(l, Literals.LAYER__MAX_EXEC_TIME, "maxExecTime", l.getMaxExecTime());
        unitIfUnwritten(l, timed);
        l.getModules().forEach(this::module);
        close();
    }

    private void module(Module m) {
        open("module", m);
        realTime(m, false);
        references("sensors", m.getSensors(), Literals.SENSOR);
        references("actuators", m.getActuators(), Literals.ACTUATOR);
        attribute(m, Literals.MODULE__LIFECYCLE, "lifecycle", () -> m.getLifecycle().getLiteral());
        m.getPorts().forEach(this::port);
        m.getFunctions().forEach(this::function);
        m.getInhibitors().forEach(i -> link("inhibitor", i, i.getTarget(), Literals.OUTPUT_PORT));
        m.getSuppressors().forEach(s -> link("suppressor", s, s.getTarget(), Literals.ENTRY_PORT));
        close();
    }

    private void function(Function f) {
        open("function", f);
        realTime(f, false);
        attribute(f, Literals.FUNCTION__SYNCHRO_TYPE, "synchroType", () -> f.getSynchroType().getLiteral());
        attribute(f, Literals.FUNCTION__SCHED_POLICY, "schedPolicy", () -> f.getSchedPolicy().getLiteral());
        attribute(f, Literals.FUNCTION__OTHER_POLICY, "otherPolicy", () -> RsamlTextSyntax.quote(f.getOtherPolicy()));
        f.getActions().forEach(this::action);
        close();
    }

    private void action(Action a) {
        open(a instanceof RTAction ? "rtAction" : "action", a);
        realTime(a, true);
        close();
    }

    private void port(Port p) {
        open(p instanceof EntryPort ? "input" : "output", p);
        attribute(p, Literals.PORT__DATA_TYPE, "dataType", () -> p.getDataType().getLiteral());
        attribute(p, Literals.PORT__MESSAGE_TYPE, "messageType", () -> RsamlTextSyntax.quote(p.getMessageType()));
        attribute(p, Literals.PORT__TOPIC, "topic", () -> RsamlTextSyntax.quote(p.getTopic()));
        close();
    }

    private void connection(Connection c) {
        StringBuilder line = new StringBuilder("connect");
        if (c.getSource() != null) {
            line.append(' ').append(reference(c.getSource(), Literals.OUTPUT_PORT));
        }
        line.append(" ->");
        if (c.getTarget() != null) {
            line.append(' ').append(reference(c.getTarget(), Literals.ENTRY_PORT));
        }
        line(line.toString());
    }

    private void link(String keyword, SubsumptionLink l, EObject target, EClass targetType) {
        open(keyword, l);
        if (l.getTrigger() != null) {
            line("trigger " + reference(l.getTrigger(), Literals.OUTPUT_PORT));
        }
        if (target != null) {
            line("target " + reference(target, targetType));
        }
        boolean timed = time(l, Literals.SUBSUMPTION_LINK__DURATION, "duration", l.getDuration());
        unitIfUnwritten(l, timed);
        close();
    }

    private void device(String keyword, Device d) {
        open(keyword, d);
        attribute(d, Literals.DEVICE__KIND, "kind", () -> RsamlTextSyntax.quote(d.getKind()));
        attribute(d, Literals.DEVICE__DATA_TYPE, "dataType", () -> d.getDataType().getLiteral());
        boolean timed = time(d, Literals.DEVICE__PERIOD, "period", d.getPeriod());
        unitIfUnwritten(d, timed);
        close();
    }

    private void mission(Mission m) {
        open("mission", m);
        m.getGoals().forEach(this::goal);
        m.getPlans().forEach(this::plan);
        close();
    }

    private void goal(Goal g) {
        open("goal", g);
        attribute(g, Literals.GOAL__PRIORITY, "priority", () -> Integer.toString(g.getPriority()));
        g.getSubGoals().forEach(this::goal);
        close();
    }

    private void plan(Plan p) {
        open("plan", p);
        references("achieves", p.getAchieves(), Literals.GOAL);
        p.getActivities().forEach(this::activity);
        close();
    }

    private void activity(Activity a) {
        open("activity", a);
        realTime(a, false);
        references("actions", a.getActions(), Literals.ACTION);
        close();
    }

    private void supervisor(Supervisor s) {
        open("supervisor", s);
        references("plans", s.getPlans(), Literals.PLAN);
        if (s.getRealisedBy() != null) {
            line("realisedBy " + reference(s.getRealisedBy(), Literals.MODULE));
        }
        close();
    }

    private void order(Order o) {
        open("order", o);
        attribute(o, Literals.ORDER__ISSUER, "issuer", () -> RsamlTextSyntax.quote(o.getIssuer()));
        if (o.getReceiver() != null) {
            line("receiver " + reference(o.getReceiver(), Literals.MODULE));
        }
        if (o.getRequests() != null) {
            line("requests " + reference(o.getRequests(), Literals.ACTIVITY));
        }
        close();
    }

    private void database(Database d) {
        open("database", d);
        d.getKnowledge().forEach(this::knowledge);
        close();
    }

    private void knowledge(Knowledge k) {
        open("knowledge", k);
        attribute(k, Literals.KNOWLEDGE__DATA_TYPE, "dataType", () -> k.getDataType().getLiteral());
        references("usedBy", k.getUsedBy(), Literals.MODULE);
        close();
    }

    private void processor(Processor p) {
        open("processor", p);
        attribute(p, Literals.PROCESSOR__SCHED_POLICY, "schedPolicy", () -> p.getSchedPolicy().getLiteral());
        attribute(p, Literals.PROCESSOR__CORE, "core", () -> Integer.toString(p.getCore()));
        attribute(p, Literals.PROCESSOR__HOST, "host", () -> RsamlTextSyntax.quote(p.getHost()));
        boolean timed = time(p, Literals.PROCESSOR__LINK_LATENCY, "linkLatency", p.getLinkLatency());
        unitIfUnwritten(p, timed);
        references("modules", p.getModules(), Literals.MODULE);
        close();
    }

    private void latency(LatencyRequirement r) {
        open("latency", r);
        if (r.getSource() != null) {
            line("from " + reference(r.getSource(), Literals.NAMED_ELEMENT));
        }
        if (r.getTarget() != null) {
            line("to " + reference(r.getTarget(), Literals.NAMED_ELEMENT));
        }
        references("via", r.getVia(), Literals.NAMED_ELEMENT);
        boolean timed = time(r, Literals.LATENCY_REQUIREMENT__MAX_LATENCY, "maxLatency", r.getMaxLatency());
        attribute(r, Literals.LATENCY_REQUIREMENT__KIND, "kind", () -> r.getKind().getLiteral());
        unitIfUnwritten(r, timed);
        close();
    }

    private void realTime(RealTimeElement e, boolean action) {
        attribute(e, Literals.REAL_TIME_ELEMENT__TYPE, "type", () -> e.getType().getLiteral());
        attribute(e, Literals.REAL_TIME_ELEMENT__EXEC_TYPE, "execType", () -> e.getExecType().getLiteral());
        boolean timed = time(e, Literals.REAL_TIME_ELEMENT__PERIOD, "period", e.getPeriod());
        timed |= time(e, Literals.REAL_TIME_ELEMENT__DELAY, "deadline", e.getDelay());
        timed |= time(e, Literals.REAL_TIME_ELEMENT__EXEC_DURATION, "wcet", e.getExecDuration());
        if (action) {
            timed |= time(e, Literals.ACTION__START_DATE, "start", ((Action) e).getStartDate());
        }
        unitIfUnwritten(e, timed);
    }

    /** A time value with the element's unit, when set. */
    private boolean time(TimeScaled e, EAttribute feature, String keyword, double value) {
        if (!e.eIsSet(feature)) {
            return false;
        }
        line(keyword + " " + number(value) + " " + RsamlTimes.unit(e).getLiteral());
        return true;
    }

    /** The unit on its own, when it is not the default and no time value carries it. */
    private void unitIfUnwritten(TimeScaled e, boolean written) {
        if (!written && RsamlTimes.unit(e) != RsamlTimes.DEFAULT_UNIT) {
            line("unit " + RsamlTimes.unit(e).getLiteral());
        }
    }

    private void attribute(EObject e, EAttribute feature, String keyword, java.util.function.Supplier<String> value) {
        if (e.eIsSet(feature) && e.eGet(feature) != null) {
            line(keyword + " " + value.get());
        }
    }

    private void references(String keyword, List<? extends EObject> targets, EClass type) {
        if (targets.isEmpty()) {
            return;
        }
        StringBuilder line = new StringBuilder(keyword);
        for (int i = 0; i < targets.size(); i++) {
            line.append(i == 0 ? " " : ", ").append(reference(targets.get(i), type));
        }
        line(line.toString());
    }

    private String reference(EObject target, EClass type) {
        if (target.eIsProxy() || target.eResource() != resource) {
            throw new UnwritableModelException("a reference to " + describe(target)
                    + " leads into another file; a textual model holds all it refers to: convert the model it is in into this one first");
        }
        QualifiedName name = referenceNames.computeIfAbsent(type, this::shortestNames).get(target);
        if (name == null) {
            throw new UnwritableModelException("a reference to " + describe(target) + " cannot be written: "
                    + (target instanceof NamedElement n && n.getName() != null
                            ? "another " + type.getName() + " has the same full name; give them different names"
                            : "it or one of its containers has no name; name them"));
        }
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < name.getSegmentCount(); i++) {
            text.append(i == 0 ? "" : ".").append(syntax.referenceSegment(name.getSegment(i), i == 0));
        }
        return text.toString();
    }

    /** For each element of the type, its shortest name in the reference table that names it alone. */
    private Map<EObject, QualifiedName> shortestNames(EClass type) {
        Map<EObject, QualifiedName> shortest = new HashMap<>();
        RsamlTextNameIndex.names(resource, type).forEach((name, element) -> {
            int minimum = element instanceof Port || element instanceof Action ? 2 : 1;
            if (name.getSegmentCount() < minimum && RsamlTextQualifiedNameProvider.qualifiedName(element).getSegmentCount() >= minimum) {
                return;
            }
            shortest.merge(element, name, (a, b) -> b.getSegmentCount() < a.getSegmentCount() ? b : a);
        });
        return shortest;
    }

    private static String describe(EObject target) {
        String name = target instanceof NamedElement n && n.getName() != null ? " '" + n.getName() + "'" : "";
        return target.eClass().getName() + name;
    }

    private void open(String keyword, NamedElement e) {
        if (depth > 0) {
            blankLine();
        }
        String head = e.getName() == null ? keyword : keyword + " " + syntax.declaredName(e.getName());
        line(head + " {");
        depth++;
        attribute(e, Literals.NAMED_ELEMENT__DESCRIPTION, "description", () -> RsamlTextSyntax.quote(e.getDescription()));
    }

    private void close() {
        depth--;
        if (endsWithOpening()) {
            // Nothing inside: {} on the same line.
            out.setLength(out.length() - 1);
            out.append("}\n");
        } else {
            line("}");
        }
    }

    private void blankLine() {
        int length = out.length();
        if (length > 0 && !(length >= 2 && out.charAt(length - 2) == '\n') && !endsWithOpening()) {
            out.append('\n');
        }
    }

    private boolean endsWithOpening() {
        int length = out.length();
        return length >= 3 && out.charAt(length - 1) == '\n' && out.charAt(length - 2) == '{' && out.charAt(length - 3) == ' ';
    }

    private void line(String text) {
        for (int i = 0; i < depth; i++) {
            out.append(INDENT);
        }
        out.append(text).append('\n');
    }
}
