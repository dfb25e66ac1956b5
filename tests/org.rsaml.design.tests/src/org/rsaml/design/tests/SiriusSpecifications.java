/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.DiagnosticChain;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EEnumLiteral;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.EValidator;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.impl.EValidatorRegistryImpl;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.eclipse.emf.ecore.util.EObjectValidator;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceImpl;

/**
 * Loads a Sirius viewpoint specification (.odesign) without Sirius: Sirius's metamodels are read as
 * dynamic EMF packages, the .odesign is read as an instance of them, and every problem a Sirius
 * installation would meet in the file is listed: unknown classes and features, dangling references,
 * and violated multiplicities.
 */
final class SiriusSpecifications {

    /** The .odesign's content and what is wrong with it, each problem on one line. */
    record Loaded(Resource resource, EPackage rsaml, List<String> problems) {
        EObject group() {
            return resource.getContents().get(0);
        }
    }

    private SiriusSpecifications() {
    }

    static Loaded load(Path siriusMetamodels, Path rsamlEcore, Path odesign) throws IOException {
        ResourceSet set = new ResourceSetImpl();
        set.getResourceFactoryRegistry().getExtensionToFactoryMap().put("ecore", new EcoreResourceFactoryImpl());
        set.getResourceFactoryRegistry().getExtensionToFactoryMap().put("odesign", new XMIResourceFactoryImpl());
        // Sirius's metamodels name Ecore by its plug-in location and viewpoint.ecore by its path in Sirius's sources.
        set.getPackageRegistry().put("platform:/plugin/org.eclipse.emf.ecore/model/Ecore.ecore", EcorePackage.eINSTANCE);
        Resource viewpoint = set.getResource(URI.createFileURI(siriusMetamodels.resolve("viewpoint.ecore").toString()), true);
        URI diagramUri = URI.createFileURI(siriusMetamodels.resolve("diagram.ecore").toString());
        set.getURIConverter().getURIMap().put(URI.createURI("../../org.eclipse.sirius.model/model/viewpoint.ecore").resolve(diagramUri),
                viewpoint.getURI());
        Resource diagram = set.getResource(diagramUri, true);
        List<String> problems = new ArrayList<>();
        for (Resource metamodel : List.of(viewpoint, diagram)) {
            EcoreUtil.resolveAll(metamodel);
            register(set, (EPackage) metamodel.getContents().get(0));
        }
        EPackage rsaml = (EPackage) set.getResource(URI.createFileURI(rsamlEcore.toString()), true).getContents().get(0);
        set.getPackageRegistry().put(rsaml.getNsURI(), rsaml);
        set.getResources().add(environment(set));

        Resource resource = set.createResource(URI.createFileURI(odesign.toString()));
        try {
            resource.load(Map.of());
        } catch (IOException | RuntimeException e) {
            // A file that cannot be read at all says why in the resource's errors, listed below.
        }
        for (Resource.Diagnostic d : resource.getErrors()) {
            problems.add("error at " + d.getLine() + ":" + d.getColumn() + ": " + withoutLocation(d.getMessage()));
        }
        for (Resource.Diagnostic d : resource.getWarnings()) {
            problems.add("warning at " + d.getLine() + ":" + d.getColumn() + ": " + withoutLocation(d.getMessage()));
        }
        if (resource.getContents().isEmpty()) {
            return new Loaded(resource, rsaml, problems);
        }
        EcoreUtil.resolveAll(resource);
        for (EObject element : (Iterable<EObject>) resource::getAllContents) {
            for (EReference reference : element.eClass().getEAllReferences()) {
                if (reference.isContainment() || reference.isDerived() || reference.isTransient()) {
                    continue;
                }
                Object value = element.eGet(reference, false);
                for (Object target : value instanceof List<?> list ? list : value == null ? List.of() : List.of(value)) {
                    if (((EObject) target).eIsProxy()) {
                        problems.add("unresolved reference " + where(element) + "." + reference.getName() + " -> "
                                + ((org.eclipse.emf.ecore.InternalEObject) target).eProxyURI());
                    }
                }
            }
        }
        EValidator.Registry validators = new EValidatorRegistryImpl();
        EValidator structure = new PersistedStructureValidator();
        for (EObject element : (Iterable<EObject>) resource::getAllContents) {
            validators.putIfAbsent(element.eClass().getEPackage(), structure);
        }
        Diagnostician diagnostician = new Diagnostician(validators) {
            @Override
            public String getObjectLabel(EObject eObject) {
                return where(eObject);
            }
        };
        BasicDiagnostic chain = new BasicDiagnostic();
        diagnostician.validate(resource.getContents().get(0), chain, diagnostician.createDefaultContext());
        collect(chain, problems);
        return new Loaded(resource, rsaml, problems);
    }

