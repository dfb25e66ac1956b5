/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.ArrayList;
import java.util.Collection;
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
import org.eclipse.emf.ecore.EOperation;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.ETypedElement;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.ocl.EvaluationEnvironment;
import org.eclipse.ocl.ParserException;
import org.eclipse.ocl.ecore.Constraint;
import org.eclipse.ocl.ecore.EcoreEnvironmentFactory;
import org.eclipse.ocl.ecore.EcoreEvaluationEnvironment;
import org.eclipse.ocl.ecore.OCL;
import org.eclipse.ocl.ecore.OCLExpression;
import org.eclipse.ocl.expressions.CollectionKind;
import org.eclipse.ocl.util.CollectionUtil;
import org.rsaml.model.RsamlPackage;
import org.rsaml.validation.Rule;
import org.rsaml.validation.RsamlValidationSetup;
import org.rsaml.validation.RsamlValidationSetup.RuleDefinitionException;
import org.rsaml.validation.Rules;

/**
 * The OCL invariants of an EPackage, read from its OCLinEcore annotations, parsed once with classic
 * OCL and evaluated on demand. Parsing everything up front makes a broken constraint fail at
 * start-up, naming its rule, instead of on every element it applies to.
 */
public final class OclRules {

    /** The delegate URI under which rsaml.ecore declares its invariants. */
    public static final String OCL_URI = "http://www.eclipse.org/emf/2002/Ecore/OCL";

    private static volatile OclRules instance;

    private final OCL ocl = OCL.newInstance(new CachingEnvironmentFactory());
    private final Map<EClass, Map<String, org.eclipse.ocl.Query<EClassifier, EClass, EObject>>> queries = new HashMap<>();
    private final List<String> problems = new ArrayList<>();
    private final Set<String> declared = new HashSet<>();

    public OclRules(EPackage ePackage) {
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
                try {
                    OCL.Helper helper = ocl.createOCLHelper();
                    helper.setContext(eClass);
                    Constraint parsed = helper.createInvariant(body);
                    OCLExpression expression = (OCLExpression) parsed.getSpecification().getBodyExpression();
                    queries.computeIfAbsent(eClass, k -> new HashMap<>()).put(constraint, ocl.createQuery(expression));
                } catch (ParserException | RuntimeException e) {
                    problems.add(rule + " (" + constraint + " on " + eClass.getName() + ") does not parse: "
                            + e.getLocalizedMessage());
                }
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
     * The parsed invariants of rsaml.ecore, parsed once. Throws {@link RuleDefinitionException}
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

    /** Registers classic OCL's own packages (the Ecore binding and the standard library) in EMF's registry. */
    public static void registerPackages() {
        org.eclipse.ocl.ecore.EcorePackage.eINSTANCE.getNsURI();
        org.eclipse.ocl.ecore.internal.OCLStandardLibraryImpl.INSTANCE.getClass();
    }

    /** One line per constraint that has no body or does not parse; empty when all are usable. */
    public List<String> problems() {
        return List.copyOf(problems);
    }

    /** Number of parsed constraints. */
    public int size() {
        return queries.values().stream().mapToInt(Map::size).sum();
    }

    /** Whether an invariant of one of {@code ruleIds} is violated on the element, or cannot be evaluated there. */
    public boolean violatesAny(EObject object, Set<String> ruleIds) {
        return violatesAny(object, ruleIds, null);
    }

    /** The same, telling {@code facts} each definite result. */
    boolean violatesAny(EObject object, Set<String> ruleIds, ValidationFacts facts) {
        for (EClass eClass : TimingChecks.classes(object)) {
            Map<String, org.eclipse.ocl.Query<EClassifier, EClass, EObject>> byName = queries.get(eClass);
            if (byName == null) {
                continue;
            }
            for (String constraint : byName.keySet()) {
                if (Rules.forConstraint(constraint).map(r -> ruleIds.contains(r.id())).orElse(false)) {
                    Boolean satisfied;
                    try {
                        satisfied = check(eClass, constraint, object);
                    } catch (RuntimeException e) {
                        satisfied = null;
                    }
                    if (facts != null && satisfied != null) {
                        facts.invariant(object, constraint, satisfied);
                    }
                    if (!Boolean.TRUE.equals(satisfied)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /**
     * Evaluates the invariant {@code constraint} declared on {@code eClass} for {@code object}:
     * {@link Boolean#TRUE} or {@link Boolean#FALSE}, or {@code null} when the expression is
     * invalid for this object (for example a navigation through a missing element).
     */
    public synchronized Boolean check(EClass eClass, String constraint, EObject object) {
        Map<String, org.eclipse.ocl.Query<EClassifier, EClass, EObject>> byName = queries.get(eClass);
        org.eclipse.ocl.Query<EClassifier, EClass, EObject> query = byName == null ? null : byName.get(constraint);
        if (query == null) {
            throw new IllegalArgumentException("no OCL invariant " + constraint + " on " + eClass.getName());
        }
        Object result = query.evaluate(object);
        return result instanceof Boolean b ? b : null;
    }

    /**
     * Classic OCL's Ecore environment, whose evaluation remembers the collection kind of each feature
     * and operation. Classic OCL works it out again on every navigation of a feature and every
     * operation's result, creating a new collection type each time (about a fifth of all evaluation
     * time on large models); the kind belongs to the metamodel, so it never changes.
     */
    private static final class CachingEnvironmentFactory extends EcoreEnvironmentFactory {
        private final Map<ETypedElement, Optional<CollectionKind>> kinds = new ConcurrentHashMap<>();

        @Override
        public EvaluationEnvironment<EClassifier, EOperation, EStructuralFeature, EClass, EObject> createEvaluationEnvironment() {
            return new CachingEvaluationEnvironment(this);
        }

        @Override
        public EvaluationEnvironment<EClassifier, EOperation, EStructuralFeature, EClass, EObject> createEvaluationEnvironment(
                EvaluationEnvironment<EClassifier, EOperation, EStructuralFeature, EClass, EObject> parent) {
            return new CachingEvaluationEnvironment(parent, this);
        }
    }

    /** {@link EcoreEvaluationEnvironment#coerceValue} with the feature's collection kind looked up once. */
    private static final class CachingEvaluationEnvironment extends EcoreEvaluationEnvironment {
        private final CachingEnvironmentFactory factory;

        CachingEvaluationEnvironment(CachingEnvironmentFactory factory) {
            super(factory);
            this.factory = factory;
        }

        CachingEvaluationEnvironment(EvaluationEnvironment<EClassifier, EOperation, EStructuralFeature, EClass, EObject> parent,
                CachingEnvironmentFactory factory) {
            super(parent);
            this.factory = factory;
        }

        @Override
        protected Object coerceValue(ETypedElement element, Object value, boolean copy) {
            CollectionKind kind = factory.kinds.computeIfAbsent(element, e -> Optional.ofNullable(getCollectionKind(e))).orElse(null);
            if (kind != null) {
                if (value instanceof Collection<?> collection) {
                    return copy ? CollectionUtil.createNewCollection(kind, collection) : collection;
                }
                Collection<Object> single = CollectionUtil.createNewCollection(kind);
                single.add(value);
                return single;
            }
            if (value instanceof Collection<?> collection) {
                return collection.isEmpty() ? null : collection.iterator().next();
            }
            return value;
        }
    }
}
