/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import static org.rsaml.model.support.RsamlLabels.duration;
import static org.rsaml.model.support.RsamlLabels.name;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.Device;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.NamedElement;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Suppressor;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlText;
import org.rsaml.model.support.RsamlTimes;

/**
 * The named parameters of the catalogue's message templates, computed from the element a finding is
 * on, in this one place: {@code {element}} is {@code module 'resourceChecker'}, {@code {Element}} the
 * same capitalised, and every other parameter is a fact of the element. A template may use any
 * parameter that applies to the classes its rule is checked on.
 */
public final class MessageParameters {

    private static final Pattern PARAMETER = Pattern.compile("\\{(\\w+)}");
    /** The parameters computed from the element, in this class's order. */
    private static final List<String> COMPUTED = List.of("element", "Element", "name",
            // timing
            "period", "delay", "execDuration", "missingTiming", "negativeTimes", "nonRepresentableTimes",
            // layers
            "layerName", "layerBudget", "declaredLayers", "layerCount", "layerNames", "layerLevels", "maxLevel",
            // contents
            "nonRealTimeFunctions", "nonRealTimeActions", "inputs", "neverHappens", "duplicates", "longTexts",
            // connections
            "source", "target", "sourceType", "targetType", "sourceLayer", "targetLayer", "skippedLayers",
            // topics and packages
            "portModule", "topicProblem", "packageProblem",
            // subsumption
            "owner", "ownerLayer", "levelBelow", "subsumes", "subsumable", "trigger", "linkDuration", "linkKind", "asserting",
            "triggerSends", "lapseEffect",
            // budgets of functions and actions
            "exceededBudgets");

    /** Every parameter a template may use: the computed ones, then the results the timing checks supply with a finding. */
    private static final Set<String> NAMES;

    static {
        Set<String> names = new LinkedHashSet<>(COMPUTED);
        names.addAll(TimingChecks.PARAMETERS);
        NAMES = Collections.unmodifiableSet(names);
    }

    private MessageParameters() {
    }

    /** The names a template may use. */
    public static Set<String> names() {
        return NAMES;
    }

