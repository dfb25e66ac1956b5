/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.nio.file.Path;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.rsaml.model.Architecture;
import org.rsaml.model.resource.LocatingResource;
import org.rsaml.model.resource.SourceLocation;

/** A loaded model (.rsaml or .rsa) that knows where in its file each element starts. */
public final class LoadedModel {

    private final LocatingResource resource;
    private final String file;
    private final Path path;

    LoadedModel(LocatingResource resource, String file, Path path) {
        this.resource = resource;
        this.file = file;
        this.path = path;
    }

    /**
     * A model already in a resource, such as a textual model an editor or language server holds; it is
     * judged and located as one {@link ModelLoader} read. {@code path} may be null when it has no file.
     */
    public static LoadedModel of(LocatingResource resource, String file, Path path) {
        return new LoadedModel(resource, file, path);
    }

    public Resource resource() {
        return resource;
    }

    public Architecture architecture() {
        return (Architecture) resource.getContents().get(0);
    }

    /** The file as the user named it. */
    public String file() {
        return file;
    }

    /** The file that was read. */
    public Path path() {
        return path;
    }

    /** Number of elements whose position is known (every element read from the file). */
    public int elementCount() {
        return resource.locatedElementCount();
    }

    /** Where the element's start tag begins, in the file as the user named it; line and column 0 when not read from it. */
    public SourceLocation location(EObject element) {
        return resource.locate(element).inFile(file);
    }

    /** The 1-based line and column where the element's start tag begins, or {0, 0} when it was not read from the file. */
    public int[] locate(EObject element) {
        SourceLocation at = resource.locate(element);
        return new int[] { at.line(), at.column() };
    }
}
