/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide;

import java.util.Arrays;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IProjectDescription;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.QualifiedName;
import org.rsaml.model.resource.ModelFormats;

/**
 * Turns RsaML workspace validation on and off for a project. A project with the RsaML nature has
 * the RsaML builder, which validates its {@code .rsaml} and textual {@code .rsa} files and reports findings as
 * {@link RsamlMarkers#PROBLEM} markers.
 */
public final class RsamlProjects {

    public static final String NATURE_ID = "org.rsaml.ide.rsamlNature";
    public static final String BUILDER_ID = "org.rsaml.ide.rsamlBuilder";

    /** Kept in the workspace's metadata, not in the project: a user's choice on this machine. */
    private static final QualifiedName VALIDATION = new QualifiedName("org.rsaml.ide", "validation");
    private static final String OFF = "off";

    private RsamlProjects() {
    }

    /** Whether {@code project} is open and has the RsaML nature. */
    public static boolean hasNature(IProject project) {
        try {
            return project.isAccessible() && project.hasNature(NATURE_ID);
        } catch (CoreException e) {
            return false; // closed or deleted meanwhile: it has no nature we can use
        }
    }

    /**
     * Whether the user turned RsaML validation off for the project ({@link #removeNature}), so that
     * opening or creating a model there does not turn it on again; {@link #addNature} forgets it.
     */
    public static boolean isOptedOut(IProject project) {
        try {
            return project.isAccessible() && OFF.equals(project.getPersistentProperty(VALIDATION));
        } catch (CoreException e) {
            return false;
        }
    }

    /**
     * Turns RsaML validation on for the project of a model the user creates or opens, unless the
     * project has it or the user turned it off there before. The caller holds the workspace
     * root's scheduling rule or none (it changes the project's natures).
     *
     * @return whether the nature was added now
     */
    public static boolean enableFor(IFile model, IProgressMonitor monitor) throws CoreException {
        IProject project = model.getProject();
        if (!isModelFile(model) || project == null || !project.isAccessible() || hasNature(project) || isOptedOut(project)) {
            return false;
        }
        addNature(project, monitor);
        return true;
    }

    /** Adds the RsaML nature (and so its builder) to an open project; does nothing if it is there. */
    public static void addNature(IProject project, IProgressMonitor monitor) throws CoreException {
        project.setPersistentProperty(VALIDATION, null);
        if (hasNature(project)) {
            return;
        }
        IProjectDescription description = project.getDescription();
        String[] natures = description.getNatureIds();
        String[] more = Arrays.copyOf(natures, natures.length + 1);
        more[natures.length] = NATURE_ID;
        description.setNatureIds(more);
        project.setDescription(description, monitor);
    }

    /**
     * Removes the RsaML nature, its builder and every RsaML problem marker of the project, and
     * remembers that the user wants it so ({@link #isOptedOut}).
     */
    public static void removeNature(IProject project, IProgressMonitor monitor) throws CoreException {
        if (!hasNature(project)) {
            return;
        }
        project.setPersistentProperty(VALIDATION, OFF);
        IProjectDescription description = project.getDescription();
        description.setNatureIds(Arrays.stream(description.getNatureIds()).filter(id -> !NATURE_ID.equals(id))
                .toArray(String[]::new));
        project.setDescription(description, monitor);
    }

    /** Whether {@code resource} is an RsaML model file ({@code .rsaml} or textual {@code .rsa}), judged by its extension. */
    public static boolean isModelFile(IResource resource) {
        return resource instanceof IFile && ModelFormats.isModelFile(resource.getName());
    }
}
