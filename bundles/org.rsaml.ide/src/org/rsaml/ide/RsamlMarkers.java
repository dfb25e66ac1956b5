/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide;

import org.eclipse.emf.ecore.EValidator;
import org.rsaml.validation.Rules;

/**
 * The problem markers the RsaML builder puts on {@code .rsaml} files: one per finding, with the
 * standard severity, message ({@code "RSA-08: Module 'resourceChecker' takes ..."}) and line
 * number, plus the attributes below.
 */
public final class RsamlMarkers {

    /** The marker type; a problem marker and a text marker, persistent. */
    public static final String PROBLEM = "org.rsaml.ide.problem";

    /** The rule's stable id, e.g. {@code RSA-08}. */
    public static final String RULE_ID = "ruleId";

    /**
     * The element's URI ({@code platform:/resource/<project>/<path>#<fragment>}), under the key
     * EMF's marker helpers read, so that EMF editors can select the element.
     */
    public static final String URI = EValidator.URI_ATTRIBUTE;

    /** The element's URI fragment within its file. */
    public static final String URI_FRAGMENT = "uriFragment";

    /** The element's path by names, e.g. {@code robot/control/resourceChecker}. */
    public static final String QUALIFIED_NAME = "qualifiedName";

    /** The rule id of the marker put on a file that cannot be read as an RsaML model. */
    public static final String LOAD_ERROR_RULE_ID = Rules.STRUCTURE.id();

    private RsamlMarkers() {
    }
}
