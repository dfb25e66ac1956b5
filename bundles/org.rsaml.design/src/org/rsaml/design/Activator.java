/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design;

import java.util.HashSet;
import java.util.Set;

import org.eclipse.core.runtime.Plugin;
import org.eclipse.sirius.business.api.componentization.ViewpointRegistry;
import org.eclipse.sirius.viewpoint.description.Viewpoint;
import org.osgi.framework.BundleContext;

/**
 * Registers the RsaML viewpoint (description/rsaml.odesign) with Sirius while the bundle is active, and lets its
 * diagrams show each finding once ({@link MarkerDecorations}).
 */
public class Activator extends Plugin {

    public static final String PLUGIN_ID = "org.rsaml.design";

    private static Activator plugin;

    private final Set<Viewpoint> viewpoints = new HashSet<>();

    /** Keeps Sirius's decoration of Validate's markers off RsaML's diagrams, whose own decorations show the findings. */
    private MarkerDecorations markerDecorations;

    @Override
    public void start(BundleContext context) throws Exception {
        super.start(context);
        plugin = this;
        viewpoints.addAll(ViewpointRegistry.getInstance().registerFromPlugin(PLUGIN_ID + "/description/rsaml.odesign"));
        try {
            markerDecorations = MarkerDecorations.install();
        } catch (RuntimeException e) {
            getLog().warn("RsaML: Sirius's decoration of Validate's markers could not be kept off RsaML's diagrams (findings may show twice)", e);
        }
        if (markerDecorations == null) {
            getLog().warn("RsaML: Sirius's decorator of Validate's markers was not found; after Diagram > Validate a finding may show twice");
        }
    }

    @Override
    public void stop(BundleContext context) throws Exception {
        if (markerDecorations != null) {
            markerDecorations.uninstall();
            markerDecorations = null;
        }
        for (Viewpoint viewpoint : viewpoints) {
            ViewpointRegistry.getInstance().disposeFromPlugin(viewpoint);
        }
        viewpoints.clear();
        plugin = null;
        super.stop(context);
    }

    public static Activator getDefault() {
        return plugin;
    }
}
