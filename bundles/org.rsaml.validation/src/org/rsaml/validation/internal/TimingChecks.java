/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.DiagnosticChain;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EObjectValidator;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TaskSource;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingModelException;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.plan.UnplannableException;
import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Function;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.Module;
import org.rsaml.model.Processor;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;

/**
 * The timing rules, which OCL cannot express: the verdicts of {@link TimingAnalysis} on the
 * architecture of an element, computed once per validation (cached in the validation context) and
 * reported on the element they concern. Each kind of verdict has a name here ({@link #VERDICTS}); the
 * catalogue's {@code verdicts} key binds it to the rule it is reported as, whose texts are in the
 * catalogue like every other rule's.
 */
public final class TimingChecks {

    /** A task can miss its deadline. */
    public static final String DEADLINE = "task-misses-deadline";
    /** A latency requirement can be exceeded. */
    public static final String LATENCY = "latency-exceeded";
    /** A task the analysis reaches no verdict on. */
    public static final String TASK_NOT_ANALYSED = "task-not-analysed";
    /** A latency requirement the analysis reaches no verdict on. */
    public static final String LATENCY_NOT_ANALYSED = "latency-not-analysed";
    /** The analysis could not be run on the architecture (an error, never a silent pass). */
    public static final String ANALYSIS_FAILED = "analysis-failed";
    /** The deployment allocates a module to more than one processor. */
    public static final String DEPLOYMENT = "inconsistent-deployment";

    /** Every verdict these checks report; the catalogue binds each to exactly one rule. */
    public static final List<String> VERDICTS = List.of(DEADLINE, ANALYSIS_FAILED, LATENCY, TASK_NOT_ANALYSED, LATENCY_NOT_ANALYSED,
            DEPLOYMENT);

    /** The message parameters these checks supply from the analysis' results. */
    public static final List<String> PARAMETERS = List.of("processor", "task", "reason", "worstPath", "where", "witness");

    /**
     * Rules whose errors leave the architecture without a task set (times missing, negative, beyond
     * the clock, longer than their period, references broken): while one is violated, those rules
     * report the problem and the timing is not analysed, instead of reporting its consequences. The
     * catalogue marks them ({@code timingPrerequisite}). A holder: the catalogue's parser reads this
     * class's {@link #PARAMETERS} while {@link Rules} is still being initialised.
     */
    private static final class Prerequisites {
        static final Set<String> IDS = Rules.timingPrerequisites().stream().map(Rule::id).collect(Collectors.toUnmodifiableSet());
    }

    /**
     * One timing finding: the rule, the element it is on, the supplied message parameters; or, with
     * a {@code failure}, the analysis could not be run (an error, never a silent pass).
     */
    public record Found(Rule rule, EObject element, Map<String, String> parameters, String failure, String detail) {
        Found(Rule rule, EObject element, Map<String, String> parameters) {
            this(rule, element, parameters, null, null);
        }

        Found(Rule rule, EObject element, Map<String, String> parameters, String failure) {
            this(rule, element, parameters, failure, null);
        }
    }

    /** Hops of a worst path a message shows at each end; longer paths are shortened in the middle. */
    static final int SHOWN_HOPS = 4;

    /**
     * EMF's structural checks alone (RSA-00). Invariants are skipped: inside OSGi EMF would evaluate
     * them through the registered OCL delegate, outside it not, and the verdict must not depend on that.
     * Duplicate names (RSA-09) do not stop the analysis.
     */
    private static final EObjectValidator STRUCTURE = new EObjectValidator() {
        @Override
        public boolean validate(EClass eClass, EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context,
                String validationDelegate, String constraint, String expression, int severity, String source, int code) {
            return true;
        }

        @Override
        public boolean validate_EveryKeyUnique(EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
            return true;
        }
    };

    private static final Object CONTEXT_KEY = TimingChecks.class;

    private TimingChecks() {
    }

