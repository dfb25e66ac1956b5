/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CancellationException;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.DiagnosticChain;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EDataType;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.EValidator;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.impl.EValidatorRegistryImpl;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.eclipse.emf.ecore.util.EObjectValidator;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.TimingModelException;
import org.rsaml.analysis.plan.UnplannableException;
import org.rsaml.model.Architecture;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.resource.SourceLocation;
import org.rsaml.model.support.Interruptions;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.internal.OclRules;
import org.rsaml.validation.internal.RuleEValidator;
import org.rsaml.validation.internal.TimingChecks;

/**
 * Validates RsaML models against the OCL rules of rsaml.ecore and EMF's structural checks, and
 * returns located findings. The same API serves the command line, the Maven plugin and Eclipse.
 */
public final class RsamlModelValidator {

    private static final Comparator<Finding> ORDER = Comparator.comparingInt(Finding::line)
            .thenComparingInt(Finding::column).thenComparing(Finding::ruleId);

    /** EMF's own checks; the OCL invariants are skipped, not reported as missing delegates. */
    private static final EValidator STRUCTURE_ONLY = new EObjectValidator() {
        @Override
        public boolean validate(org.eclipse.emf.ecore.EClass eClass, EObject eObject,
                org.eclipse.emf.common.util.DiagnosticChain diagnostics, Map<Object, Object> context,
                String validationDelegate, String constraint, String expression, int severity, String source, int code) {
            return true;
        }
    };

    private RsamlModelValidator() {
    }

    /** Loads and validates one file; findings sorted by position. */
    public static List<Finding> validate(Path file, String displayName) throws ModelLoadException {
        return validate(ModelLoader.load(file, displayName));
    }

    public static List<Finding> validate(Path file) throws ModelLoadException {
        return validate(file, file.toString());
    }

    /** Validates a loaded model with every RsaML rule. */
    public static List<Finding> validate(LoadedModel model) {
        RsamlValidationSetup.init();
        return toFindings(diagnose(model.resource().getContents(), new RuleEValidator(OclRules.instance())), model);
    }

    /**
     * The findings of the timing rules alone (RSA-22 to RSA-25), worded and located as
     * {@link #validate(LoadedModel)} reports them.
     *
     * @throws ModelLoadException when the model cannot be analysed, as {@link #analyseTiming} decides
     */
    public static List<Finding> validateTiming(LoadedModel model) throws ModelLoadException {
        return validateTiming(model, analyseTiming(model));
    }

    /**
     * The findings of the timing rules alone, as {@link #validateTiming(LoadedModel)} reports them, of a
     * model already analysed: {@code timing} is what {@link #analyseTiming} returned for it. A run that
     * reports the verdicts and the findings analyses each model once.
     */
    public static List<Finding> validateTiming(LoadedModel model, ArchitectureTiming timing) {
        BasicDiagnostic chain = new BasicDiagnostic();
        for (TimingChecks.Found f : TimingChecks.all(model.architecture(), timing)) {
            chain.add(TimingChecks.diagnostic(f));
        }
        return toFindings(chain, model);
    }

