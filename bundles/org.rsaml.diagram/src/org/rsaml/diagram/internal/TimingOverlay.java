/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.BinaryOperator;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.Exclusion;
import org.rsaml.analysis.Hop;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.PathBound;
import org.rsaml.analysis.ProcessorResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TaskSource;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingModelException;
import org.rsaml.analysis.TimingText;
import org.rsaml.analysis.Verdict;
import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.model.Actuator;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.EntryPort;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Port;
import org.rsaml.model.Sensor;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlTimes;

/**
 * The timing analysis ({@link TimingAnalysis}) drawn over the architecture view: each processor's
 * utilisation and verdict in the title (and the HTML page's list), each task's worst-case response
 * time on the function, action or module it releases, the processor each module runs on, and for each
 * latency requirement its worst path: the sensor or port it starts from, the modules with what each
 * adds, the connections between them and the actuator or port it ends at.
 */
public final class TimingOverlay implements DiagramOverlay {

    static final String SECTION = "Timing";

    private final Map<String, List<Line>> lines = new LinkedHashMap<>();
    private final Map<String, Set<String>> classes = new LinkedHashMap<>();
    private final Map<String, Map<String, String>> data = new LinkedHashMap<>();
    private final List<Item> items = new ArrayList<>();

    @Override
    public Notes notes(Architecture architecture) {
        lines.clear();
        classes.clear();
        data.clear();
        items.clear();
        String root = RsamlLabels.qualifiedName(architecture);
        ArchitectureTiming timing;
        try {
            timing = TimingAnalysis.analyse(architecture);
        } catch (TimingModelException e) {
            return notAnalysed(root, RsamlLabels.describe(e.element()) + ": " + e.getMessage());
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            // The plan's own exception (a time generated code cannot count): its message names the element.
            return notAnalysed(root, e.getMessage());
        }
        boolean deployed = !architecture.getProcessors().isEmpty();
        for (ProcessorTiming p : timing.processors()) {
            processor(root, p, deployed);
        }
        for (Exclusion x : timing.excluded()) {
            Line line = new Line("excluded " + x.label() + " (processor " + x.processor() + "): not analysed", style(Verdict.NOT_ANALYSED));
            add(root, line);
            items.add(new Item(SECTION, line, List.of(x.reason()), List.of(RsamlLabels.qualifiedName(x.element()))));
        }
        for (LatencyResult l : timing.latencies()) {
            latency(root, architecture, l);
        }
        return new Notes(lines, classes, data, items);
    }

    private Notes notAnalysed(String root, String why) {
        Line line = new Line("timing not analysed: " + why, style(Verdict.NOT_ANALYSED));
        add(root, line);
        items.add(new Item(SECTION, line, List.of(), List.of()));
        return new Notes(lines, classes, data, items);
    }

    private void processor(String root, ProcessorTiming p, boolean deployed) {
        ProcessorResult r = p.result();
        Line line = new Line("processor " + p.name() + " (" + r.policy().label() + "): utilisation " + r.utilisationText() + ", "
                + r.tasks().size() + (r.tasks().size() == 1 ? " task" : " tasks") + ": " + TimingText.word(r.verdict()), style(r.verdict()));
        add(root, line);
        Set<String> on = new LinkedHashSet<>();
        if (p.element() != null) {
            for (Module m : p.element().getModules()) {
                on.add(RsamlLabels.qualifiedName(m));
            }
        }
        for (int i = 0; i < p.sources().size(); i++) {
            TaskSource s = p.sources().get(i);
            TaskResult t = r.tasks().get(i);
            String response = t.responseTime().isPresent() ? RsamlTimes.text(t.responseTime().getAsLong()) : "unbounded";
            add(RsamlLabels.qualifiedName(s.element()), new Line((s.kind().equals("reaction") ? "reaction " : "") + "WCRT " + response
                    + " of deadline " + RsamlTimes.text(t.task().deadline()) + ": " + TimingText.word(t.verdict()), style(t.verdict())));
            Module module = module(s.element());
            if (module != null) {
                on.add(RsamlLabels.qualifiedName(module));
            }
        }
        if (deployed) {
            for (String module : on) {
                add(module, Line.plain("on processor " + p.name()));
            }
        }
        List<String> details = new ArrayList<>();
        details.add(r.explanation());
        details.addAll(p.notes());
        items.add(new Item(SECTION, line, details, List.copyOf(on)));
    }

