/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.List;

import org.eclipse.emf.ecore.EValidator;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.validation.internal.OclRules;
import org.rsaml.validation.internal.RuleEValidator;

/**
 * Makes RsaML's rules runnable in a plain JVM: registers the package, the {@code .rsaml} resource
 * factory and RsaML's validator in EMF's registries (so that EMF's stock {@code Diagnostician}
 * reports RsaML's findings), and binds every OCL invariant of rsaml.ecore to its compiled Java (or, for
 * one that is interpreted, parses it), so that a broken rule fails here, naming its id, instead of on every element. Inside OSGi the bundle's
 * component ({@code OSGI-INF/validator.xml}) registers the validator.
 */
public final class RsamlValidationSetup {

    private RsamlValidationSetup() {
    }

    /** Idempotent and thread-safe; cheap after the first call. */
    public static void init() {
        registerValidator();
        OclRules.instance();
    }

    /**
     * The same as {@link #init()}. It once parsed the rules on a thread of its own while the caller read models; the
     * invariants are now compiled at build time, so setting up costs about a millisecond and classic OCL is loaded only
     * if an invariant must be interpreted.
     */
    public static void initInBackground() {
        init();
    }

    /** Registers the RsaML package and the {@code .rsaml} resource factory: all that reading a model needs. */
    public static void registerPackage() {
        RsamlStandaloneSetup.init();
    }

    /**
     * Registers the package and puts RsaML's validator in EMF's validator registry for it: the only
     * validator of the package (the generated package registers none).
     */
    public static synchronized void registerValidator() {
        registerPackage();
        EValidator.Registry.INSTANCE.put(RsamlPackage.eINSTANCE, RuleEValidator.DESCRIPTOR);
    }

    /** Thrown at start-up when a rule of the metamodel or its catalogue entry cannot be used. */
    public static final class RuleDefinitionException extends IllegalStateException {
        private static final long serialVersionUID = 1L;
        private final List<String> problems;

        public RuleDefinitionException(List<String> problems) {
            super("RsaML rules are broken in rsaml.ecore or the rule catalogue rules/rules.properties:\n  " + String.join("\n  ", problems));
            this.problems = List.copyOf(problems);
        }

        public List<String> problems() {
            return problems;
        }
    }
}
