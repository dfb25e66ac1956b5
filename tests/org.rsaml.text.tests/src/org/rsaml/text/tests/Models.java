/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.rsaml.model.Architecture;
import org.rsaml.model.RsamlPackage;
import org.rsaml.tests.support.models.RandomModels;
import org.rsaml.tests.support.models.RandomModels.Shape;
import org.rsaml.tests.support.models.RandomModels.Values;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;

/** Reading text as the commands read it, and saying where two models differ. */
final class Models {

    private Models() {
    }

    /** The model of the text, read from a file {@code name} in {@code dir} through {@link ModelLoader}. */
    static LoadedModel read(Path dir, String name, String text) throws IOException, ModelLoadException {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return ModelLoader.load(file, name);
    }

    /**
     * Seeded random model {@code seed}: every concept, attributes set or not, odd names and numbers ({@link Values#ODD}),
     * references of every kind; names apart among one element's children, as the textual syntax needs to name references.
     */
    static Architecture random(long seed) {
        return (Architecture) RandomModels.model(RsamlPackage.eINSTANCE, RsamlPackage.Literals.ARCHITECTURE, seed, Values.ODD,
                Shape.NAMED_APART);
    }

    /** Null when the models are equal (EcoreUtil.equals), else the first difference found. */
    static String difference(Architecture expected, Architecture actual) {
        if (EcoreUtil.equals(expected, actual)) {
            return null;
        }
        List<String> found = new ArrayList<>();
        new EcoreUtil.EqualityHelper() {
            private static final long serialVersionUID = 1L;

            @Override
            protected boolean haveEqualFeature(EObject a, EObject b, EStructuralFeature feature) {
                boolean equal = super.haveEqualFeature(a, b, feature);
                if (!equal && found.isEmpty() && !(feature instanceof EReference r && r.isContainment())) {
                    found.add(EcoreUtil.getURI(a).fragment() + " " + feature.getName() + ": expected " + a.eGet(feature)
                            + " (set: " + a.eIsSet(feature) + "), was " + b.eGet(feature) + " (set: " + b.eIsSet(feature) + ")");
                }
                return equal;
            }
        }.equals(expected, actual);
        return found.isEmpty() ? "the models differ (no single feature found)" : found.get(0);
    }
}