    /**
     * One line per broken binding between these checks' verdicts and the catalogue's timing rules: a
     * verdict no rule reports, a timing rule that names no verdict or a verdict these checks do not have.
     */
    public static List<String> bindingProblems(List<Rule> rules) {
        List<String> problems = new ArrayList<>();
        for (String verdict : VERDICTS) {
            if (rules.stream().noneMatch(r -> r.verdicts().contains(verdict))) {
                problems.add("the timing analysis' verdict " + verdict + " is reported as no rule: name it under the verdicts"
                        + " key of a rule of source '" + Rule.TIMING_ANALYSIS + "' in " + RuleCatalog.SOURCE_FILE);
            }
        }
        for (Rule rule : rules) {
            if (rule.isTiming() && rule.verdicts().isEmpty()) {
                problems.add(rule.id() + " is a rule of the timing analysis but names no verdict under " + rule.id()
                        + ".verdicts in " + RuleCatalog.SOURCE_FILE + "; known: " + String.join(", ", VERDICTS));
            }
            for (String verdict : rule.verdicts()) {
                if (!VERDICTS.contains(verdict)) {
                    problems.add(rule.id() + " names the verdict " + verdict + ", which the timing analysis does not report; known: "
                            + String.join(", ", VERDICTS));
                }
            }
        }
        return problems;
    }

    /** Whether the timing rules may report on this element. */
    public static boolean concerns(EObject element) {
        return element instanceof Module || element instanceof Function || element instanceof Action
                || element instanceof LatencyRequirement || element instanceof Processor || element instanceof Architecture;
    }

    /**
     * Makes a validation whose walk covers a whole architecture report the timing rules after the walk instead of
     * when it reaches the root: the walk itself then tells whether the prerequisites hold (every element is judged by
     * EMF's structural checks and every invariant anyway), so they are not checked in a pass of their own. The caller
     * adds {@link #afterWalk} once the walk is over.
     */
    public static void deferToAfterWalk(Map<Object, Object> context) {
        ValidationFacts.of(context).deferTiming();
    }

    /**
     * The timing findings of a deferred validation of {@code architecture} ({@link #deferToAfterWalk}), in document
     * order, as the walk would have reported them: none when an element broke a prerequisite.
     */
    public static List<Diagnostic> afterWalk(Architecture architecture, Map<Object, Object> context) {
        if (ValidationFacts.of(context).isTaskSetBroken()) {
            return List.of();
        }
        Map<EObject, List<Found>> byElement;
        try {
            byElement = analysed(architecture);
        } catch (RuntimeException e) {
            byElement = failed(architecture, e);
        }
        List<Diagnostic> out = new ArrayList<>();
        if (byElement.isEmpty()) {
            return out; // every verdict met: no walk to put findings in document order
        }
        for (Iterator<EObject> it = architecture.eAllContents(); ; ) {
            EObject o = it.hasNext() ? it.next() : null;
            EObject element = o == null ? architecture : o;
            if (concerns(element)) {
                byElement.getOrDefault(element, List.of()).forEach(f -> out.add(diagnostic(f)));
            }
            if (o == null) {
                return out;
            }
        }
    }

    /** The timing findings on {@code element} itself (none when it is in no architecture). */
    public static List<Found> on(EObject element, Map<Object, Object> context, OclRules rules) {
        Architecture architecture = architectureOf(element);
        if (architecture == null) {
            return List.of();
        }
        Map<EObject, List<Found>> byElement;
        if (context == null) {
            byElement = findings(architecture, rules, null);
        } else {
            @SuppressWarnings("unchecked")
            Map<Architecture, Map<EObject, List<Found>>> cache = (Map<Architecture, Map<EObject, List<Found>>>) context
                    .computeIfAbsent(CONTEXT_KEY, k -> new IdentityHashMap<>());
            ValidationFacts facts = ValidationFacts.of(context);
            byElement = cache.computeIfAbsent(architecture, a -> findings(a, rules, facts));
        }
        return byElement.getOrDefault(element, List.of());
    }

    private static Architecture architectureOf(EObject element) {
        for (EObject e = element; e != null; e = e.eContainer()) {
            if (e instanceof Architecture a) {
                return a;
            }
        }
        return null;
    }

