/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.install.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.content.IContentType;
import org.eclipse.equinox.app.IApplication;
import org.eclipse.equinox.app.IApplicationContext;
import org.osgi.framework.Bundle;

/**
 * Checks, in an Eclipse into which RsaML's editors feature was installed with p2, what a user relies on to open a
 * {@code .rsaml} file and draw its diagrams: every installed bundle resolves (EMF UI, Sirius and RsaML's editors
 * among them), {@code .rsaml} files have RsaML's content type, an editor is registered for that content type and its
 * class loads (its bundle is wired to the Eclipse UI and EMF UI), and Sirius registers RsaML's viewpoint. No
 * workbench is started, but Sirius's diagram UI, whose VSM migrations Sirius consults, initialises SWT: it needs a
 * display (Xvfb in CI). Exit code 0 when everything holds, 1 otherwise (each
 * failed check printed on standard error).
 */
public class EditorsRegisteredApplication implements IApplication {

    static final String CONTENT_TYPE = "org.rsaml.model.rsaml";
    static final String EDITORS = "org.eclipse.ui.editors";
    static final String VIEWPOINTS = "org.eclipse.sirius.componentization";
    static final String VIEWPOINT = "RsaML";

    private final List<String> failures = new ArrayList<>();

    @Override
    public Object start(IApplicationContext context) throws Exception {
        checkEveryBundleResolves();
        checkContentType();
        checkEditor();
        checkViewpoint();
        failures.forEach(f -> System.err.println("INSTALL CHECK FAILED: " + f));
        return failures.isEmpty() ? IApplication.EXIT_OK : Integer.valueOf(1);
    }

    private void checkEveryBundleResolves() {
        int installed = InstalledBundles.checkResolve(id -> true, failures);
        System.out.println("bundles installed: " + installed);
        for (String id : List.of("org.rsaml.model.editor", "org.rsaml.design", "org.eclipse.emf.edit.ui", "org.eclipse.sirius",
                "org.eclipse.sirius.diagram.ui")) {
            if (Platform.getBundle(id) == null) {
                failures.add(id + " is not installed");
            }
        }
    }

    private void checkContentType() {
        IContentType type = Platform.getContentTypeManager().findContentTypeFor("model.rsaml");
        if (type == null || !CONTENT_TYPE.equals(type.getId())) {
            failures.add("a .rsaml file has content type " + (type == null ? "none" : type.getId()) + ", not " + CONTENT_TYPE);
        }
    }

    private void checkEditor() {
        List<String> editors = new ArrayList<>();
        for (IConfigurationElement editor : Platform.getExtensionRegistry().getConfigurationElementsFor(EDITORS)) {
            for (IConfigurationElement binding : editor.getChildren("contentTypeBinding")) {
                if (CONTENT_TYPE.equals(binding.getAttribute("contentTypeId"))) {
                    editors.add(editor.getAttribute("id"));
                    loads(editor.getContributor().getName(), editor.getAttribute("class"), "the .rsaml editor");
                }
            }
        }
        System.out.println("editors of " + CONTENT_TYPE + ": " + editors);
        if (editors.isEmpty()) {
            failures.add("no editor (" + EDITORS + ") is registered for content type " + CONTENT_TYPE);
        }
    }

    /**
     * The viewpoint as Sirius sees it: the component RsaML contributes to {@code org.eclipse.sirius.componentization}
     * is started, which registers its specification, and Sirius's {@code ViewpointRegistry} then holds a viewpoint
     * named RsaML (one Sirius loaded and did not refuse). Sirius is reached by reflection: this check bundle also runs
     * in Eclipses without Sirius (the runtime's install test), so it cannot require it.
     */
    private void checkViewpoint() throws Exception {
        List<String> components = new ArrayList<>();
        for (IConfigurationElement component : Platform.getExtensionRegistry().getConfigurationElementsFor(VIEWPOINTS)) {
            String contributor = component.getContributor().getName();
            if (contributor.startsWith("org.rsaml.")) {
                components.add(contributor);
                loads(contributor, component.getAttribute("class"), "the viewpoint component");
                Platform.getBundle(contributor).start(Bundle.START_TRANSIENT);
            }
        }
        System.out.println("RsaML components contributed to Sirius: " + components);
        if (components.isEmpty()) {
            failures.add("no RsaML component is contributed to Sirius (" + VIEWPOINTS + ")");
            return;
        }
        Class<?> registry = Platform.getBundle("org.eclipse.sirius")
                .loadClass("org.eclipse.sirius.business.api.componentization.ViewpointRegistry");
        Object instance = registry.getMethod("getInstance").invoke(null);
        List<String> viewpoints = new ArrayList<>();
        for (Object viewpoint : (Set<?>) registry.getMethod("getViewpoints").invoke(instance)) {
            viewpoints.add(String.valueOf(viewpoint.getClass().getMethod("getName").invoke(viewpoint)));
        }
        System.out.println("viewpoints registered in Sirius: " + viewpoints);
        if (!viewpoints.contains(VIEWPOINT)) {
            failures.add("Sirius's ViewpointRegistry has no viewpoint " + VIEWPOINT + " (it has " + viewpoints
                    + "): Sirius refused or did not load RsaML's specification (see the log above)");
        }
    }

    private void loads(String bundleId, String className, String what) {
        try {
            Platform.getBundle(bundleId).loadClass(className);
        } catch (ClassNotFoundException | LinkageError | RuntimeException e) {
            failures.add(what + " " + className + " of " + bundleId + " does not load: " + e);
        }
    }

    @Override
    public void stop() {
        // Runs to completion.
    }
}
