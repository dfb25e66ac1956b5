/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.TimeUnit;

/** Every concept and every attribute of RsaML survives a save to .rsaml and a reload. */
class RoundTripTest {

    @TempDir
    Path dir;

    @Test
    void everyConceptAndAttributeSurvivesSaveAndReload() throws Exception {
        Map<EClass, List<EObject>> instances = new HashMap<>();
        Architecture root = (Architecture) populate(RsamlPackage.Literals.ARCHITECTURE, instances, 0);
        linkReferences(instances);

        Set<String> concrete = new TreeSet<>();
        for (EClassifier c : RsamlPackage.eINSTANCE.getEClassifiers()) {
            if (c instanceof EClass e && !e.isAbstract() && !e.isInterface()) {
                concrete.add(e.getName());
            }
        }
        Set<String> created = new TreeSet<>();
        instances.keySet().forEach(c -> created.add(c.getName()));
        assertEquals(concrete, created, "the round-trip model must hold every concrete RsaML concept");

        URI uri = URI.createFileURI(dir.resolve("all-concepts.rsaml").toString());
        ResourceSet saveSet = new ResourceSetImpl();
        Resource saved = saveSet.createResource(uri);
        saved.getContents().add(root);
        saved.save(null);
        assertTrue(Files.size(dir.resolve("all-concepts.rsaml")) > 0);

        Resource reloaded = new ResourceSetImpl().getResource(uri, true);
        assertTrue(reloaded.getErrors().isEmpty(), () -> "reload errors: " + reloaded.getErrors());
        EObject copy = reloaded.getContents().get(0);
        EcoreUtil.resolveAll(reloaded);
        assertTrue(EcoreUtil.UnresolvedProxyCrossReferencer.find(reloaded).isEmpty());
        assertTrue(new EcoreUtil.EqualityHelper().equals(root, copy),
                "the reloaded model must equal the saved one, attribute for attribute and reference for reference");

        // Container opposites are transient but restored on load, so rules can navigate upwards.
        Module module = ((Architecture) copy).getLayers().get(0).getModules().get(0);
        assertEquals(((Architecture) copy).getLayers().get(0), module.getLayer());
        assertEquals(module, module.getPorts().get(0).getModule());
    }

    @Test
    void cyclicReferencesUseReadableNameKeys() throws Exception {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName("robot");
        Layer control = f.createLayer();
        control.setName("control");
        a.getLayers().add(control);
        Module checker = f.createModule();
        checker.setName("resourceChecker");
        control.getModules().add(checker);
        var out = f.createOutputPort();
        out.setName("s0");
        var in = f.createEntryPort();
        in.setName("e0");
        checker.getPorts().add(out);
        checker.getPorts().add(in);
        var connection = f.createConnection();
        connection.setSource(out);
        connection.setTarget(in);
        a.getConnections().add(connection);

        Path file = dir.resolve("keys.rsaml");
        Resource r = new ResourceSetImpl().createResource(URI.createFileURI(file.toString()));
        r.getContents().add(a);
        r.save(null);
        String xml = Files.readString(file);
        assertTrue(xml.contains("source=\"//@layers[name='control']/@modules[name='resourceChecker']/@ports[name='s0']\""), xml);
    }

    @Test
    void timeValuesOfDifferentUnitsAreComparableInMilliseconds() {
        Layer layer = RsamlFactory.eINSTANCE.createLayer();
        layer.setTimeUnit(TimeUnit.US);
        assertEquals(2.0, layer.toMilliseconds(2000.0), 1e-12);
        layer.setTimeUnit(TimeUnit.S);
        assertEquals(1500.0, layer.toMilliseconds(1.5), 1e-9);
        layer.setTimeUnit(TimeUnit.NS);
        assertEquals(0.5, layer.toMilliseconds(500_000.0), 1e-12);
        assertEquals(TimeUnit.MS, RsamlFactory.eINSTANCE.createModule().getTimeUnit(), "milliseconds by default");
    }

    /** Creates an instance with every attribute set to a non-default value, and one child per containment. */
    private EObject populate(EClass eClass, Map<EClass, List<EObject>> instances, int depth) {
        EObject object = EcoreUtil.create(eClass);
        instances.computeIfAbsent(eClass, k -> new ArrayList<>()).add(object);
        int n = instances.get(eClass).size();
        for (EAttribute attribute : eClass.getEAllAttributes()) {
            if (attribute.isChangeable() && !attribute.isDerived() && !attribute.isTransient()) {
                object.eSet(attribute, sample(attribute, eClass.getName() + n));
            }
        }
        if (depth > 3) {
            return object;
        }
        for (EReference containment : eClass.getEAllContainments()) {
            for (EClass type : concreteSubtypes(containment.getEReferenceType())) {
                EObject child = populate(type, instances, depth + (type == eClass ? 3 : 1));
                if (containment.isMany()) {
                    @SuppressWarnings("unchecked")
                    List<EObject> list = (List<EObject>) object.eGet(containment);
                    list.add(child);
                } else {
                    object.eSet(containment, child);
                }
            }
        }
        return object;
    }

    private void linkReferences(Map<EClass, List<EObject>> instances) {
        for (List<EObject> objects : instances.values()) {
            for (EObject object : objects) {
                for (EReference reference : object.eClass().getEAllReferences()) {
                    if (reference.isContainment() || reference.isContainer() || reference.isTransient()
                            || !reference.isChangeable()) {
                        continue;
                    }
                    EObject target = instances.entrySet().stream()
                            .filter(e -> reference.getEReferenceType().isSuperTypeOf(e.getKey()))
                            .flatMap(e -> e.getValue().stream()).findFirst().orElse(null);
                    assertNotNull(target, "no instance for " + reference.getName());
                    if (reference.isMany()) {
                        @SuppressWarnings("unchecked")
                        List<EObject> list = (List<EObject>) object.eGet(reference);
                        list.add(target);
                    } else {
                        object.eSet(reference, target);
                    }
                }
            }
        }
    }

    private static List<EClass> concreteSubtypes(EClass type) {
        List<EClass> result = new ArrayList<>();
        for (EClassifier c : RsamlPackage.eINSTANCE.getEClassifiers()) {
            if (c instanceof EClass e && !e.isAbstract() && !e.isInterface() && type.isSuperTypeOf(e)) {
                result.add(e);
            }
        }
        return result;
    }

    private static Object sample(EAttribute attribute, String seed) {
        EClassifier type = attribute.getEType();
        if (type instanceof EEnum eEnum) {
            List<?> literals = eEnum.getELiterals();
            return ((org.eclipse.emf.ecore.EEnumLiteral) literals.get(literals.size() - 1)).getInstance();
        }
        Class<?> c = type.getInstanceClass();
        if (c == String.class) {
            return attribute.getName() + "_" + seed;
        }
        if (c == double.class || c == Double.class) {
            return 2.5;
        }
        if (c == int.class || c == Integer.class) {
            return 3;
        }
        throw new AssertionError("no sample value for " + attribute.getName() + " of type " + c);
    }
}
