/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import java.nio.file.Path;

import org.rsaml.tests.support.TestRepository;

/** Where the repository's files are, for tests running inside OSGi. */
final class Paths {
    private Paths() {
    }

    static Path root() {
        return TestRepository.root();
    }

    static Path example(String name) {
        return root().resolve("examples").resolve(name);
    }

    static Path resource(String name) {
        return root().resolve("tests/org.rsaml.validation.tests/resources").resolve(name);
    }
}
