/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.Action;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.ElementType;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.NamedElement;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.TimeScaled;

/**
 * How RsaML names and describes elements to people: in editor labels, validation messages and
 * generated code comments, so that all of them speak alike.
 */
public final class RsamlLabels {

    private RsamlLabels() {
    }

    /** A time value with its unit, as the architect wrote it: {@code 2.5 ms}. */
    public static String duration(double value, TimeScaled unitOwner) {
        return number(value) + " " + RsamlTimes.unit(unitOwner).getLiteral();
    }

    /** A number without a spurious exponent: {@code 2.0}, {@code 0.001}, {@code 1500.0}. */
    public static String number(double value) {
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return (long) value + ".0";
        }
        return java.math.BigDecimal.valueOf(value).stripTrailingZeros().toPlainString();
    }

    /** The element's name, or a placeholder that says it has none. */
    public static String name(EObject element) {
        if (element instanceof NamedElement named && named.getName() != null && !named.getName().isEmpty()) {
            return named.getName();
        }
        if (element instanceof Connection connection) {
            return name(connection.getSource()) + " -> " + name(connection.getTarget());
        }
        return element == null ? "<none>" : "<unnamed " + element.eClass().getName() + ">";
    }

    /**
     * The machine a processor is on: its host, stripped of surrounding white space, or "" for the architecture's main
     * host (a processor without a host, and the default processor). Two processors with the same host share a
     * machine; the analysis, the generated launch files and the diagrams' labels all ask here.
     */
    public static String host(Processor processor) {
        return processor == null || processor.getHost() == null || processor.getHost().isBlank() ? "" : processor.getHost().strip();
    }

    /**
     * The name of the main host (the processors without a host, and the default processor) wherever a host is named: a
     * ROS 2 launch's {@code host:=} value that starts them, and the messages and notes that name hosts.
     */
    public static final String MAIN_HOST = "main";

    /** The name of the machine a processor is on: its {@link #host}, or {@link #MAIN_HOST} for the main host. */
    public static String hostName(Processor processor) {
        String host = host(processor);
        return host.isEmpty() ? MAIN_HOST : host;
    }

    /**
     * The element's path from the architecture down, by names:
     * {@code architecture/decisionLayer/proceduralExec/e0}.
     */
    public static String qualifiedName(EObject element) {
        List<String> segments = new ArrayList<>();
        for (EObject e = element; e != null; e = e.eContainer()) {
            segments.add(0, name(e));
        }
        return String.join("/", segments);
    }

    /** What the element's timing is, in a few words, for prose and generated comments: {@code real-time, 1.0 ms every 20.0 ms}. */
    public static String timing(RealTimeElement element) {
        List<String> parts = new ArrayList<>();
        parts.add(element.getType() == ElementType.REAL_TIME ? "real-time" : "simple");
        if (element instanceof Function function && function.getSchedPolicy() != null) {
            parts.add(function.getSchedPolicy() == SchedulingPolicy.OTHER && function.getOtherPolicy() != null
                    ? function.getOtherPolicy() : function.getSchedPolicy().getLiteral());
        }
        String work = element.getExecDuration() > 0 ? duration(element.getExecDuration(), element) : null;
        if (element.getExecType() == ExecutionType.PERIODIC && element.getPeriod() > 0) {
            parts.add((work == null ? "" : work + " ") + "every " + duration(element.getPeriod(), element));
        } else if (element.getExecType() == ExecutionType.SPORADIC) {
            parts.add("sporadic" + (work == null ? "" : ", " + work));
        } else if (work != null) {
            parts.add(work);
        }
        return String.join(", ", parts);
    }

    /**
     * The element's timing facts for diagram labels, each with its unit:
     * {@code real-time \u00b7 periodic \u00b7 T 20.0 ms \u00b7 D 20.0 ms \u00b7 C 4.0 ms}, or {@code no timing}.
     */
    public static String timingFacts(RealTimeElement e) {
        List<String> parts = new ArrayList<>();
        if (e.getType() == ElementType.REAL_TIME) {
            parts.add("real-time");
        }
        if (e.getExecType() != null && e.getExecType() != ExecutionType.APERIODIC) {
            parts.add(e.getExecType().getLiteral());
        }
        if (e.getPeriod() > 0) {
            parts.add("T " + duration(e.getPeriod(), e));
        }
        if (e.getDelay() > 0) {
            parts.add("D " + duration(e.getDelay(), e));
        }
        if (e.getExecDuration() > 0) {
            parts.add("C " + duration(e.getExecDuration(), e));
        }
        if (e instanceof Action action && action.getStartDate() > 0) {
            parts.add("at " + duration(action.getStartDate(), e));
        }
        if (e instanceof Function f && f.getSchedPolicy() != null
                && (e.getType() == ElementType.REAL_TIME || f.getExecType() == ExecutionType.PERIODIC)) {
            parts.add(f.getSchedPolicy().getLiteral());
        }
        return parts.isEmpty() ? "no timing" : String.join(" \u00b7 ", parts);
    }

    /** A one-line description of the element for tree labels: {@code resourceChecker — real-time, 2.5 ms}. */
    public static String describe(EObject element) {
        String name = name(element);
        if (element instanceof RealTimeElement timed) {
            return name + " \u2014 " + timing(timed);
        }
        if (element instanceof Layer layer) {
            return name + " \u2014 level " + layer.getLevel()
                    + (layer.getMaxExecTime() > 0 ? ", at most " + duration(layer.getMaxExecTime(), layer) + " a module" : "");
        }
        if (element instanceof Port port) {
            return name + " \u2014 " + dataType(port);
        }
        return name;
    }

    /** The data type of a port, naming the message type of structured data. */
    public static String dataType(Port port) {
        if (port.getDataType() == DataType.STRUCTURED && port.getMessageType() != null && !port.getMessageType().isEmpty()) {
            return port.getMessageType();
        }
        return port.getDataType().getLiteral();
    }
}
