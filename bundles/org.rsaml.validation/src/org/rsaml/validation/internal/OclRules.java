/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import org.eclipse.emf.ecore.EAnnotation;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.rsaml.model.RsamlPackage;
import org.rsaml.validation.Rule;
import org.rsaml.validation.RsamlValidationSetup;
import org.rsaml.validation.RsamlValidationSetup.RuleDefinitionException;
import org.rsaml.validation.Rules;

/**
 * The OCL invariants of an EPackage, read from its OCLinEcore annotations, each bound to its catalogue entry and
 * evaluated on demand. An invariant of rsaml.ecore whose text is the one {@code CompiledInvariants} was generated from
 * runs as that Java; any other (one the translator left to the interpreter, or a text changed since the code was
 * regenerated) is interpreted by classic OCL ({@link OclInterpreter}). A text that was compiled is known to parse, so
 * classic OCL is loaded only when something must be interpreted; a text that was not is parsed here, so that a broken
 * constraint fails at start-up, naming its rule, instead of on every element it applies to.
 */
public final class OclRules {

    /** The delegate URI under which rsaml.ecore declares its invariants. */
    public static final String OCL_URI = "http://www.eclipse.org/emf/2002/Ecore/OCL";

    /** One invariant, ready to evaluate: TRUE, FALSE, or null when the expression is null or invalid for the element. */
    @FunctionalInterface
    public interface Evaluator {
        Boolean evaluate(EObject object);
    }

    private static volatile OclRules instance;

    private final boolean compiled;
    private OclInterpreter interpreter;
    private final Map<EClass, Map<String, Evaluator>> evaluators = new HashMap<>();
    private final List<String> problems = new ArrayList<>();
    private final Set<String> declared = new HashSet<>();
    private int compiledCount;
    private final Map<String, String> interpreted = new java.util.TreeMap<>();

    /** Compiled where the text matches the generated code (rsaml.ecore's own package only), interpreted elsewhere. */
    public OclRules(EPackage ePackage) {
        this(ePackage, ePackage == RsamlPackage.eINSTANCE, null);
    }

    private OclRules(EPackage ePackage, boolean compiled, OclInterpreter interpreter) {
        this.compiled = compiled;
        this.interpreter = interpreter;
        for (EClassifier classifier : ePackage.getEClassifiers()) {
            if (!(classifier instanceof EClass eClass)) {
                continue;
            }
            EAnnotation bodies = eClass.getEAnnotation(OCL_URI);
            for (String constraint : EcoreUtil.getConstraints(eClass)) {
                declared.add(constraint);
                Optional<Rule> catalogued = Rules.forConstraint(constraint);
                String rule = catalogued.map(Rule::id).orElse("unknown rule");
                if (catalogued.isEmpty() || catalogued.get().message() == null) {
                    problems.add(rule + " (" + constraint + " on " + eClass.getName()
                            + ") has no entry with a message in the rule catalogue " + RuleCatalog.SOURCE_FILE);
                    continue;
                }
                String body = bodies == null ? null : bodies.getDetails().get(constraint);
                if (body == null) {
                    problems.add(rule + " (" + constraint + " on " + eClass.getName() + ") has no OCL body");
                    continue;
                }
                Evaluator evaluator = compiled ? compiled(eClass, constraint, body) : null;
                if (evaluator == null) {
                    String why = compiled ? CompiledInvariants.interpreted(eClass.getName(), constraint, body) : null;
                    if (compiled) {
                        interpreted.put(eClass.getName() + "." + constraint,
                                why != null ? why : "its text in the .ecore is not the one compiled: regenerate the code");
                    }
                    try {
                        evaluator = why != null ? lazilyInterpreted(eClass, body) : interpreter().evaluator(eClass, body);
                    } catch (RuntimeException e) {
                        problems.add(rule + " (" + constraint + " on " + eClass.getName() + ") does not parse: "
                                + e.getLocalizedMessage());
                        continue;
                    }
                } else {
                    compiledCount++;
                }
                evaluators.computeIfAbsent(eClass, k -> new HashMap<>()).put(constraint, evaluator);
            }
        }
        if (ePackage == RsamlPackage.eINSTANCE || RsamlPackage.eNS_URI.equals(ePackage.getNsURI())) {
            for (Rule rule : Rules.all()) {
                List<String> undeclared = rule.constraints().stream().filter(c -> !declared.contains(c)).toList();
                if (!undeclared.isEmpty()) {
                    problems.add(rule.id() + " is in the rule catalogue but no invariant of " + ePackage.getName()
                            + " declares the constraint " + String.join(", ", undeclared) + " it names in " + RuleCatalog.SOURCE_FILE);
                } else if (rule.message() != null && rule.constraints().isEmpty() && !rule.isTiming()) {
                    problems.add(rule.id() + " is in the rule catalogue but no invariant of " + ePackage.getName()
                            + " implements it (name its constraints under " + rule.id() + ".constraints)");
                }
            }
            problems.addAll(TimingChecks.bindingProblems(Rules.all()));
        }
    }

    /**
     * Every invariant interpreted by classic OCL, none compiled: the definition the compiled invariants are tested
     * against. {@code cachingEnvironment == false} interprets in classic OCL's own Ecore environment.
     */
    public static OclRules interpreted(EPackage ePackage, boolean cachingEnvironment) {
        return new OclRules(ePackage, false, new OclInterpreter(cachingEnvironment));
    }