    /** Every timing finding of the architecture, by the element it is on. */
    static Map<EObject, List<Found>> findings(Architecture architecture, OclRules rules, ValidationFacts facts) {
        try {
            return prerequisitesHold(architecture, rules, facts) ? analysed(architecture) : new IdentityHashMap<>();
        } catch (RuntimeException e) {
            return failed(architecture, e);
        }
    }

    private static Map<EObject, List<Found>> failed(Architecture architecture, RuntimeException e) {
        Map<EObject, List<Found>> out = new IdentityHashMap<>();
        add(out, new Found(rule(ANALYSIS_FAILED), architecture, Map.of(), "the timing rules could not be evaluated on "
                + MessageParameters.element(architecture) + ": " + e));
        return out;
    }

    /** The findings of the analysis of an architecture whose prerequisites hold. */
    private static Map<EObject, List<Found>> analysed(Architecture architecture) {
        Map<EObject, List<Found>> out = new IdentityHashMap<>();
        ArchitectureTiming timing;
        try {
            timing = TimingAnalysis.verdicts(architecture);
        } catch (UnplannableException e) {
            return out; // RSA-13 or RSA-20 reports the time; prerequisitesHold normally catches it first
        } catch (TimingModelException e) {
            EObject on = e.element() == null ? architecture : e.element();
            add(out, new Found(rule(DEPLOYMENT), on, Map.of("reason", e.getMessage())));
            return out;
        }
        return verdicts(timing);
    }

    /** The findings of an analysis's verdicts short of "meets", by the element each is on. */
    private static Map<EObject, List<Found>> verdicts(ArchitectureTiming timing) {
        Map<EObject, List<Found>> out = new IdentityHashMap<>();
        for (ProcessorTiming p : timing.processors()) {
            for (int i = 0; i < p.result().tasks().size() && i < p.sources().size(); i++) {
                TaskResult t = p.result().tasks().get(i);
                TaskSource s = p.sources().get(i);
                if (t.verdict() == Verdict.MEETS || s.element() == null) {
                    continue;
                }
                Map<String, String> parameters = new LinkedHashMap<>();
                parameters.put("processor", "'" + p.name() + "'");
                parameters.put("task", t.task().name());
                parameters.put("where", " (" + t.task().name() + " on processor '" + p.name() + "')");
                parameters.put("reason", reason(t.explanation()) + (s.note().isEmpty() ? "" : " (" + s.note() + ")"));
                parameters.put("witness", t.witness() != null ? "; rsaml analyze shows the critical-instant schedule"
                        : p.result().demand() != null ? "; rsaml analyze shows the interval whose jobs need more than its length" : "");
                add(out, new Found(rule(t.verdict() == Verdict.MISSES ? DEADLINE : TASK_NOT_ANALYSED), s.element(), parameters));
            }
        }
        for (LatencyResult l : timing.latencies()) {
            if (l.verdict() == Verdict.MEETS || l.requirement() == null) {
                continue;
            }
            Map<String, String> parameters = new LinkedHashMap<>();
            parameters.put("where", "");
            parameters.put("reason", reason(l.explanation()));
            List<String> hops = l.worstPathHops();
            String whole = String.join(" -> ", hops);
            // A path of a thousand hops would make a line of kilobytes: the message names its ends, the
            // finding's detail (JSON, SARIF) keeps all of it.
            String shown = hops.size() <= 2 * SHOWN_HOPS + 1 ? whole
                    : String.join(" -> ", hops.subList(0, SHOWN_HOPS)) + " -> ... " + (hops.size() - 2 * SHOWN_HOPS)
                            + " more hops ... -> " + String.join(" -> ", hops.subList(hops.size() - SHOWN_HOPS, hops.size()))
                            + " (" + hops.size() + " hops; rsaml analyze and the JSON and SARIF reports list them all)";
            parameters.put("worstPath", hops.isEmpty() ? "" : "; worst path: " + shown);
            add(out, new Found(rule(l.verdict() == Verdict.MISSES ? LATENCY : LATENCY_NOT_ANALYSED), l.requirement(), parameters, null,
                    shown.equals(whole) ? null : "worst path: " + whole));
        }
        return out;
    }

