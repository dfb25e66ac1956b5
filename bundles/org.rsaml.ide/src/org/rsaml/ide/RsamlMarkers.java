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
import org.rsaml.model.resource.LocatingResource;
import org.rsaml.model.resource.SourceLocation;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Rule;
import org.rsaml.validation.Rules;
import org.rsaml.validation.Severity;

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
     * Puts on {@code file} the marker of one finding: the builder's and the tree editor's Validate
     * markers are all written here, so the Problems view shows a finding alike (type, message, line,
     * attributes) whichever of them ran last.
     */
    public static IMarker create(IFile file, Finding finding) throws CoreException {
        Map<String, Object> attributes = new HashMap<>();
        attributes.put(IMarker.SEVERITY, switch (finding.severity()) {
            case ERROR -> IMarker.SEVERITY_ERROR;
            case WARNING -> IMarker.SEVERITY_WARNING;
            case INFO -> IMarker.SEVERITY_INFO;
        });
        attributes.put(IMarker.MESSAGE, finding.text());
        if (finding.line() > 0) {
            attributes.put(IMarker.LINE_NUMBER, finding.line());
        }
        attributes.put(RULE_ID, finding.ruleId());
        attributes.put(QUALIFIED_NAME, finding.qualifiedName());
        if (!finding.uriFragment().isEmpty()) {
            attributes.put(URI_FRAGMENT, finding.uriFragment());
            attributes.put(URI, org.eclipse.emf.common.util.URI.createPlatformResourceURI(file.getFullPath().toString(), true)
                    .appendFragment(finding.uriFragment()).toString());
        }
        return file.createMarker(PROBLEM, attributes);
    }

    /**
     * Puts on {@code file} the marker of one finding of {@link RsamlModelValidator#diagnose} (the tree
     * editor's Validate), located where the element's start tag was when its file was last read or
     * saved ({@link LocatingResource#locate}, for .rsaml and .rsa files alike); an element added since has no line yet.
     */
    public static IMarker create(IFile file, Diagnostic finding) throws CoreException {
        return create(file, toFinding(file, finding));
    }

    /** One child of {@link RsamlModelValidator#diagnose} as the builder reports it. */
    public static Finding toFinding(IFile file, Diagnostic finding) {
        List<?> data = finding.getData();
        Rule rule = data.size() > 1 && data.get(1) instanceof Rule r ? r : Rules.STRUCTURE;
        String message = data.size() > 2 && data.get(2) instanceof String m ? m : finding.getMessage();
        Severity severity = finding.getSeverity() >= Diagnostic.ERROR ? Severity.ERROR
                : finding.getSeverity() >= Diagnostic.WARNING ? Severity.WARNING : Severity.INFO;
        String qualifiedName = "";
        String fragment = "";
        int line = 0;
        int column = 0;
        if (!data.isEmpty() && data.get(0) instanceof EObject element) {
            qualifiedName = RsamlLabels.qualifiedName(element);
            if (element.eResource() != null) {
                fragment = element.eResource().getURIFragment(element);
            }
            if (element.eResource() instanceof LocatingResource resource) {
                SourceLocation at = resource.locate(element);
                line = at.line();
                column = at.column();
            }
        }
        return new Finding(rule, severity, message, qualifiedName, fragment, file.getFullPath().toString(), line, column);
    }
}
