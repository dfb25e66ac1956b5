/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.nio.file.Path;

/** Paths as the build log shows them: relative to the project when inside it, with forward slashes. */
final class ProjectPaths {

    private ProjectPaths() {
    }

    static String relative(Path baseDirectory, Path path) {
        Path base = baseDirectory.toAbsolutePath().normalize();
        Path p = path.toAbsolutePath().normalize();
        return (p.startsWith(base) && !p.equals(base) ? base.relativize(p) : p).toString().replace('\\', '/');
    }
}