    /** The finding as EMF diagnostic, worded as {@link RuleEValidator} words the OCL rules' findings. */
    public static Diagnostic diagnostic(Found f) {
        EObject on = f.element();
        if (f.failure() != null) {
            String message = MessageParameters.capitalized(f.failure());
            return new BasicDiagnostic(Diagnostic.ERROR, RuleEValidator.SOURCE, 0, f.rule().text(message), new Object[] { on, f.rule(), message });
        }
        String message;
        try {
            message = MessageParameters.render(f.rule().message(), on, f.parameters());
        } catch (RuntimeException e) {
            message = MessageParameters.capitalized(MessageParameters.element(on)) + " violates " + f.rule().id() + " ("
                    + f.rule().description() + "); its message could not be written: " + e;
        }
        return new BasicDiagnostic(f.rule().severity().diagnosticSeverity(), RuleEValidator.SOURCE, 0,
                f.rule().text(message), f.detail() == null ? new Object[] { on, f.rule(), message }
                        : new Object[] { on, f.rule(), message, f.detail() });
    }

    /**
     * The timing findings of the architecture alone, as {@code rsaml analyze} reports them, from its analysis
     * ({@code timing}, made once its prerequisites hold): a run reporting both the verdicts and the findings
     * analyses it once.
     */
    public static List<Found> all(Architecture architecture, ArchitectureTiming timing) {
        Map<EObject, List<Found>> byElement;
        try {
            byElement = verdicts(timing);
        } catch (RuntimeException e) {
            byElement = failed(architecture, e);
        }
        List<Found> all = new ArrayList<>();
        byElement.values().forEach(all::addAll);
        return all;
    }

    private static String reason(String explanation) {
        return explanation.startsWith("not analysed: ") ? explanation.substring("not analysed: ".length()) : explanation;
    }

    private static void add(Map<EObject, List<Found>> out, Found found) {
        out.computeIfAbsent(found.element(), k -> new ArrayList<>()).add(found);
    }

    private static Rule rule(String verdict) {
        return Rules.forVerdict(verdict).orElseThrow(() -> new IllegalStateException(
                "no rule of the catalogue " + RuleCatalog.SOURCE_FILE + " names the verdict " + verdict + " under verdicts"));
    }

    /** No element of the architecture breaks EMF's structure or a rule the catalogue marks {@code timingPrerequisite}. */
    private static boolean prerequisitesHold(Architecture architecture, OclRules rules, ValidationFacts facts) {
        return withoutTaskSet(architecture, rules, facts) == null;
    }

    /**
     * The first element (in document order, the architecture last) that breaks EMF's structure or a
     * rule the catalogue marks {@code timingPrerequisite}, leaving the architecture without a task set;
     * {@code null} when none does and the architecture can be analysed.
     */
    public static EObject withoutTaskSet(Architecture architecture, OclRules rules) {
        return withoutTaskSet(architecture, rules, null);
    }

    /** The same, recording what it checks in {@code facts} for the rest of the validation. */
    static EObject withoutTaskSet(Architecture architecture, OclRules rules, ValidationFacts facts) {
        Map<Object, Object> context = new HashMap<>();
        for (Iterator<EObject> it = architecture.eAllContents(); ; ) {
            EObject o = it.hasNext() ? it.next() : null;
            EObject element = o == null ? architecture : o;
            boolean sound = STRUCTURE.validate(element.eClass(), element, null, context);
            if (sound && facts != null) {
                facts.structurallySound(element);
            }
            if (!sound || rules.violatesAny(element, Prerequisites.IDS)) {
                return element;
            }
            if (o == null) {
                return null;
            }
        }
    }

    /** Whether a finding of this rule leaves an architecture without a task set (the catalogue's {@code timingPrerequisite}). */
    public static boolean prerequisite(String ruleId) {
        return Prerequisites.IDS.contains(ruleId);
    }

    /** The classes whose invariants apply to an element of {@code eClass}: its supertypes and itself. */
    static List<EClass> classes(EClass eClass) {
        List<EClass> classes = new ArrayList<>(eClass.getEAllSuperTypes());
        classes.add(eClass);
        return classes;
    }
}