    /**
     * The rules of rsaml.ecore, set up once. Throws {@link RuleDefinitionException}
     * when an invariant has no body, does not parse, or has no complete entry in the catalogue.
     */
    public static OclRules instance() {
        OclRules r = instance;
        if (r != null) {
            return r;
        }
        synchronized (OclRules.class) {
            if (instance == null) {
                RsamlValidationSetup.registerPackage();
                OclRules parsed = new OclRules(RsamlPackage.eINSTANCE);
                if (!parsed.problems().isEmpty()) {
                    throw new RuleDefinitionException(parsed.problems());
                }
                instance = parsed;
            }
            return instance;
        }
    }

    private Evaluator compiled(EClass eClass, String constraint, String body) {
        int index = CompiledInvariants.index(eClass.getName(), constraint, body);
        return index < 0 ? null : object -> CompiledInvariants.check(index, object);
    }

    /** An invariant the translator parsed but left to the interpreter: parsed when first evaluated. */
    private Evaluator lazilyInterpreted(EClass eClass, String body) {
        return new Evaluator() {
            private volatile Evaluator parsed;

            @Override
            public Boolean evaluate(EObject object) {
                Evaluator e = parsed;
                if (e == null) {
                    synchronized (this) {
                        if (parsed == null) {
                            parsed = interpreter().evaluator(eClass, body);
                        }
                        e = parsed;
                    }
                }
                return e.evaluate(object);
            }
        };
    }

    private synchronized OclInterpreter interpreter() {
        if (interpreter == null) {
            interpreter = new OclInterpreter();
        }
        return interpreter;
    }

    /** One line per constraint that has no body or does not parse; empty when all are usable. */
    public List<String> problems() {
        return List.copyOf(problems);
    }

    /** Number of usable constraints. */
    public int size() {
        return evaluators.values().stream().mapToInt(Map::size).sum();
    }

    /** Number of constraints that run as compiled Java. */
    public int compiledCount() {
        return compiledCount;
    }

    /**
     * The invariants a compiling instance interprets, as {@code Class.constraint}, each with why: left to the
     * interpreter by the translator, or changed since the code was generated.
     */
    public Map<String, String> interpreted() {
        return Map.copyOf(interpreted);
    }

    /** Whether this instance compiles (false: every invariant interpreted). */
    public boolean isCompiled() {
        return compiled;
    }

    /** Whether an invariant of one of {@code ruleIds} is violated on the element, or cannot be evaluated there. */
    public boolean violatesAny(EObject object, Set<String> ruleIds) {
        for (Bound bound : byRules.computeIfAbsent(ruleIds, k -> new ConcurrentHashMap<>())
                .computeIfAbsent(object.eClass(), c -> bind(c, ruleIds))) {
            Boolean satisfied;
            try {
                satisfied = evaluate(bound.evaluator(), object);
            } catch (RuntimeException e) {
                satisfied = null;
            }
            if (!Boolean.TRUE.equals(satisfied)) {
                return true;
            }
        }
        return false;
    }

    /** An invariant an element of some class must satisfy, with its evaluator. */
    private record Bound(EClass declaredOn, String constraint, Evaluator evaluator) {
    }

    private final Map<Set<String>, Map<EClass, List<Bound>>> byRules = new ConcurrentHashMap<>();

    /** The invariants of the rules {@code ruleIds} that apply to an element of {@code eClass}, supertypes' first. */
    private List<Bound> bind(EClass eClass, Set<String> ruleIds) {
        List<Bound> bound = new ArrayList<>();
        for (EClass c : TimingChecks.classes(eClass)) {
            Map<String, Evaluator> byName = evaluators.get(c);
            if (byName == null) {
                continue;
            }
            for (Map.Entry<String, Evaluator> e : byName.entrySet()) {
                if (Rules.forConstraint(e.getKey()).map(r -> ruleIds.contains(r.id())).orElse(false)) {
                    bound.add(new Bound(c, e.getKey(), e.getValue()));
                }
            }
        }
        return List.copyOf(bound);
    }

    /** The evaluator of the invariant {@code constraint} declared on {@code eClass}; null when there is none. */
    public Evaluator evaluator(EClass eClass, String constraint) {
        Map<String, Evaluator> byName = evaluators.get(eClass);
        return byName == null ? null : byName.get(constraint);
    }

    /** The evaluator's result on the object: TRUE, FALSE, or null for null and invalid. */
    public static Boolean evaluate(Evaluator evaluator, EObject object) {
        try {
            return evaluator.evaluate(object);
        } catch (CompiledOcl.Invalid e) {
            return null;
        }
    }

    /**
     * Evaluates the invariant {@code constraint} declared on {@code eClass} for {@code object}:
     * {@link Boolean#TRUE} or {@link Boolean#FALSE}, or {@code null} when the expression is
     * invalid for this object (for example a navigation through a missing element).
     */
    public Boolean check(EClass eClass, String constraint, EObject object) {
        Evaluator evaluator = evaluator(eClass, constraint);
        if (evaluator == null) {
            throw new IllegalArgumentException("no OCL invariant " + constraint + " on " + eClass.getName());
        }
        return evaluate(evaluator, object);
    }
}
