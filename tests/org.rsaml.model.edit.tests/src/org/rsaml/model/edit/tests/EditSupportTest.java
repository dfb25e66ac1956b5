/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.edit.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.net.URL;
import java.security.MessageDigest;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.edit.provider.ComposedAdapterFactory;
import org.eclipse.emf.edit.provider.IEditingDomainItemProvider;
import org.eclipse.emf.edit.provider.IItemLabelProvider;
import org.eclipse.emf.edit.provider.IItemPropertySource;
import org.eclipse.emf.edit.provider.ITreeItemContentProvider;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Action;
import org.rsaml.model.DataType;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.RsamlPackage;

/** What an architect sees in a tree editor: labels that say what an element is, and an icon per concept. */
class EditSupportTest {

    private final ComposedAdapterFactory factory = new ComposedAdapterFactory(ComposedAdapterFactory.Descriptor.Registry.INSTANCE);

    private String label(EObject object) {
        IItemLabelProvider provider = (IItemLabelProvider) factory.adapt(object, IItemLabelProvider.class);
        assertNotNull(provider, "no label provider registered for " + object.eClass().getName());
        return provider.getText(object);
    }

    @Test
    void labelsSayWhatAnElementIsAndHowItIsTimed() {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Module module = f.createModule();
        module.setName("resourceChecker");
        module.setType(ElementType.REAL_TIME);
        module.setExecDuration(2.5);
        assertEquals("Module resourceChecker \u2014 real-time, 2.5 ms", label(module), "a module's label says its kind, name, type and duration");

        Action action = f.createRTAction();
        action.setName("instruction1");
        action.setType(ElementType.REAL_TIME);
        action.setExecType(ExecutionType.PERIODIC);
        action.setPeriod(20);
        action.setExecDuration(1);
        assertEquals("RT Action instruction1 \u2014 real-time, 1.0 ms every 20.0 ms", label(action), "an action's label says its duration and period");

        Layer layer = f.createLayer();
        layer.setName("control");
        layer.setLevel(1);
        layer.setMaxExecTime(2.0);
        assertEquals("Layer control \u2014 level 1, at most 2.0 ms a module", label(layer), "a layer's label says its level and per-module budget");

        EntryPort port = f.createEntryPort();
        port.setName("e0_prodExec");
        port.setDataType(DataType.ALPHANUMERIC);
        assertEquals("Entry Port e0_prodExec \u2014 alphanumeric", label(port), "a port's label says its kind and data type");

        var mission = f.createMission();
        mission.setName("patrol");
        assertEquals("Mission patrol", label(mission), "a mission's label says its kind and name");
    }

    @Test
    void everyConceptHasAnIconOfItsOwn() throws Exception {
        Map<String, String> digests = new HashMap<>();
        for (EClassifier classifier : RsamlPackage.eINSTANCE.getEClassifiers()) {
            if (classifier instanceof EClass eClass && !eClass.isAbstract() && !eClass.isInterface()) {
                EObject object = EcoreUtil.create(eClass);
                IItemLabelProvider provider = (IItemLabelProvider) factory.adapt(object, IItemLabelProvider.class);
                Object image = provider.getImage(object);
                URL url = assertInstanceOf(URL.class, image, eClass.getName() + " has no icon");
                byte[] bytes;
                try (InputStream in = url.openStream()) {
                    bytes = in.readAllBytes();
                }
                String digest = HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
                String previous = digests.put(digest, eClass.getName());
                assertEquals(null, previous, eClass.getName() + " shares its icon with " + previous);
            }
        }
    }

    /** The tree editor and the Properties view ask the same factory for contents and properties. */
    @Test
    void treeContentsAndPropertiesStayTheGeneratedOnes() {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Layer layer = f.createLayer();
        layer.setName("control");
        Module module = f.createModule();
        module.setName("resourceChecker");
        layer.getModules().add(module);
        ITreeItemContentProvider tree = assertInstanceOf(ITreeItemContentProvider.class,
                factory.adapt(layer, ITreeItemContentProvider.class), "the tree editor gets a layer's children from the item provider");
        assertEquals(List.of(module), List.copyOf(tree.getChildren(layer)), "a layer's children in the tree are its modules");
        assertEquals("Module resourceChecker \u2014 simple", label((EObject) tree.getChildren(layer).iterator().next()), "a module without a type is labelled simple in the tree");
        IItemPropertySource properties = assertInstanceOf(IItemPropertySource.class, factory.adapt(module, IItemPropertySource.class), "the Properties view gets a module's properties from the item provider");
        assertTrue(properties.getPropertyDescriptors(module).stream().anyMatch(d -> "name".equals(d.getId(module))),
                "the module's name is editable in the Properties view");
        assertInstanceOf(IEditingDomainItemProvider.class, factory.adapt(module, IEditingDomainItemProvider.class), "the editing domain gets commands for a module from the item provider");
    }
}