    private void latency(String root, Architecture architecture, LatencyResult l) {
        String what = l.dataAge() ? "data age" : "reaction time";
        String worst = l.boundNs() < 0 ? "no bound" : "worst " + RsamlTimes.text(l.boundNs());
        Line line = new Line("latency " + l.name() + " (" + what + " at most " + RsamlTimes.text(l.maxNs()) + "): " + worst + ": "
                + TimingText.word(l.verdict()), style(l.verdict()));
        add(root, line);
        List<String> details = new ArrayList<>();
        details.add(l.explanation());
        List<String> path = new ArrayList<>();
        LatencyRequirement requirement = l.requirement();
        List<Module> hops = new ArrayList<>();
        for (Hop hop : l.worstPath()) {
            // The analysis' own module, not one found by name: names need not tell modules apart.
            Module m = hop.module();
            hops.add(m);
            details.add((hops.size()) + ". " + hop.label() + ": " + hop.contribution());
        }
        if (!hops.isEmpty() && !hops.contains(null)) {
            Set<String> on = new LinkedHashSet<>();
            // References drawn without an element of their own (a sensor's line to its module): styled, not listed.
            Set<String> references = new LinkedHashSet<>();
            EObject source = requirement.getSource();
            EObject target = requirement.getTarget();
            if (source instanceof Sensor s) {
                on.add(RsamlLabels.qualifiedName(s));
                references.add(RsamlLabels.qualifiedName(s) + " -> " + RsamlLabels.qualifiedName(hops.get(0)));
            } else if (source instanceof OutputPort p) {
                on.add(RsamlLabels.qualifiedName(p));
                connections(architecture, p, null, hops.get(0), on);
            }
            for (int i = 0; i < hops.size(); i++) {
                Module m = hops.get(i);
                Hop hop = l.worstPath().get(i);
                on.add(RsamlLabels.qualifiedName(m));
                add(RsamlLabels.qualifiedName(m), new Line(l.name() + " hop " + (i + 1) + ": " + hop.contribution(), style(l.verdict())));
                if (i + 1 < hops.size()) {
                    connections(architecture, null, m, hops.get(i + 1), on);
                }
            }
            Module last = hops.get(hops.size() - 1);
            if (target instanceof Actuator a) {
                references.add(RsamlLabels.qualifiedName(last) + " -> " + RsamlLabels.qualifiedName(a));
                on.add(RsamlLabels.qualifiedName(a));
            } else if (target instanceof EntryPort e) {
                for (Connection c : architecture.getConnections()) {
                    if (c.getTarget() == e && c.getSource() != null && c.getSource().eContainer() == last) {
                        on.add(RsamlLabels.qualifiedName(c));
                    }
                }
                on.add(RsamlLabels.qualifiedName(e));
            }
            path.addAll(on);
            on.addAll(references);
            for (String element : on) {
                Set<String> css = classes.computeIfAbsent(element, k -> new LinkedHashSet<>());
                css.add("latency-path");
                if (l.verdict() == Verdict.MISSES) {
                    css.add("latency-misses");
                }
                data.computeIfAbsent(element, k -> new TreeMap<>()).merge("latency", l.name(), (a, b) -> a + ", " + b);
            }
        } else if (hops.contains(null)) {
            details.add("(the path's modules are not all known to the analysis, so the path is not drawn)");
        }
        if (!l.via().isEmpty()) {
            details.add("the paths through " + String.join(", then ", l.via()));
        }
        if (l.pathBounds().size() > 1 || !l.unlisted().isEmpty()) {
            details.add(l.pathsHeading(LatencyResult.SHOWN_PATHS));
            for (PathBound b : l.pathBounds().subList(0, Math.min(LatencyResult.SHOWN_PATHS, l.pathBounds().size()))) {
                details.add("- " + b.text() + ": " + (b.bounded() ? "reaction time " + RsamlTimes.text(b.reactionNs()) + ", data age "
                        + RsamlTimes.text(b.dataAgeNs()) : "no bound (" + b.unbounded() + ")"));
            }
            edgeWorst(architecture, l);
        }
        items.add(new Item(SECTION, line, details, path));
    }

