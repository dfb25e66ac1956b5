/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.presentation.spec;

import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.OperationCanceledException;
import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.edit.ui.action.ValidateAction;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.RsamlModelValidator;

/**
 * Validate in the tree editor: the selected elements are checked against RsaML's rules (the OCL
 * invariants of rsaml.ecore and EMF's structural checks, as the command line checks them), and the
 * dialog and the Problems view show each finding as "RSA-08: Module 'resourceChecker' takes ...".
 */
public class RsamlValidateAction extends ValidateAction {

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
