/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.presentation.spec;

import java.util.Collection;
import java.util.List;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.jface.dialogs.ErrorDialog;
import org.rsaml.ide.RsamlProjects;
import org.rsaml.model.support.ArchitectureSkeleton;
import org.rsaml.model.editor.presentation.RsamlModelWizard;

/**
 * The new-model wizard: an RsaML file always holds one architecture, and it starts as the three-layer
 * skeleton of {@link ArchitectureSkeleton}, named after the file, so that it validates from the start.
 * Its project gets RsaML validation (the nature and builder), unless the user turned it off there.
 */
public class RsamlModelWizardSpec extends RsamlModelWizard {

    /** The only root the language admits (ModelLoader rejects any other). */
    @Override
    protected Collection<String> getInitialObjectNames() {
        if (initialObjectNames == null) {
            initialObjectNames = List.of(rsamlPackage.getArchitecture().getName());
        }
        return initialObjectNames;
    }

    @Override
    protected EObject createInitialModel() {
        return ArchitectureSkeleton.create(getModelFile().getFullPath().removeFileExtension().lastSegment());
    }

    @Override
    public boolean performFinish() {
        if (!super.performFinish()) {
            return false;
        }
        try {
            RsamlProjects.enableFor(getModelFile(), null);
        } catch (CoreException e) {
            // The model exists and is open; only the validation of its project could not be turned on.
            ErrorDialog.openError(getShell(), "RsaML validation", "RsaML validation could not be turned on for project '"
                    + getModelFile().getProject().getName() + "'; Configure > Enable RsaML validation tries again.", e.getStatus());
        }
        return true;
    }
}
