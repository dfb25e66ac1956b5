/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import static org.rsaml.model.support.RsamlLabels.duration;
import static org.rsaml.model.support.RsamlLabels.name;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.ElementType;
import org.rsaml.model.Function;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.NamedElement;
import org.rsaml.model.Port;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Suppressor;
import org.rsaml.model.support.RsamlLabels;

/** The messages of RsaML's rules: what is wrong, with the elements and values involved. */
final class RuleMessages {

    private RuleMessages() {
    }

    /** A kind and a name, as messages start: {@code Module 'resourceChecker'}. */
    static String element(EObject o) {
        if (o == null) {
            return "<none>";
        }
        String kind = switch (o.eClass().getName()) {
            case "EntryPort" -> "entry port";
            case "OutputPort" -> "output port";
            case "RTAction" -> "RTAction";
            default -> o.eClass().getName().toLowerCase(java.util.Locale.ROOT);
        };
        return kind + " '" + name(o) + "'";
    }

    static String capitalized(String s) {
        return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }

    /** A port with its module: {@code 'resourceChecker.s0_ressourceCheck'}. */
    static String port(Port p) {
        return "'" + (p.getModule() == null ? "" : name(p.getModule()) + ".") + name(p) + "'";
    }

    static String layer(Layer l) {
        return "layer '" + name(l) + "' (level " + l.getLevel() + ")";
    }

    static String message(String constraint, EObject o) {
        String rule = constraint.substring(0, 5);
        switch (rule) {
            case "RSA01": {
                Architecture a = (Architecture) o;
                return capitalized(element(a)) + " declares " + a.getDeclaredLayers() + " layers but contains "
                        + a.getLayers().size() + names(a.getLayers()) + "; set declaredLayers to "
                        + a.getLayers().size() + " or add the missing layers";
            }
            case "RSA02": {
                Connection c = (Connection) o;
                return "Connection from output port " + port(c.getSource()) + " (" + RsamlLabels.dataType(c.getSource())
                        + ") to entry port " + port(c.getTarget()) + " (" + RsamlLabels.dataType(c.getTarget())
                        + ") joins different data types";
            }
            case "RSA03": {
                Connection c = (Connection) o;
                Layer from = c.getSource().getModule().getLayer();
                Layer to = c.getTarget().getModule().getLayer();
                return "Connection from " + port(c.getSource()) + " in " + layer(from) + " to " + port(c.getTarget())
                        + " in " + layer(to) + " skips " + (Math.abs(from.getLevel() - to.getLevel()) - 1)
                        + " layer(s); modules may only talk within their layer or to the layer directly above or below";
            }
            case "RSA04": {
                SubsumptionLink link = (SubsumptionLink) o;
                Module own = owner(link);
                Port target = link instanceof Inhibitor i ? i.getTarget() : ((Suppressor) link).getTarget();
                String verb = link instanceof Inhibitor ? "inhibits output " : "suppresses entry ";
                return capitalized(element(link)) + " of module '" + name(own) + "' in " + layer(own.getLayer()) + " "
                        + verb + port(target) + " in " + layer(target.getModule().getLayer())
                        + "; a module may only " + (link instanceof Inhibitor ? "inhibit outputs" : "suppress inputs")
                        + " of the layer immediately below (level " + (own.getLayer().getLevel() - 1) + ")";
            }
            case "RSA05": {
                Module m = (Module) o;
                List<String> zero = new ArrayList<>();
                if (m.getPeriod() <= 0) {
                    zero.add("period");
                }
                if (m.getDelay() <= 0) {
                    zero.add("delay");
                }
                return "Real-time module '" + name(m) + "' has no " + String.join(" and no ", zero)
                        + "; a real-time module needs a non-zero period and delay";
            }
            case "RSA06": {
                Module m = (Module) o;
                return "Real-time module '" + name(m) + "' has non-real-time function(s) " + quoted(
                        m.getFunctions().stream().filter(f -> f.getType() != ElementType.REAL_TIME).collect(Collectors.toList()));
            }
            case "RSA07": {
                Function f = (Function) o;
                return "Real-time function '" + name(f) + "' contains non-real-time action(s) " + quoted(
                        f.getActions().stream().filter(a -> a.getType() != ElementType.REAL_TIME).collect(Collectors.toList()));
            }
            case "RSA08": {
                Module m = (Module) o;
                return "Module '" + name(m) + "' takes " + duration(m.getExecDuration(), m) + " but layer '"
                        + name(m.getLayer()) + "' allows at most " + duration(m.getLayer().getMaxExecTime(), m.getLayer());
            }
            case "RSA09":
                return capitalized(element(o)) + " has more than one " + duplicates(o);
            case "RSA10": {
                RealTimeElement e = (RealTimeElement) o;
                return capitalized(element(e)) + " takes " + duration(e.getExecDuration(), e) + " but runs every "
                        + duration(e.getPeriod(), e) + "; its execution duration must not exceed its period";
            }
            case "RSA11": {
                RealTimeElement e = (RealTimeElement) o;
                return capitalized(element(e)) + " has a delay of " + duration(e.getDelay(), e)
                        + ", longer than its period of " + duration(e.getPeriod(), e) + ", so its activations can overlap";
            }
            case "RSA12":
                return "Periodic " + element(o) + " has no period";
            case "RSA13":
                return capitalized(element(o)) + " has a negative time value: " + negatives(o);
            case "RSA14": {
                Architecture a = (Architecture) o;
                return capitalized(element(a)) + " has layer levels " + a.getLayers().stream()
                        .map(l -> String.valueOf(l.getLevel())).sorted().collect(Collectors.joining(", "))
                        + "; levels must run from 0 to " + (a.getLayers().size() - 1) + " without gaps or duplicates";
            }
            case "RSA15":
                return "RTAction '" + name(o) + "' is declared simple; an RTAction is real-time";
            case "RSA16": {
                SubsumptionLink link = (SubsumptionLink) o;
                Module own = owner(link);
                return capitalized(element(link)) + " is triggered by " + port(link.getTrigger())
                        + ", which is not an output port of its own module '" + name(own) + "'";
            }
            case "RSA17": {
                RealTimeElement e = (RealTimeElement) o;
                return capitalized(element(e)) + " takes " + duration(e.getExecDuration(), e)
                        + " but must respond within " + duration(e.getDelay(), e) + " (its delay)";
            }
            case "RSA18":
                return "Structured " + element(o) + " names no message type";
            default:
                return "The '" + constraint + "' constraint is violated on " + element(o);
        }
    }

