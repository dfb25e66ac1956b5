package org.rsaml.validation;

import java.util.List;

import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.util.RsamlResourceFactoryImpl;
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

    /** The parsed invariants of rsaml.ecore. */
    public static OclRules rules() {
        OclRules r = rules;
        if (r != null) {
            return r;
        }
        synchronized (RsamlValidationSetup.class) {
            if (rules == null) {
                EPackage.Registry.INSTANCE.put(RsamlPackage.eNS_URI, RsamlPackage.eINSTANCE);
                Resource.Factory.Registry.INSTANCE.getExtensionToFactoryMap().putIfAbsent("rsaml", new RsamlResourceFactoryImpl());
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
