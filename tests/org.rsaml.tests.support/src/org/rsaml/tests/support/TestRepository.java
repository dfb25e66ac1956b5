/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.tests.support;

import java.nio.file.Path;

/**
 * Where the repository's files are, for every test (inside OSGi or on a plain class path): the
 * build passes the root as the system property {@code rsaml.root}; a test started from its own
 * module directory (in an IDE) finds it two levels up.
 */
public final class TestRepository {

    private TestRepository() {
    }

    /** The repository root: {@code examples/}, {@code bundles/}, {@code tests/} are below it. */
    public static Path root() {
        return Path.of(System.getProperty("rsaml.root", "../..")).toAbsolutePath().normalize();
    }

    /** A model of {@code examples/}. */
    public static Path example(String name) {
        return root().resolve("examples").resolve(name);
    }

    /** A file under {@code tests/<testBundle>/resources/}. */
    public static Path resource(String testBundle, String name) {
        return root().resolve("tests").resolve(testBundle).resolve("resources").resolve(name);
    }
}