    /**
     * Per module, connection, inhibitor and suppressor on any listed path of the requirement, the worst bound of the
     * listed paths through it (data attribute {@code latency-worst}, {@code name: 1.2 s}): a connection by the ports
     * the path passes, so that of two between the same modules only the one taken carries it; a module off the worst
     * path also gets it as a line, so that the diagram shows what each branch takes, not only the worst one.
     */
    private void edgeWorst(Architecture architecture, LatencyResult l) {
        Map<String, Long> worst = new LinkedHashMap<>();
        Map<List<Port>, Connection> byPorts = new HashMap<>();
        for (Connection c : architecture.getConnections()) {
            if (c.getSource() != null && c.getTarget() != null) {
                byPorts.putIfAbsent(List.of(c.getSource(), c.getTarget()), c);
            }
        }
        Set<Module> onWorst = new LinkedHashSet<>();
        l.worstPath().forEach(h -> onWorst.add(h.module()));
        Set<String> offWorst = new LinkedHashSet<>();
        for (PathBound b : l.pathBounds()) {
            long bound = b.bounded() ? (l.dataAge() ? b.dataAgeNs() : b.reactionNs()) : -1;
            for (Hop h : b.hops()) {
                Module m = h.module();
                if (m == null) {
                    continue;
                }
                worst.merge(RsamlLabels.qualifiedName(m), bound, WORSE);
                if (!onWorst.contains(m)) {
                    offWorst.add(RsamlLabels.qualifiedName(m));
                }
            }
            EObject before = null;
            for (EObject e : b.passes()) {
                if (e instanceof SubsumptionLink link) {
                    worst.merge(RsamlLabels.qualifiedName(link), bound, WORSE);
                } else if (before instanceof Port s && e instanceof Port t) {
                    Connection c = byPorts.get(List.of(s, t));
                    if (c != null) {
                        worst.merge(RsamlLabels.qualifiedName(c), bound, WORSE);
                    }
                }
                before = e;
            }
        }
        String paths = l.unlisted().isEmpty() ? "the paths" : "the listed paths";
        worst.forEach((element, ns) -> {
            String text = ns < 0 ? "no bound" : RsamlTimes.text(ns);
            data.computeIfAbsent(element, k -> new TreeMap<>()).merge("latency-worst", l.name() + ": " + text, (a, b) -> a + ", " + b);
            if (offWorst.contains(element)) {
                add(element, Line.plain(l.name() + ": " + paths + " through here take at most " + text));
            }
        });
    }

    /** The larger of two bounds, no bound (-1) the largest. */
    private static final BinaryOperator<Long> WORSE = (a, b) -> a < 0 || b < 0 ? -1L : Math.max(a, b);

    /** The connections from {@code port} (or any output port of {@code from}) to an entry port of {@code to}. */
    private static void connections(Architecture architecture, Port port, Module from, Module to, Set<String> on) {
        for (Connection c : architecture.getConnections()) {
            Port s = c.getSource();
            Port t = c.getTarget();
            if (s == null || t == null || t.eContainer() != to) {
                continue;
            }
            if (port != null ? s == port : s.eContainer() == from) {
                on.add(RsamlLabels.qualifiedName(c));
            }
        }
    }

    private static Module module(EObject element) {
        for (EObject e = element; e != null; e = e.eContainer()) {
            if (e instanceof Module m) {
                return m;
            }
        }
        return null;
    }

    private void add(String element, Line line) {
        lines.computeIfAbsent(element, k -> new ArrayList<>()).add(line);
    }

    static String style(Verdict verdict) {
        return switch (verdict) {
            case MEETS -> "overlay-meets";
            case MISSES -> "overlay-misses";
            case NOT_ANALYSED -> "overlay-unknown";
        };
    }
}
