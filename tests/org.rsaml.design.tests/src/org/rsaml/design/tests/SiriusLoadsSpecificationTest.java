/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.common.util.WrappedException;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.sirius.business.api.componentization.ViewpointRegistry;
import org.eclipse.sirius.business.internal.migration.description.VSMMigrationService;
import org.eclipse.sirius.business.internal.migration.description.VSMVersionSAXParser;
import org.eclipse.sirius.viewpoint.description.Group;
import org.eclipse.sirius.viewpoint.description.RepresentationDescription;
import org.eclipse.sirius.viewpoint.description.Viewpoint;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.Version;

/**
 * Sirius itself reads rsaml.odesign: through its own resource factory (the one a user's Eclipse uses for
 * {@code .odesign} files) and its migration service, which refuses a specification written by a later
 * Sirius and silently rewrites one written by an earlier one. Either would mean a user gets no diagram, or
 * one that is not the specification in the repository; both fail here.
 */
class SiriusLoadsSpecificationTest {

    private static final URI SPECIFICATION = URI.createPlatformPluginURI("org.rsaml.design/description/rsaml.odesign", true);

    /** What Sirius would object to in the specification at {@code uri}; empty when it loads it as written. */
    private static List<String> problems(URI uri) {
        List<String> problems = new ArrayList<>();
        String written = new VSMVersionSAXParser(uri).getVersion(new NullProgressMonitor());
        Version last = VSMMigrationService.getInstance().getLastMigrationVersion();
        if (written == null) {
            problems.add("no version attribute");
        } else if (VSMMigrationService.getInstance().isMigrationNeeded(Version.parseVersion(written))) {
            problems.add("Sirius would migrate it: version " + written + " is older than " + last);
        }
        try {
            Resource resource = new ResourceSetImpl().getResource(uri, true);
            resource.getErrors().forEach(e -> problems.add("error: " + e.getMessage()));
            resource.getWarnings().forEach(e -> problems.add("warning: " + e.getMessage()));
            if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof Group)) {
                problems.add("not a Sirius specification: " + resource.getContents());
            }
        } catch (WrappedException | IllegalStateException e) {
            problems.add("refused: " + e.getMessage());
        }
        return problems;
    }

    @Test
    void siriusLoadsTheSpecificationAsWrittenWithoutMigratingIt() {
        assertEquals(List.of(), problems(SPECIFICATION), "rsaml.odesign as Sirius 7.6 reads it");
        assertEquals(VSMMigrationService.getInstance().getLastMigrationVersion(),
                Version.parseVersion(new VSMVersionSAXParser(SPECIFICATION).getVersion(new NullProgressMonitor())),
                "rsaml.odesign carries the version of the last Sirius migration it is written for");
    }

    /** The check above can fail: a specification from a later Sirius is refused, one from an earlier Sirius is migrated. */
    @Test
    void aSpecificationFromAnotherSiriusReleaseIsReported(@TempDir Path dir) throws Exception {
        String text = Files.readString(Repository.file(Repository.ODESIGN));
        String written = new VSMVersionSAXParser(SPECIFICATION).getVersion(new NullProgressMonitor());

        Path later = dir.resolve("later.odesign");
        Files.writeString(later, text.replace("version=\"" + written + "\"", "version=\"99.0.0.209901010000\""));
        List<String> refused = problems(URI.createFileURI(later.toString()));
        assertTrue(refused.stream().anyMatch(p -> p.contains("more recent Sirius release")), "a later Sirius's specification is refused: " + refused);

        Path earlier = dir.resolve("earlier.odesign");
        Files.writeString(earlier, text.replace("version=\"" + written + "\"", "version=\"11.0.0.201604141600\""));
        List<String> migrated = problems(URI.createFileURI(earlier.toString()));
        assertTrue(migrated.stream().anyMatch(p -> p.startsWith("Sirius would migrate it")), "an earlier Sirius's specification is migrated: " + migrated);
    }

    @Test
    void theRsamlViewpointIsRegisteredWithItsTwoDiagrams() {
        List<Viewpoint> rsaml = ViewpointRegistry.getInstance().getViewpoints().stream()
                .filter(v -> "RsaML".equals(v.getName())).toList();
        assertEquals(1, rsaml.size(), "one RsaML viewpoint in Sirius's registry");
        assertEquals(SPECIFICATION.toString(), rsaml.get(0).eResource().getURI().toString(), "registered from the design bundle");
        assertEquals(List.of("Architecture", "Missions"),
                rsaml.get(0).getOwnedRepresentations().stream().map(RepresentationDescription::getName).toList(),
                "Sirius offers an Architecture and a Missions diagram");
        assertEquals("rsaml", rsaml.get(0).getModelFileExtension(), "Sirius applies the viewpoint to .rsaml files");
    }
}
