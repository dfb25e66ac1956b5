/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EValidator;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rule;
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

    /**
     * Puts on {@code file} the marker of one finding of {@link RsamlModelValidator#diagnose}, with
     * the builder's type and attributes (but no line: an edited model has no position in the file
     * yet). The tree editor's Validate writes its markers through this, so that the Problems view
     * lists each finding once, whether the builder or the editor ran last.
     */
    public static IMarker create(IFile file, Diagnostic finding) throws CoreException {
        Map<String, Object> attributes = new HashMap<>();
        attributes.put(IMarker.SEVERITY, finding.getSeverity() >= Diagnostic.ERROR ? IMarker.SEVERITY_ERROR
                : finding.getSeverity() >= Diagnostic.WARNING ? IMarker.SEVERITY_WARNING : IMarker.SEVERITY_INFO);
        attributes.put(IMarker.MESSAGE, finding.getMessage());
        List<?> data = finding.getData();
        if (data.size() > 1 && data.get(1) instanceof Rule rule) {
            attributes.put(RULE_ID, rule.id());
        }
        if (!data.isEmpty() && data.get(0) instanceof EObject element) {
            attributes.put(QUALIFIED_NAME, RsamlLabels.qualifiedName(element));
            if (element.eResource() != null) {
                String fragment = element.eResource().getURIFragment(element);
                attributes.put(URI_FRAGMENT, fragment);
                attributes.put(URI, org.eclipse.emf.common.util.URI.createPlatformResourceURI(file.getFullPath().toString(), true)
                        .appendFragment(fragment).toString());
            }
        }
        return file.createMarker(PROBLEM, attributes);
    }
}
