/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.Collection;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EOperation;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.ETypedElement;
import org.eclipse.ocl.EvaluationEnvironment;
import org.eclipse.ocl.ParserException;
import org.eclipse.ocl.ecore.Constraint;
import org.eclipse.ocl.ecore.EcoreEnvironmentFactory;
import org.eclipse.ocl.ecore.EcoreEvaluationEnvironment;
import org.eclipse.ocl.ecore.OCL;
import org.eclipse.ocl.ecore.OCLExpression;
import org.eclipse.ocl.expressions.CollectionKind;

/**
 * Classic Eclipse OCL, parsing and interpreting the invariants of rsaml.ecore: the definition of what an invariant
 * means. Validation runs the invariants compiled from the same text ({@code CompiledInvariants}); the interpreter
 * evaluates those that could not be compiled, judges a changed {@code .ecore} until the code is regenerated, and is
 * the tests' oracle. Nothing loads this class, nor classic OCL, until one of those needs it.
 */
public final class OclInterpreter {

    private final OCL ocl;

    /** With the environment validation uses (feature collection kinds remembered). */
    public OclInterpreter() {
        this(true);
    }

    /** {@code caching == false}: classic OCL's own Ecore environment, to compare the two. */
    public OclInterpreter(boolean caching) {
        registerPackages();
        ocl = OCL.newInstance(caching ? new CachingEnvironmentFactory() : EcoreEnvironmentFactory.INSTANCE);
    }

    /** Registers classic OCL's own packages (the Ecore binding and the standard library) in EMF's registry. */
    public static void registerPackages() {
        org.eclipse.ocl.ecore.EcorePackage.eINSTANCE.getNsURI();
        org.eclipse.ocl.ecore.internal.OCLStandardLibraryImpl.INSTANCE.getClass();
    }

    /** The invariant's body parsed in the context of {@code eClass}. */
    public OCLExpression parse(EClass eClass, String body) throws ParserException {
        OCL.Helper helper = ocl.createOCLHelper();
        helper.setContext(eClass);
        Constraint parsed = helper.createInvariant(body);
        return (OCLExpression) parsed.getSpecification().getBodyExpression();
    }

    /**
     * An invariant ready to evaluate: {@link Boolean#TRUE}, {@link Boolean#FALSE}, or {@code null} for null and invalid.
     * Throws {@link IllegalArgumentException} with the parser's message when the text does not parse.
     */
    public OclRules.Evaluator evaluator(EClass eClass, String body) {
        org.eclipse.ocl.Query<EClassifier, EClass, EObject> query;
        try {
            query = ocl.createQuery(parse(eClass, body));
        } catch (ParserException e) {
            throw new IllegalArgumentException(e.getLocalizedMessage(), e);
        }
        return object -> {
            synchronized (ocl) {
                Object result = query.evaluate(object);
                return result instanceof Boolean b ? b : null;
            }
        };
    }

    /**
     * Classic OCL's Ecore environment, whose evaluation remembers the collection kind of each feature
     * and operation. Classic OCL works it out again on every navigation of a feature and every
     * operation's result, creating a new collection type each time; the kind belongs to the metamodel.
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

    /**
     * Classic OCL's environment, answering itself only where the remembered kind already gives classic OCL's
     * answer: a single value of a single-valued feature or operation is returned as it is. Everything else (a
     * collection to copy, wrap or unwrap) is {@link EcoreEvaluationEnvironment#coerceValue}'s.
     */
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
            boolean single = factory.kinds.computeIfAbsent(element, e -> Optional.ofNullable(getCollectionKind(e))).isEmpty();
            if (single && !(value instanceof Collection<?>)) {
                return value;
            }
            return super.coerceValue(element, value, copy);
        }
    }
}
