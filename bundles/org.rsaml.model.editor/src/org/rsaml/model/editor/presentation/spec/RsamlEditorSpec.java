/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.presentation.spec;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.IEditorSite;
import org.eclipse.ui.IFileEditorInput;
import org.eclipse.ui.PartInitException;
import org.rsaml.ide.RsamlProjects;
import org.rsaml.model.edit.provider.spec.RsamlItemProviderAdapterFactorySpec;
import org.rsaml.model.editor.presentation.RsamlEditor;
import org.rsaml.model.resource.RsamlResource;

/**
 * The tree editor, with RsaML's labels ("Module resourceChecker — real-time, 2.5 ms") and the edit
 * bundle's icons. Opening a model turns RsaML validation on for its project (the builder then marks
 * the findings on every save), unless the user turned it off there. A save keeps the file's
 * comments ({@link RsamlResource}) and re-reads where each element now stands, so that Validate
 * marks the lines the builder marks.
 */
public class RsamlEditorSpec extends RsamlEditor {

    /** The family of the jobs that turn validation on, for whoever waits for them (the tests). */
    public static final Object ENABLE_VALIDATION_FAMILY = RsamlProjects.NATURE_ID;

    /** The generated editor adds the generated item providers; RsaML's go in front of them. */
    @Override
    protected void initializeEditingDomain() {
        super.initializeEditingDomain();
        adapterFactory.insertAdapterFactory(new RsamlItemProviderAdapterFactorySpec());
    }

    @Override
    public void init(IEditorSite site, IEditorInput editorInput) {
        super.init(site, editorInput);
        if (editorInput instanceof IFileEditorInput input) {
            enableValidation(input.getFile());
        }
    }

    /** In a job: the project description cannot change while the workspace is locked (a build, a save). */
    private static void enableValidation(IFile file) {
        IProject project = file.getProject();
        if (!RsamlProjects.isModelFile(file) || RsamlProjects.hasNature(project) || RsamlProjects.isOptedOut(project)) {
            return;
        }
        WorkspaceJob job = new WorkspaceJob("Turning on RsaML validation for " + project.getName()) {
            @Override
            public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
                RsamlProjects.enableFor(file, monitor);
                return Status.OK_STATUS;
            }

            @Override
            public boolean belongsTo(Object family) {
                return family == ENABLE_VALIDATION_FAMILY;
            }
        };
        // Changing natures locks the workspace root (natures may concern other projects).
        job.setRule(ResourcesPlugin.getWorkspace().getRoot());
        job.setSystem(true);
        job.schedule();
    }

    @Override
    public void doSave(IProgressMonitor progressMonitor) {
        super.doSave(progressMonitor);
        if (isDirty()) {
            return; // the save failed: the positions of the file as it was stay right
        }
        for (Resource resource : editingDomain.getResourceSet().getResources()) {
            if (resource instanceof RsamlResource rsaml && rsaml.isLoaded() && rsaml.getErrors().isEmpty()) {
                rsaml.refreshLocations();
            }
        }
    }
}
