/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Path;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.text.convert.ModelConverter;
import org.rsaml.validation.LoadedModel;

/**
 * The property behind conversion, on seeded random models: text written from a model reads back to
 * an equal model, and writing that model again gives the same text. {@code -Drsaml.text.randomModels=N}
 * checks N models (2,000 by default; the seed of a failure is in its message).
 */
class RandomModelsTest {

    @TempDir
    Path temp;

    @Test
    void randomModelsRoundTrip() throws Exception {
        int count = Integer.getInteger("rsaml.text.randomModels", 2000);
        for (long seed = 1; seed <= count; seed++) {
            Architecture model = Models.random(seed);
            // In a resource, as a loaded model is: the writer names references within it.
            Resource resource = RsamlStandaloneSetup.newResourceSet().createResource(URI.createFileURI(temp.resolve("m.rsaml").toString()));
            resource.getContents().add(model);
            String text = ModelConverter.toText(model);
            LoadedModel read = Models.read(temp, "random-" + seed + ".rsa", text);
            long s = seed;
            assertNull(Models.difference(model, read.architecture()), () -> "seed " + s + ": the text reads back to another model:\n" + text);
            assertEquals(text, ModelConverter.toText(read.architecture()), "seed " + seed + ": writing the model read back gives other text");
        }
    }
}
