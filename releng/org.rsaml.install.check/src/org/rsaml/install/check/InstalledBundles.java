/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.install.check;

import java.util.List;
import java.util.function.Predicate;

import org.osgi.framework.Bundle;
import org.osgi.framework.FrameworkUtil;

/** The bundles p2 installed, as the install checks see them. */
final class InstalledBundles {

    private InstalledBundles() {
    }

    /**
     * Adds one failure for each installed bundle whose symbolic name {@code which} accepts and that OSGi could not
     * resolve (it stays {@code INSTALLED}: a requirement is missing or in the wrong version).
     *
     * @return how many installed bundles {@code which} accepts
     */
    static int checkResolve(Predicate<String> which, List<String> failures) {
        int found = 0;
        for (Bundle bundle : FrameworkUtil.getBundle(InstalledBundles.class).getBundleContext().getBundles()) {
            if (which.test(bundle.getSymbolicName())) {
                found++;
                if (bundle.getState() == Bundle.INSTALLED) {
                    failures.add(bundle.getSymbolicName() + " " + bundle.getVersion() + " is installed but does not resolve");
                }
            }
        }
        return found;
    }
}
