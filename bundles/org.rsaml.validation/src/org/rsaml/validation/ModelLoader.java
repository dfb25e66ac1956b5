/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Collection;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.common.util.WrappedException;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.model.resource.SourceLocation;

/**
 * Reads a .rsaml file for validation through the model's own {@link RsamlResource} (safe, located
 * loading), in a resource set that opens local files only, and turns the first thing that makes
 * the file unfit, including a reference that does not resolve, into a {@link ModelLoadException}.
 */
public final class ModelLoader {

    private ModelLoader() {
    }

    /** Loads {@code path}, reporting it as {@code displayName} in messages. */
    public static LoadedModel load(Path path, String displayName) throws ModelLoadException {
        RsamlValidationSetup.registerPackage();
        ResourceSet resourceSet = RsamlStandaloneSetup.newResourceSet();
        URI uri = URI.createFileURI(path.toAbsolutePath().toString());
        RsamlResource resource = new RsamlResource(uri);
        resourceSet.getResources().add(resource);
        try {
            resource.load(resourceSet.getLoadOptions());
            checkCrossReferences(displayName, uri, resource);
        } catch (IOException | WrappedException e) {
            throw describe(displayName, resource, e);
        } catch (RuntimeException e) {
            // Not the file's fault, but still this file's failure only.
            throw new ModelLoadException(displayName, 0, 0, "RsaML failed on this file with an internal error ("
                    + e.getClass().getSimpleName() + "); please report it together with the file", e);
        }
        return new LoadedModel(resource, displayName, path);
    }

    private static ModelLoadException describe(String file, Resource resource, Exception thrown) {
        if (resource.getErrors().isEmpty()) {
            return new ModelLoadException(file, 0, 0, "the file cannot be read: " + thrown.getMessage(), thrown);
        }
        Resource.Diagnostic first = resource.getErrors().get(0);
        String message = first.getMessage();
        int more = resource.getErrors().size() - 1;
        if (more > 0) {
            message += " (and " + more + " more error" + (more > 1 ? "s" : "") + ")";
        }
        return new ModelLoadException(file, first.getLine(), first.getColumn(), message, first instanceof Exception e ? e : thrown);
    }

    private static void checkCrossReferences(String file, URI uri, RsamlResource resource) throws ModelLoadException {
        Map<EObject, Collection<EStructuralFeature.Setting>> unresolved = EcoreUtil.UnresolvedProxyCrossReferencer.find(resource);
        if (unresolved.isEmpty()) {
            return;
        }
        Map.Entry<EObject, Collection<EStructuralFeature.Setting>> first = unresolved.entrySet().iterator().next();
        EStructuralFeature.Setting setting = first.getValue().iterator().next();
        SourceLocation at = resource.locate(setting.getEObject());
        URI target = ((InternalEObject) first.getKey()).eProxyURI();
        // Named as written, relative to the model, never as an absolute path the user did not give.
        String named = target.trimFragment().equals(uri) ? target.fragment() : target.deresolve(uri).toString();
        Resource other = target.trimFragment().equals(uri) ? null : resource.getResourceSet().getResource(target.trimFragment(), false);
        String why = ", which does not exist";
        if (other != null && !other.getErrors().isEmpty()) {
            Resource.Diagnostic problem = other.getErrors().get(0);
            why = ", which cannot be loaded: " + new SourceLocation(target.trimFragment().deresolve(uri).toString(),
                    problem.getLine(), problem.getColumn()) + ": " + problem.getMessage();
        } else if (other != null && !other.isLoaded()) {
            why = ", which cannot be loaded";
        }
        throw new ModelLoadException(file, at.line(), at.column(), "reference " + setting.getEStructuralFeature().getName()
                + " points to '" + named + "'" + why
                + (unresolved.size() > 1 ? " (and " + (unresolved.size() - 1) + " more unresolved references)" : ""), null);
    }
}
