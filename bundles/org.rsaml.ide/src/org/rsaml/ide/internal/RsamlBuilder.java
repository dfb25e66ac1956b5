/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IResourceDelta;
import org.eclipse.core.resources.IResourceProxy;
import org.eclipse.core.resources.IncrementalProjectBuilder;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.OperationCanceledException;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.core.runtime.jobs.ISchedulingRule;
import org.rsaml.ide.RsamlMarkers;
import org.rsaml.ide.RsamlProjects;
import org.rsaml.model.resource.ModelFormats;

/**
 * Validates the project's model files ({@code .rsaml} and textual {@code .rsa}): all of them on a full build, the added and changed
 * ones on an incremental build. Derived files (build output copies) are skipped, so a model is
 * reported once, where the user edits it.
 */
public final class RsamlBuilder extends IncrementalProjectBuilder {

    private static final int CONTENT_CHANGES = IResourceDelta.CONTENT | IResourceDelta.REPLACED
            | IResourceDelta.ENCODING | IResourceDelta.TYPE | IResourceDelta.DERIVED_CHANGED;

    @Override
    protected IProject[] build(int kind, Map<String, String> args, IProgressMonitor monitor) throws CoreException {
        IResourceDelta delta = kind == FULL_BUILD ? null : getDelta(getProject());
        List<IFile> toValidate = new ArrayList<>();
        List<IFile> toClear = new ArrayList<>();
        if (delta == null) {
            getProject().deleteMarkers(RsamlMarkers.PROBLEM, true, IResource.DEPTH_INFINITE);
            collectAll(toValidate);
        } else {
            collectChanged(delta, toValidate, toClear);
        }
        SubMonitor progress = SubMonitor.convert(monitor, "Validating RsaML models", toValidate.size() + toClear.size());
        try {
            for (IFile file : toClear) {
                file.deleteMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO);
                progress.split(1);
            }
            for (IFile file : toValidate) {
                progress.subTask(file.getFullPath().toString());
                ModelFileValidator.validate(file);
                progress.split(1);
            }
        } catch (OperationCanceledException e) {
            forgetLastBuiltState(); // the next build validates everything again
            throw e;
        }
        return null;
    }

    @Override
    protected void clean(IProgressMonitor monitor) throws CoreException {
        getProject().deleteMarkers(RsamlMarkers.PROBLEM, true, IResource.DEPTH_INFINITE);
    }

    /** Only this project's files are read and marked, so other projects can build meanwhile. */
    @Override
    public ISchedulingRule getRule(int kind, Map<String, String> args) {
        return getProject();
    }

    private void collectAll(List<IFile> out) throws CoreException {
        getProject().accept((IResourceProxy proxy) -> {
            if (proxy.isDerived()) {
                return false;
            }
            if (proxy.getType() == IResource.FILE && ModelFormats.isModelFile(proxy.getName())) {
                out.add((IFile) proxy.requestResource());
            }
            return true;
        }, IResource.NONE);
    }

    private static void collectChanged(IResourceDelta delta, List<IFile> toValidate, List<IFile> toClear) throws CoreException {
        delta.accept(d -> {
            if (!(d.getResource() instanceof IFile file)) {
                return true;
            }
            boolean touched = d.getKind() == IResourceDelta.ADDED
                    || d.getKind() == IResourceDelta.CHANGED && (d.getFlags() & CONTENT_CHANGES) != 0;
            if (touched && file.exists()) {
                if (isValidated(file)) {
                    toValidate.add(file);
                } else if (file.findMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO).length > 0) {
                    // Renamed from .rsaml or marked derived: the markers moved with it but no longer apply.
                    toClear.add(file);
                }
            }
            // Removed files take their markers with them.
            return false;
        });
    }

    private static boolean isValidated(IFile file) {
        return RsamlProjects.isModelFile(file) && !file.isDerived(IResource.CHECK_ANCESTORS);
    }
}
