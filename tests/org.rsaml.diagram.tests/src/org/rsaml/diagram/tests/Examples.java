/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.tests;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.rsaml.diagram.DiagramView;
import org.rsaml.diagram.RsamlDiagrams;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/** The repository's example models (found through {@link TestRepository}) and their diagrams. */
final class Examples {

    private Examples() {
    }

    static List<String> names() throws IOException {
        try (Stream<Path> files = Files.list(TestRepository.root().resolve("examples"))) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted().toList();
        }
    }

    record Drawn(LoadedModel model, List<Finding> findings, String svg) {
    }

    static Drawn draw(String name, DiagramView view) throws Exception {
        LoadedModel model = ModelLoader.load(TestRepository.example(name), "examples/" + name);
        List<Finding> findings = RsamlModelValidator.validate(model);
        return new Drawn(model, findings, new RsamlDiagrams(view).svg(model.architecture(), findings));
    }
}
