/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
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
import org.rsaml.tests.support.models.RandomModels;
import org.rsaml.tests.support.models.RandomModels.Shape;
import org.rsaml.tests.support.models.RandomModels.Values;

/**
 * Every concept and every attribute of RsaML survives a save to .rsaml and a reload: a seeded model of every concrete class
 * with every attribute and reference set ({@link RandomModels}, {@link Shape#EVERY_KIND}).
 */
class RoundTripTest {

    private static final long SEED = 20261127L;

    @TempDir
    Path dir;

    @Test
    void everyConceptAndAttributeSurvivesSaveAndReload() throws Exception {
        Architecture root = (Architecture) RandomModels.model(RsamlPackage.eINSTANCE, RsamlPackage.Literals.ARCHITECTURE, SEED,
                Values.PLAIN, Shape.EVERY_KIND);
        List<EObject> elements = new ArrayList<>();
        elements.add(root);
        root.eAllContents().forEachRemaining(elements::add);

        Set<String> concrete = new TreeSet<>();
        for (EClassifier c : RsamlPackage.eINSTANCE.getEClassifiers()) {
            if (c instanceof EClass e && !e.isAbstract() && !e.isInterface()) {
                concrete.add(e.getName());
            }
        }
        Set<String> created = new TreeSet<>();
        elements.forEach(e -> created.add(e.eClass().getName()));
        assertEquals(concrete, created, "the round-trip model must hold every concrete RsaML concept");
        List<String> unset = new ArrayList<>();
        for (EObject e : elements) {
            for (EStructuralFeature f : e.eClass().getEAllStructuralFeatures()) {
                boolean stored = f.isChangeable() && !f.isDerived() && !f.isTransient() && !(f instanceof EReference r && r.isContainer());
                if (stored && !e.eIsSet(f) && !(f instanceof EReference r && r.isContainment())) {
                    unset.add(e.eClass().getName() + "." + f.getName());
                }
            }
        }
        assertEquals(List.of(), unset, "every attribute and reference of every element must be set, to other than its default");

        URI uri = URI.createFileURI(dir.resolve("all-concepts.rsaml").toString());
        ResourceSet saveSet = new ResourceSetImpl();
        Resource saved = saveSet.createResource(uri);
        saved.getContents().add(root);
        saved.save(null);
        assertTrue(Files.size(dir.resolve("all-concepts.rsaml")) > 0, "the saved model file is not empty");

        Resource reloaded = new ResourceSetImpl().getResource(uri, true);
        assertTrue(reloaded.getErrors().isEmpty(), () -> "reload errors: " + reloaded.getErrors());
        EObject copy = reloaded.getContents().get(0);
        EcoreUtil.resolveAll(reloaded);
        assertTrue(EcoreUtil.UnresolvedProxyCrossReferencer.find(reloaded).isEmpty(), "every reference of the reloaded model resolves");
        assertTrue(new EcoreUtil.EqualityHelper().equals(root, copy),
                "the reloaded model must equal the saved one, attribute for attribute and reference for reference");

        // Container opposites are transient but restored on load, so rules can navigate upwards.
        Module module = ((Architecture) copy).getLayers().get(0).getModules().get(0);
        assertEquals(((Architecture) copy).getLayers().get(0), module.getLayer(), "a reloaded module knows its layer");
        assertEquals(module, module.getPorts().get(0).getModule(), "a reloaded port knows its module");
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
        assertEquals(2.0, layer.toMilliseconds(2000.0), 1e-12, "2000 us are 2 ms");
        layer.setTimeUnit(TimeUnit.S);
        assertEquals(1500.0, layer.toMilliseconds(1.5), 1e-9, "1.5 s are 1500 ms");
        layer.setTimeUnit(TimeUnit.NS);
        assertEquals(0.5, layer.toMilliseconds(500_000.0), 1e-12, "500000 ns are 0.5 ms");
        assertEquals(TimeUnit.MS, RsamlFactory.eINSTANCE.createModule().getTimeUnit(), "milliseconds by default");
    }
}