    /** A readable path to a specification element: the names of its named ancestors and its own class. */
    static String where(EObject element) {
        List<String> names = new ArrayList<>();
        for (EObject e = element; e != null; e = e.eContainer()) {
            EStructuralFeature name = e.eClass().getEStructuralFeature("name");
            Object value = name == null ? null : e.eGet(name);
            if (value != null && !value.toString().isBlank()) {
                names.add(0, value.toString());
            } else if (e == element) {
                names.add(0, e.eClass().getName());
            }
        }
        return String.join("/", names);
    }

    // Reading the dynamic specification by feature name: Sirius's classes exist here only as EClasses.

    static boolean is(EObject object, String className) {
        return object.eClass().getName().equals(className)
                || object.eClass().getEAllSuperTypes().stream().anyMatch(c -> c.getName().equals(className));
    }

    static Object get(EObject object, String feature) {
        EStructuralFeature f = object.eClass().getEStructuralFeature(feature);
        return f == null ? null : object.eGet(f);
    }

    static EObject ref(EObject object, String feature) {
        return (EObject) get(object, feature);
    }

    @SuppressWarnings("unchecked")
    static List<EObject> list(EObject object, String feature) {
        Object value = get(object, feature);
        return value == null ? List.of() : (List<EObject>) value;
    }

    /** EMF ends its messages with "(file, line, column)"; the line and column are given once, in front. */
    private static String withoutLocation(String message) {
        return message == null ? "" : message.replaceFirst("\\s\\([^()]*, \\d+, \\d+\\)$", "");
    }

    private static void register(ResourceSet set, EPackage ePackage) {
        set.getPackageRegistry().put(ePackage.getNsURI(), ePackage);
        ePackage.getESubpackages().forEach(p -> register(set, p));
    }

    /**
     * Sirius serves {@code environment:/viewpoint} at run time: its system colour palette has one
     * colour per literal of {@code SystemColors}. The same, built from Sirius's own metamodel.
     */
    private static Resource environment(ResourceSet set) {
        EPackage description = set.getPackageRegistry().getEPackage("http://www.eclipse.org/sirius/description/1.1.0");
        EObject environment = EcoreUtil.create((EClass) description.getEClassifier("Environment"));
        EObject palette = EcoreUtil.create((EClass) description.getEClassifier("SytemColorsPalette"));
        environment.eSet(environment.eClass().getEStructuralFeature("systemColors"), palette);
        @SuppressWarnings("unchecked")
        List<EObject> entries = (List<EObject>) palette.eGet(palette.eClass().getEStructuralFeature("entries"));
        EClass systemColor = (EClass) description.getEClassifier("SystemColor");
        for (EEnumLiteral literal : ((EEnum) description.getEClassifier("SystemColors")).getELiterals()) {
            EObject color = EcoreUtil.create(systemColor);
            color.eSet(systemColor.getEStructuralFeature("name"), literal.getName());
            entries.add(color);
        }
        Resource resource = new XMIResourceImpl(URI.createURI("environment:/viewpoint"));
        resource.getContents().add(environment);
        return resource;
    }

    private static void collect(Diagnostic diagnostic, List<String> problems) {
        for (Diagnostic child : diagnostic.getChildren()) {
            if (child.getSeverity() >= Diagnostic.WARNING) {
                problems.add((child.getSeverity() == Diagnostic.ERROR ? "invalid: " : "suspect: ") + child.getMessage());
            }
            collect(child, problems);
        }
    }

    /**
     * EMF's structural checks on what a file holds. Sirius computes its transient features in code
     * (the system colour palette of a group, for one), so their multiplicity says nothing about the file.
     */
    private static final class PersistedStructureValidator extends EObjectValidator {
        @Override
        protected boolean validate_MultiplicityConforms(EObject eObject, EStructuralFeature eStructuralFeature,
                DiagnosticChain diagnostics, Map<Object, Object> context) {
            return eStructuralFeature.isTransient()
                    || super.validate_MultiplicityConforms(eObject, eStructuralFeature, diagnostics, context);
        }
    }
}
