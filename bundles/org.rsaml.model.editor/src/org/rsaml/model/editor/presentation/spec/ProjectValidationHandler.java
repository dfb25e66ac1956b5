/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.presentation.spec;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.Adapters;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import org.eclipse.core.runtime.IExecutableExtension;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.ui.handlers.HandlerUtil;
import org.rsaml.ide.RsamlProjects;

/**
 * <i>Configure &gt; Enable RsaML validation</i> and <i>Disable RsaML validation</i> on the selected
 * projects: adds or removes the RsaML nature (its builder validates the projects' .rsaml files and
 * marks the findings in the Problems view). Registered as {@code ...ProjectValidationHandler:enable}
 * and {@code :disable}.
 */
public class ProjectValidationHandler extends AbstractHandler implements IExecutableExtension {

    private boolean enable = true;

    @Override
    public void setInitializationData(IConfigurationElement config, String propertyName, Object data) {
        enable = !"disable".equals(data);
    }

    @Override
    public Object execute(ExecutionEvent event) throws ExecutionException {
        List<IProject> projects = new ArrayList<>();
        if (HandlerUtil.getCurrentSelection(event) instanceof IStructuredSelection selection) {
            for (Object element : selection) {
                IProject project = Adapters.adapt(element, IProject.class);
                if (project != null && project.isAccessible()) {
                    projects.add(project);
                }
            }
        }
        try {
            ResourcesPlugin.getWorkspace().run(monitor -> {
                for (IProject project : projects) {
                    if (enable) {
                        RsamlProjects.addNature(project, monitor);
                    } else {
                        RsamlProjects.removeNature(project, monitor);
                    }
                }
            }, null);
        } catch (CoreException e) {
            throw new ExecutionException("RsaML validation could not be turned " + (enable ? "on" : "off") + ": "
                    + e.getStatus().getMessage(), e);
        }
        return null;
    }
}