    /*
     * The value of one of the names, by a switch rather than a table of lambdas: each lambda would be linked through the
     * JVM's method-handle bootstrap in every process that reports a finding.
     */
    private static Object value(String parameter, EObject o) {
        return switch (parameter) {
        case "element" -> element(o);
        case "Element" -> capitalized(element(o));
        case "name" -> "'" + name(o) + "'";
        case "period" -> duration(((RealTimeElement) o).getPeriod(), (TimeScaled) o);
        case "delay" -> duration(((RealTimeElement) o).getDelay(), (TimeScaled) o);
        case "execDuration" -> duration(((RealTimeElement) o).getExecDuration(), (TimeScaled) o);
        case "missingTiming" -> missingTiming(o);
        case "negativeTimes" -> times(o, false);
        case "nonRepresentableTimes" -> times(o, true);
        case "layerName" -> "'" + name(((Module) o).getLayer()) + "'";
        case "layerBudget" -> duration(((Module) o).getLayer().getMaxExecTime(), ((Module) o).getLayer());
        case "declaredLayers" -> ((Architecture) o).getDeclaredLayers();
        case "layerCount" -> ((Architecture) o).getLayers().size();
        case "layerNames" -> names(((Architecture) o).getLayers());
        case "layerLevels" -> ((Architecture) o).getLayers().stream().map(l -> String.valueOf(l.getLevel())).sorted()
                .collect(Collectors.joining(", "));
        case "maxLevel" -> ((Architecture) o).getLayers().size() - 1;
        case "nonRealTimeFunctions" -> quoted(((Module) o).getFunctions().stream()
                .filter(f -> f.getType() != ElementType.REAL_TIME).collect(Collectors.toList()));
        case "nonRealTimeActions" -> quoted(((org.rsaml.model.Function) o).getActions().stream()
                .filter(a -> a.getType() != ElementType.REAL_TIME).collect(Collectors.toList()));
        case "inputs" -> inputs((Module) o);
        case "neverHappens" -> neverHappens((Module) o);
        case "duplicates" -> duplicates(o);
        case "longTexts" -> longTexts(o);
        case "source" -> port(((Connection) o).getSource());
        case "target" -> o instanceof Connection c ? port(c.getTarget()) : port(target((SubsumptionLink) o));
        case "sourceType" -> RsamlLabels.dataType(((Connection) o).getSource());
        case "targetType" -> RsamlLabels.dataType(((Connection) o).getTarget());
        case "sourceLayer" -> layer(((Connection) o).getSource().getModule().getLayer());
        case "targetLayer" -> layer(o instanceof Connection c ? c.getTarget().getModule().getLayer()
                : target((SubsumptionLink) o).getModule().getLayer());
        case "skippedLayers" -> {
            Connection c = (Connection) o;
            yield Math.abs(c.getSource().getModule().getLayer().getLevel() - c.getTarget().getModule().getLayer().getLevel()) - 1;
        }
        case "portModule" -> "'" + name(((Port) o).getModule()) + "'";
        case "topicProblem" -> ((Port) o).topicProblem();
        case "packageProblem" -> o instanceof Layer l ? l.packageProblem() : ((Processor) o).packageProblem();
        case "owner" -> "'" + name(owner((SubsumptionLink) o)) + "'";
        case "ownerLayer" -> layer(owner((SubsumptionLink) o).getLayer());
        case "levelBelow" -> owner((SubsumptionLink) o).getLayer().getLevel() - 1;
        case "subsumes" -> o instanceof Inhibitor ? "inhibits output" : "suppresses entry";
        case "subsumable" -> o instanceof Inhibitor ? "inhibit outputs" : "suppress inputs";
        case "trigger" -> port(((SubsumptionLink) o).getTrigger());
        case "linkDuration" -> duration(((SubsumptionLink) o).getDuration(), (TimeScaled) o);
        case "linkKind" -> o instanceof Inhibitor ? "inhibitor" : "suppressor";
        case "asserting" -> ((SubsumptionLink) o).getTrigger().getDataType() == DataType.BOOLEAN
                ? "a boolean trigger: every true" : "a " + RsamlLabels.dataType(((SubsumptionLink) o).getTrigger()) + " trigger: every message";
        case "triggerSends" -> triggerSends((SubsumptionLink) o);
        case "lapseEffect" -> o instanceof Inhibitor
                ? "output " + port(target((SubsumptionLink) o)) + " sends nothing"
                : "entry " + port(target((SubsumptionLink) o)) + " receives nothing from its own connections";
        case "exceededBudgets" -> exceededBudgets((RealTimeElement) o);
        // results of the timing analysis, which the timing checks supply with the finding
        default -> throw new IllegalArgumentException(TimingChecks.PARAMETERS.contains(parameter)
                ? "{" + parameter + "} is supplied by the timing analysis, not by " + element(o)
                : "unknown message parameter {" + parameter + "}");
        };
    }

    /**
     * The template with its parameters filled in for {@code element}. Throws when a parameter does
     * not apply to the element (the caller reports that, naming the rule, instead of a message).
     */
    public static String render(String template, EObject element) {
        return render(template, element, Map.of());
    }

