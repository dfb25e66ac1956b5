/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.maven;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.codehaus.plexus.util.DirectoryScanner;

/** Paths as the build log shows them: relative to the project when inside it, with forward slashes. */
final class ProjectPaths {

    private ProjectPaths() {
    }

    static String relative(Path baseDirectory, Path path) {
        Path base = baseDirectory.toAbsolutePath().normalize();
        Path p = path.toAbsolutePath().normalize();
        return (p.startsWith(base) && !p.equals(base) ? base.relativize(p) : p).toString().replace('\\', '/');
    }

    /**
     * The models of a project that match {@code includes} and not {@code excludes} under
     * {@code modelDirectory}, sorted, relative to the project when inside it; the build output folder
     * is always left out (it holds copies).
     */
    static List<Path> models(File baseDirectory, File modelDirectory, File buildDirectory, List<String> includes, List<String> excludes) {
        DirectoryScanner scanner = new DirectoryScanner();
        scanner.setBasedir(modelDirectory);
        scanner.setIncludes(includes.toArray(String[]::new));
        List<String> allExcludes = new ArrayList<>(excludes);
        Path build = buildDirectory.toPath().toAbsolutePath().normalize();
        Path models = modelDirectory.toPath().toAbsolutePath().normalize();
        if (build.startsWith(models) && !build.equals(models)) {
            allExcludes.add(models.relativize(build).toString().replace('\\', '/') + "/**");
        }
        scanner.setExcludes(allExcludes.toArray(String[]::new));
        scanner.addDefaultExcludes();
        scanner.scan();
        String[] found = scanner.getIncludedFiles();
        Arrays.sort(found);
        Path base = baseDirectory.toPath().toAbsolutePath().normalize();
        List<Path> paths = new ArrayList<>();
        for (String file : found) {
            Path absolute = models.resolve(file);
            paths.add(absolute.startsWith(base) ? base.relativize(absolute) : absolute);
        }
        return paths;
    }
}
