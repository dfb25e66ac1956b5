/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.List;

import org.rsaml.model.RsamlPackage;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.validation.internal.OclRules;

/**
 * Makes RsaML's rules runnable, in a plain JVM as inside OSGi: registers the package and the
 * {@code .rsaml} resource factory, and parses every OCL invariant of rsaml.ecore once, so that a
 * broken rule fails here, naming its id, instead of on every element.
 */
public final class RsamlValidationSetup {

    private static volatile OclRules rules;

    private RsamlValidationSetup() {
    }

    /** Idempotent and thread-safe; cheap after the first call. */
    public static void init() {
        rules();
    }

    /**
     * Starts {@link #init()} on a daemon thread and returns at once, so that parsing the rules
     * overlaps with whatever the caller does next (reading models); {@link #init()} and
     * {@link #rules()} wait for it. A broken rule is still reported by the next {@link #init()}.
     */
    public static void initInBackground() {
        if (rules != null) {
            return;
        }
        // EMF's package registry is not thread-safe: make every registration the parse would
        // make here, on the caller's thread, so the parser thread only reads the registry.
        registerPackage();
        OclRules.registerPackages();
        Thread thread = new Thread(() -> {
            try {
                init();
            } catch (RuntimeException e) {
                // reported again, to the caller, by the next init()
            }
        }, "rsaml-rules");
        thread.setDaemon(true);
        thread.start();
    }

    /** Registers the RsaML package and the {@code .rsaml} resource factory: all that reading a model needs. */
    public static void registerPackage() {
        RsamlStandaloneSetup.init();
    }

    /** The parsed invariants of rsaml.ecore. */
    public static OclRules rules() {
        OclRules r = rules;
        if (r != null) {
            return r;
        }
        synchronized (RsamlValidationSetup.class) {
            if (rules == null) {
                registerPackage();
                OclRules parsed = new OclRules(RsamlPackage.eINSTANCE);
                if (!parsed.problems().isEmpty()) {
                    throw new RuleDefinitionException(parsed.problems());
                }
                rules = parsed;
            }
            return rules;
        }
    }

    /** Thrown at start-up when a rule of the metamodel cannot be used. */
    public static final class RuleDefinitionException extends IllegalStateException {
        private static final long serialVersionUID = 1L;
        private final List<String> problems;

        public RuleDefinitionException(List<String> problems) {
            super("RsaML rules are broken in rsaml.ecore:\n  " + String.join("\n  ", problems));
            this.problems = List.copyOf(problems);
        }

        public List<String> problems() {
            return problems;
        }
    }
}