    /**
     * The timing analysis of the model's architecture, as {@code rsaml analyze} and the analyze goal
     * report it in every format. This is the one decision whether a model can be analysed.
     *
     * @throws ModelLoadException when it cannot be, located on the element concerned: errors of RSA-00,
     *         RSA-10, RSA-12, RSA-13 or RSA-20 leave the architecture without a task set (each such
     *         error is named, as validation words it), a time cannot be planned, or the deployment
     *         contradicts itself
     */
    public static ArchitectureTiming analyseTiming(LoadedModel model) throws ModelLoadException {
        RsamlValidationSetup.init();
        Architecture architecture = model.architecture();
        EObject broken = TimingChecks.withoutTaskSet(architecture, OclRules.instance());
        if (broken != null) {
            List<ModelLoadException.Problem> problems = new ArrayList<>();
            for (Finding f : validate(model)) {
                if (f.severity() == Severity.ERROR && TimingChecks.prerequisite(f.ruleId())) {
                    problems.add(new ModelLoadException.Problem(new SourceLocation(f.file(), f.line(), f.column()),
                            "the timing cannot be analysed: " + f.ruleId() + ": " + f.message()));
                }
            }
            if (problems.isEmpty()) {
                problems.add(new ModelLoadException.Problem(model.location(broken), "the timing cannot be analysed: "
                        + RsamlLabels.describe(broken) + " leaves the architecture without a task set (rsaml validate lists its errors)"));
            }
            ModelLoadException.Problem first = problems.get(0);
            throw new ModelLoadException(first.location().file(), first.location().line(), first.location().column(), first.message(),
                    problems.subList(1, problems.size()), null);
        }
        try {
            return TimingAnalysis.analyse(architecture);
        } catch (UnplannableException e) {
            throw cannotAnalyse(model, e.element() == null ? architecture : e.element(), e.getMessage(), e);
        } catch (TimingModelException e) {
            throw cannotAnalyse(model, e.element() == null ? architecture : e.element(), e.getMessage(), e);
        }
    }

    private static ModelLoadException cannotAnalyse(LoadedModel model, EObject element, String message, Exception cause) {
        SourceLocation at = model.location(element);
        return new ModelLoadException(at.file(), at.line(), at.column(),
                "the timing cannot be analysed: " + RsamlLabels.describe(element) + ": " + message, cause);
    }

    /** EMF's structural checks alone (multiplicities, proxies, references), without the OCL rules. */
    public static List<Finding> validateStructure(LoadedModel model) {
        return toFindings(diagnose(model.resource().getContents(), STRUCTURE_ONLY), model);
    }

    /** Validates elements that were not read from a file (no line and column). */
    public static List<Finding> validate(EObject root) {
        RsamlValidationSetup.init();
        return toFindings(diagnose(List.of(root), new RuleEValidator(OclRules.instance())), null);
    }

    /**
     * The findings on an element and everything it contains, as an EMF diagnostic for Eclipse's
     * validation UI (the tree editor's Validate action, Sirius decorations): one child per finding,
     * whose message is {@code "RSA-08: Module 'checker' takes ..."} and whose data is the element,
     * the {@link Rule} and the message without the rule id.
     */
    public static Diagnostic diagnose(EObject element) {
        RsamlValidationSetup.init();
        List<Raised> raised = raised(diagnose(List.of(element), new RuleEValidator(OclRules.instance())));
        BasicDiagnostic result = new BasicDiagnostic(RuleEValidator.SOURCE, 0,
                "RsaML rules on " + RsamlLabels.qualifiedName(element), new Object[] { element });
        for (Raised r : raised) {
            result.add(new BasicDiagnostic(r.severity().diagnosticSeverity(), RuleEValidator.SOURCE, 0,
                    r.rule().text(r.message()), new Object[] { r.element(), r.rule(), r.message() }));
        }
        return result;
    }