    /** Likewise, with the values of parameters a check computed ({@code supplied}) taking precedence. */
    public static String render(String template, EObject element, Map<String, ?> supplied) {
        Matcher m = PARAMETER.matcher(template);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String parameter = m.group(1);
            if (!NAMES.contains(parameter)) {
                throw new IllegalArgumentException("unknown message parameter {" + parameter + "}");
            }
            Object value = supplied.containsKey(parameter) ? supplied.get(parameter) : value(parameter, element);
            m.appendReplacement(out, Matcher.quoteReplacement(String.valueOf(value)));
        }
        m.appendTail(out);
        return out.toString();
    }

    /** A kind and a name, as messages start: {@code module 'resourceChecker'}. */
    public static String element(EObject o) {
        if (o == null) {
            return "<none>";
        }
        String kind = switch (o.eClass().getName()) {
            case "EntryPort" -> "entry port";
            case "OutputPort" -> "output port";
            case "RTAction" -> "RTAction";
            case "LatencyRequirement" -> "latency requirement";
            default -> o.eClass().getName().toLowerCase(java.util.Locale.ROOT);
        };
        return kind + " '" + name(o) + "'";
    }

    static String capitalized(String s) {
        return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }

    /** A port with its module: {@code 'resourceChecker.s0_ressourceCheck'}. */
    private static String port(Port p) {
        return "'" + (p.getModule() == null ? "" : name(p.getModule()) + ".") + name(p) + "'";
    }

    private static String layer(Layer l) {
        return "layer '" + name(l) + "' (level " + l.getLevel() + ")";
    }

    private static Module owner(SubsumptionLink link) {
        return link instanceof Inhibitor i ? i.getModule() : ((Suppressor) link).getModule();
    }

    private static Port target(SubsumptionLink link) {
        return link instanceof Inhibitor i ? i.getTarget() : ((Suppressor) link).getTarget();
    }

    /**
     * How often a link's trigger sends, for RSA-26: the shortest period of its module's timed
     * releases (each publishes all the module's outputs) that is no longer than the link's duration,
     * with the element it is the period of, as the invariant selects them.
     */
    private static String triggerSends(SubsumptionLink link) {
        Module m = link.getTrigger().getModule();
        List<RealTimeElement> released = new ArrayList<>();
        boolean anyTimed = false;
        boolean stepFunction = false;
        for (org.rsaml.model.Function f : m.getFunctions()) {
            if (timed(f)) {
                released.add(f);
                anyTimed = true;
            } else {
                stepFunction = true;
            }
            for (org.rsaml.model.Action a : f.getActions()) {
                if (timed(a)) {
                    released.add(a);
                    anyTimed = true;
                }
            }
        }
        if (timed(m) && (stepFunction || !anyTimed)) {
            released.add(0, m);
        }
        RealTimeElement shortest = null;
        for (RealTimeElement e : released) {
            if (shortest == null || RsamlTimes.compare(e.getPeriod(), e, shortest.getPeriod(), shortest) < 0) {
                shortest = e;
            }
        }
        if (shortest == null) {
            return "its module " + "'" + name(m) + "' sends on it";
        }
        String of = shortest == m ? "its own period" : "the period of " + element(shortest);
        return "module '" + name(m) + "' sends on it every " + duration(shortest.getPeriod(), shortest) + " (" + of + ")";
    }

    private static boolean timed(RealTimeElement e) {
        return e.getExecType() == org.rsaml.model.ExecutionType.PERIODIC && e.getPeriod() > 0;
    }

    /** The budgets a function or action exceeds, for RSA-27, as the invariants check them. */
    private static String exceededBudgets(RealTimeElement e) {
        org.rsaml.model.Function function = e instanceof org.rsaml.model.Action a ? a.getFunction() : null;
        Module module = e instanceof org.rsaml.model.Function f ? f.getModule() : function == null ? null : function.getModule();
        Layer layer = module == null ? null : module.getLayer();
        List<String> exceeded = new ArrayList<>();
        if (function != null && function.getExecDuration() > 0
                && RsamlTimes.compare(e.getExecDuration(), e, function.getExecDuration(), function) > 0) {
            exceeded.add("the " + duration(function.getExecDuration(), function) + " of its function '" + name(function) + "'");
        }
        if (module != null && module.getExecDuration() > 0 && RsamlTimes.compare(e.getExecDuration(), e, module.getExecDuration(), module) > 0) {
            exceeded.add("the " + duration(module.getExecDuration(), module) + " of its module '" + name(module) + "'");
        }
        if (layer != null && layer.getMaxExecTime() > 0 && RsamlTimes.compare(e.getExecDuration(), e, layer.getMaxExecTime(), layer) > 0) {
            exceeded.add("the " + duration(layer.getMaxExecTime(), layer) + " budget of its layer '" + name(layer) + "'");
        }
        return exceeded.isEmpty() ? "its budgets" : String.join(" and ", exceeded);
    }

    private static String missingTiming(EObject o) {
        RealTimeElement e = (RealTimeElement) o;
        List<String> zero = new ArrayList<>();
        if (e.getPeriod() <= 0) {
            zero.add("period");
        }
        if (e.getDelay() <= 0) {
            zero.add("delay");
        }
        return String.join(" and no ", zero);
    }

    /**
     * What a module's entry ports receive, for RSA-19: {@code has no entry port}, {@code none of its
     * entry ports receives data}, or the modules that deliver data to them (a connection or a
     * suppressor whose ports carry the same data, as the invariant counts them).
     */
    private static String inputs(Module m) {
        List<EntryPort> entries = m.getPorts().stream().filter(EntryPort.class::isInstance).map(EntryPort.class::cast).toList();
        if (entries.isEmpty()) {
            return "has no entry port";
        }
        Set<Module> feeders = new LinkedHashSet<>();
        for (EntryPort e : entries) {
            for (Connection c : e.getIncoming()) {
                if (delivers(c.getSource(), e)) {
                    feeders.add(c.getSource().getModule());
                }
            }
            for (Suppressor s : e.getSuppressedBy()) {
                if (delivers(s.getTrigger(), e)) {
                    feeders.add(s.getTrigger().getModule());
                }
            }
        }
        return feeders.isEmpty() ? "none of its entry ports receives data"
                : "its entry ports receive data only from modules that are never activated either (" + quoted(new ArrayList<>(feeders)) + ")";
    }

    private static boolean delivers(OutputPort from, EntryPort to) {
        return from != null && from.getModule() != null && from.getDataType() == to.getDataType()
                && (to.getDataType() != DataType.STRUCTURED
                        || java.util.Objects.equals(from.normalizedMessageType(), to.normalizedMessageType()));
    }

    /** What never happens in a module nothing activates: its outputs, actuators and functions, as it has them. */
    private static String neverHappens(Module m) {
        List<String> parts = new ArrayList<>();
        List<Port> outputs = m.getPorts().stream().filter(OutputPort.class::isInstance).collect(Collectors.toList());
        if (!outputs.isEmpty()) {
            parts.add("its outputs " + quoted(outputs) + " never carry more than their initial values");
        }
        if (!m.getActuators().isEmpty()) {
            parts.add("its actuators " + quoted(m.getActuators()) + " are never driven");
        }
        if (!m.getFunctions().isEmpty()) {
            parts.add("its functions " + quoted(m.getFunctions()) + " never run");
        }
        if (parts.isEmpty()) {
            return "it never runs";
        }
        String last = parts.remove(parts.size() - 1);
        return parts.isEmpty() ? last : String.join(", ", parts) + " and " + last;
    }

    private static String names(List<? extends NamedElement> elements) {
        return elements.isEmpty() ? "" : " (" + elements.stream().map(RsamlLabels::name).collect(Collectors.joining(", ")) + ")";
    }

    private static String quoted(List<? extends EObject> elements) {
        return elements.stream().map(e -> "'" + name(e) + "'").collect(Collectors.joining(", "));
    }

    /** Which kinds of children share which names (compared trimmed): {@code module named 'x'}. */
    private static String duplicates(EObject container) {
        List<String> parts = new ArrayList<>();
        for (EReference containment : container.eClass().getEAllContainments()) {
            if (!containment.isMany()) {
                continue;
            }
            Set<String> seen = new LinkedHashSet<>();
            Set<String> twice = new LinkedHashSet<>();
            for (Object child : (List<?>) container.eGet(containment)) {
                if (child instanceof NamedElement n && !seen.add(String.valueOf(RsamlText.normalized(n.getName())))) {
                    twice.add("'" + n.getName() + "'");
                }
            }
            if (!twice.isEmpty()) {
                parts.add(containment.getEReferenceType().getName().toLowerCase(java.util.Locale.ROOT) + " named "
                        + String.join(", ", twice));
            }
        }
        return parts.isEmpty() ? "child with the same name" : String.join("; ", parts);
    }

    /** The element's name and (for a port) message type longer than 100 characters: {@code name of 130 characters}. */
    private static String longTexts(EObject o) {
        List<String> parts = new ArrayList<>();
        if (o instanceof NamedElement n && n.normalizedName() != null && n.normalizedName().length() > 100) {
            parts.add("name of " + n.normalizedName().length() + " characters");
        }
        if (o instanceof Port p && p.normalizedMessageType() != null && p.normalizedMessageType().length() > 100) {
            parts.add("message type of " + p.normalizedMessageType().length() + " characters");
        }
        return String.join(" and a ", parts);
    }

    /** The element's negative (or, with {@code representable}, unrepresentable) time values: {@code period -2.0}. */
    private static String times(EObject o, boolean representable) {
        Map<String, Double> values = new LinkedHashMap<>();
        if (o instanceof RealTimeElement e) {
            values.put("period", e.getPeriod());
            values.put("delay", e.getDelay());
            values.put("execDuration", e.getExecDuration());
        } else if (o instanceof Layer l) {
            values.put("maxExecTime", l.getMaxExecTime());
        } else if (o instanceof SubsumptionLink s) {
            values.put("duration", s.getDuration());
        } else if (o instanceof Device d) {
            values.put("period", d.getPeriod());
        } else if (o instanceof Processor p) {
            values.put("linkLatency", p.getLinkLatency());
        }
        List<String> parts = new ArrayList<>();
        values.forEach((feature, value) -> {
            TimeScaled owner = (TimeScaled) o;
            boolean fits = feature.equals("period") ? RsamlTimes.representablePeriod(value, owner) : RsamlTimes.representable(value, owner);
            boolean wrong = representable ? !fits : value < 0;
            if (wrong) {
                parts.add(feature + " " + (representable ? duration(value, (TimeScaled) o) : RsamlLabels.number(value)));
            }
        });
        return String.join(", ", parts);
    }
}
