/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.presentation.spec;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.OperationCanceledException;
import org.eclipse.emf.common.EMFPlugin;
import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.edit.ui.action.ValidateAction;
import org.rsaml.ide.RsamlMarkers;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.RsamlModelValidator;

/**
 * Validate in the tree editor: the selected elements are checked against RsaML's rules (the OCL
 * invariants of rsaml.ecore and EMF's structural checks, as the command line checks them), and the
 * dialog and the Problems view show each finding as "RSA-08: Module 'resourceChecker' takes ...".
 * Its markers are of the RsaML builder's type, so they replace the builder's markers of the file
 * instead of listing every finding a second time.
 */
public class RsamlValidateAction extends ValidateAction {

    public RsamlValidateAction() {
        eclipseResourcesUtil = EMFPlugin.IS_RESOURCES_BUNDLE_AVAILABLE ? new EclipseResourcesUtil() {
            @Override
            protected String getMarkerID() {
                return RsamlMarkers.PROBLEM;
            }

            @Override
            protected void createMarkers(IResource resource, Diagnostic diagnostic, Diagnostic parentDiagnostic)
                    throws CoreException {
                if (resource instanceof IFile file && file.exists()) {
                    RsamlMarkers.create(file, diagnostic);
                }
            }
        } : null;
    }

    @Override
    protected Diagnostic validate(IProgressMonitor progressMonitor) {
        progressMonitor.beginTask("", selectedObjects.size());
        // The top diagnostic names the selection, so that the action clears the old markers of its resources.
        BasicDiagnostic result = new BasicDiagnostic(Diagnostic.OK, "org.rsaml.model.editor", 0,
                "RsaML rules on " + describe(), selectedObjects.toArray());
        synchronized (domain.getResourceSet()) {
            for (EObject selected : selectedObjects) {
                if (progressMonitor.isCanceled()) {
                    throw new OperationCanceledException();
                }
                progressMonitor.setTaskName("Checking " + RsamlLabels.qualifiedName(selected));
                result.addAll(RsamlModelValidator.diagnose(selected));
                progressMonitor.worked(1);
            }
        }
        return result;
    }

    private String describe() {
        return selectedObjects.size() == 1 ? RsamlLabels.qualifiedName(selectedObjects.get(0))
                : selectedObjects.size() + " elements";
    }
}