    private static Diagnostic diagnose(List<EObject> roots, EValidator validator) {
        EValidator.Registry registry = new EValidatorRegistryImpl(EValidator.Registry.INSTANCE);
        registry.put(RsamlPackage.eINSTANCE, validator);
        Diagnostician diagnostician = new Diagnostician(registry) {
            @Override
            public String getObjectLabel(EObject eObject) {
                return RuleEValidator.LABELS.getObjectLabel(eObject);
            }

            @Override
            public String getFeatureLabel(EStructuralFeature feature) {
                return RuleEValidator.LABELS.getFeatureLabel(feature);
            }

            /**
             * A value of one of Ecore's own data types (EString, EInt, EDouble, EBoolean: the types of RsaML's
             * attributes that are not RsaML's) is valid when it is an instance of the type: EMF's validator for Ecore
             * checks no more for any of them. Answered here, so that a validation does not set up that validator,
             * whose first use builds the XML Schema types' regular expressions (some milliseconds of every run).
             */
            @Override
            public boolean validate(EDataType eDataType, Object value, DiagnosticChain diagnostics, Map<Object, Object> context) {
                if (eDataType.getEPackage() == EcorePackage.eINSTANCE && eDataType.isInstance(value)) {
                    return true;
                }
                return super.validate(eDataType, value, diagnostics, context);
            }

            /** A command stopped (its thread interrupted) ends its validation here, before each element. */
            @Override
            public boolean validate(EClass eClass, EObject eObject, DiagnosticChain diagnostics, Map<Object, Object> context) {
                Interruptions.check();
                return super.validate(eClass, eObject, diagnostics, context);
            }

            /** EMF reports what a check of an element throws as that element's error; a stopped command ends instead. */
            @Override
            protected boolean handleThrowable(EClass eClass, EObject eObject, DiagnosticChain diagnostics,
                    Map<Object, Object> context, Throwable throwable) {
                if (throwable instanceof CancellationException stopped) {
                    throw stopped;
                }
                return super.handleThrowable(eClass, eObject, diagnostics, context, throwable);
            }
        };
        Map<Object, Object> context = diagnostician.createDefaultContext();
        if (validator instanceof RuleEValidator) {
            context.put(EValidator.SubstitutionLabelProvider.class, RuleEValidator.LABELS); // once, not per element
        }
        BasicDiagnostic chain = new BasicDiagnostic();
        // One architecture validated whole: its walk judges the timing rules' prerequisites, the timing rules come after it.
        boolean whole = validator instanceof RuleEValidator && roots.size() == 1 && roots.get(0) instanceof Architecture a
                && a.eContainer() == null;
        if (whole) {
            TimingChecks.deferToAfterWalk(context);
        }
        for (EObject root : roots) {
            diagnostician.validate(root, chain, context);
        }
        if (whole) {
            TimingChecks.afterWalk((Architecture) roots.get(0), context).forEach(chain::add);
        }
        return chain;
    }

    private static List<Finding> toFindings(Diagnostic chain, LoadedModel model) {
        List<Finding> findings = new ArrayList<>();
        for (Raised r : raised(chain)) {
            EObject element = r.element();
            int[] at = model == null ? new int[] { 0, 0 } : model.locate(element);
            String file = model != null ? model.file()
                    : element.eResource() == null ? "<memory>" : element.eResource().getURI().toString();
            findings.add(new Finding(r.rule(), r.severity(), r.message(), RsamlLabels.qualifiedName(element),
                    element.eResource() == null ? "" : element.eResource().getURIFragment(element), file, at[0], at[1], r.detail()));
        }
        findings.sort(ORDER);
        return findings;
    }

    /** A problem EMF's diagnostician raised on an element, read as an RsaML rule's finding. */
    private record Raised(EObject element, Rule rule, Severity severity, String message, String detail) {
    }

    private static List<Raised> raised(Diagnostic chain) {
        List<Raised> out = new ArrayList<>();
        collect(chain, out);
        return out;
    }

    private static void collect(Diagnostic diagnostic, List<Raised> out) {
        for (Diagnostic child : diagnostic.getChildren()) {
            if (child.getSeverity() != Diagnostic.OK && !child.getData().isEmpty() && child.getData().get(0) instanceof EObject element) {
                if (RuleEValidator.SOURCE.equals(child.getSource()) && child.getData().size() >= 3) {
                    out.add(new Raised(element, (Rule) child.getData().get(1), severityOf(child.getSeverity()),
                            (String) child.getData().get(2),
                            child.getData().size() >= 4 && child.getData().get(3) instanceof String d ? d : null));
                } else {
                    out.add(new Raised(element, Rules.STRUCTURE, severityOf(child.getSeverity()), child.getMessage(), null));
                }
            }
            collect(child, out);
        }
    }

    private static Severity severityOf(int diagnosticSeverity) {
        return switch (diagnosticSeverity) {
            case Diagnostic.ERROR, Diagnostic.CANCEL -> Severity.ERROR;
            case Diagnostic.WARNING -> Severity.WARNING;
            default -> Severity.INFO;
        };
    }
}