    /** The module that owns an inhibitor or a suppressor. */
    private static Module owner(SubsumptionLink link) {
        return link instanceof Inhibitor i ? i.getModule() : ((Suppressor) link).getModule();
    }

    private static String names(List<? extends NamedElement> elements) {
        return elements.isEmpty() ? "" : " (" + elements.stream().map(RsamlLabels::name).collect(Collectors.joining(", ")) + ")";
    }

    private static String quoted(List<? extends EObject> elements) {
        return elements.stream().map(e -> "'" + name(e) + "'").collect(Collectors.joining(", "));
    }

    /** Which kinds of children share which names: {@code module named 'x'}. */
    private static String duplicates(EObject container) {
        List<String> parts = new ArrayList<>();
        for (EReference containment : container.eClass().getEAllContainments()) {
            if (!containment.isMany()) {
                continue;
            }
            Set<String> seen = new LinkedHashSet<>();
            Set<String> twice = new LinkedHashSet<>();
            for (Object child : (List<?>) container.eGet(containment)) {
                if (child instanceof NamedElement n && !seen.add(String.valueOf(n.getName()))) {
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

    private static String negatives(EObject o) {
        List<String> parts = new ArrayList<>();
        if (o instanceof RealTimeElement e) {
            addIfNegative(parts, "period", e.getPeriod());
            addIfNegative(parts, "delay", e.getDelay());
            addIfNegative(parts, "execDuration", e.getExecDuration());
        } else if (o instanceof Layer l) {
            addIfNegative(parts, "maxExecTime", l.getMaxExecTime());
        } else if (o instanceof SubsumptionLink s) {
            addIfNegative(parts, "duration", s.getDuration());
        }
        return String.join(", ", parts);
    }

    private static void addIfNegative(List<String> parts, String feature, double value) {
        if (value < 0) {
            parts.add(feature + " " + RsamlLabels.number(value));
        }
    }
}
