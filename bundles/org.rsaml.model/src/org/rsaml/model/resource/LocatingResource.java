/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;

/**
 * A resource that knows where in its file each element was written, whatever the syntax: the XMI
 * {@link RsamlResource} and the textual resource of {@code .rsa} files. Findings, load errors and
 * generation errors point with it.
 */
public interface LocatingResource extends Resource {

    /** Where the element begins in this resource's file; line and column are 0 for an element that was not read from it. */
    SourceLocation locate(EObject element);

    /** How many elements were read from the file (and so have a location). */
    int locatedElementCount();
}
