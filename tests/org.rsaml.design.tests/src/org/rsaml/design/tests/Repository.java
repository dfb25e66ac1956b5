/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Assumptions;
import org.rsaml.tests.support.TestRepository;

/** Where the files under test are: the repository (system property {@code rsaml.root}) and Sirius's metamodels beside it. */
final class Repository {

    static final String DESIGN = "bundles/org.rsaml.design/";
    static final String ODESIGN = DESIGN + "description/rsaml.odesign";
    static final String ECORE = "bundles/org.rsaml.model/model/rsaml.ecore";

    private static boolean skipAnnounced;

    private Repository() {
    }

    static Path root() {
        return TestRepository.root();
    }

    static Path file(String path) {
        return root().resolve(path);
    }

    static Path resource(String name) {
        return root().resolve("tests/org.rsaml.design.tests/resources").resolve(name);
    }

    /**
     * Sirius's viewpoint.ecore and diagram.ecore: {@code rsaml.sirius.metamodels} if set, else
     * {@code shared/reference/sirius} beside the repository. A clone without them skips the tests
     * that need them, and says so.
     */
    static Path siriusMetamodels() {
        String configured = System.getProperty("rsaml.sirius.metamodels");
        Path folder = configured != null ? Path.of(configured)
                : root().resolve("../shared/reference/sirius").normalize();
        boolean present = Files.isRegularFile(folder.resolve("viewpoint.ecore")) && Files.isRegularFile(folder.resolve("diagram.ecore"));
        String why = "Sirius's metamodels (viewpoint.ecore, diagram.ecore) are not in " + folder
                + ": rsaml.odesign is not checked. Set -Drsaml.sirius.metamodels=<folder> to check it.";
        if (!present && !skipAnnounced) {
            // The test report only says "skipped"; the reason belongs in the build log too, once.
            skipAnnounced = true;
            System.out.println("SKIPPED: " + why);
        }
        Assumptions.assumeTrue(present, why);
        return folder;
    }
}
