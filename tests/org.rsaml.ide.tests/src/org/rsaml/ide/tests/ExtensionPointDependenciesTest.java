/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.TestRepository;

/** Every plugin.xml of bundles/ uses only extension points of bundles its manifest requires. */
class ExtensionPointDependenciesTest {

    @Test
    void everyBundleRequiresTheBundlesDeclaringTheExtensionPointsItUses() throws Exception {
        Path root = TestRepository.root();
        List<Path> bundles;
        try (Stream<Path> dirs = Files.list(root.resolve("bundles"))) {
            bundles = dirs.filter(d -> Files.isRegularFile(d.resolve("plugin.xml"))).sorted().collect(Collectors.toList());
        }
        List<String> names = bundles.stream().map(d -> d.getFileName().toString()).collect(Collectors.toList());
        assertTrue(names.containsAll(List.of("org.rsaml.ide", "org.rsaml.model", "org.rsaml.model.edit")),
                "the check must see the bundles with a plugin.xml, saw " + names);
        List<String> problems = new ArrayList<>();
        for (Path bundle : bundles) {
            problems.addAll(ExtensionPointDependencies.check(bundle, root));
        }
        assertEquals(List.of(), problems, "every bundle requires the bundles whose extension points its plugin.xml uses");
    }

    @Test
    void aPointOfABundleThatIsNotRequiredIsReportedWithFilePointAndBundle() throws Exception {
        Path base = TestRepository.resource("org.rsaml.ide.tests", "extension-points");
        assertEquals(List.of(
                "missing-require/plugin.xml: extension point 'org.eclipse.core.resources.markers' belongs to bundle"
                        + " 'org.eclipse.core.resources', which missing-require/META-INF/MANIFEST.MF does not require;"
                        + " add 'org.eclipse.core.resources' to its Require-Bundle",
                "missing-require/plugin.xml: extension point 'org.eclipse.ui.editors' belongs to bundle"
                        + " 'org.eclipse.ui', which missing-require/META-INF/MANIFEST.MF does not require;"
                        + " add 'org.eclipse.ui' to its Require-Bundle"),
                ExtensionPointDependencies.check(base.resolve("missing-require"), base),
                "each point of a bundle not required is named with the file, the bundle and the fix");
    }

    @Test
    void pointsOfRequiredAbsentAndOwnBundlesPass() throws Exception {
        Path base = TestRepository.resource("org.rsaml.ide.tests", "extension-points");
        assertEquals(List.of(), ExtensionPointDependencies.check(base.resolve("complete"), base),
                "points of required, absent and own bundles are no problem");
    }

    @Test
    void theRegistryNamesTheDeclaringBundleWhereTheIdPrefixWouldMislead() {
        // Declared by org.eclipse.equinox.registry under the org.eclipse.core.runtime namespace.
        assertEquals("org.eclipse.equinox.registry",
                ExtensionPointDependencies.declaringBundle("org.eclipse.core.runtime.adapters", "x", Set.of()),
                "the registry, not the id's prefix, names the bundle that declares the adapters point");
        assertEquals("org.eclipse.core.resources",
                ExtensionPointDependencies.declaringBundle("org.eclipse.core.resources.markers", "x", Set.of()),
                "the registry names the bundle that declares the markers point");
        // Not in the test runtime: the id's prefix.
        assertEquals("org.eclipse.sirius",
                ExtensionPointDependencies.declaringBundle("org.eclipse.sirius.componentization", "x", Set.of()),
                "a point not in the runtime belongs to the bundle its id's prefix names");
        assertEquals("x", ExtensionPointDependencies.declaringBundle("templates", "x", Set.of()),
                "a point without a prefix is the bundle's own");
    }
}
