/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.common.util.WrappedException;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.rsaml.model.resource.LocatingResource;
import org.rsaml.model.resource.ModelFormats;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.resource.RsamlStandaloneSetup;
import org.rsaml.model.resource.SourceLocation;

/**
 * Reads a model file for validation through the model's own {@link RsamlResource} (safe, located
 * loading), or, for a textual {@code .rsa} file, through the resource registered for it, in a resource
 * set that opens local files only, and turns the first thing that makes the file unfit, including a
 * reference that does not resolve, into a {@link ModelLoadException}.
 */
public final class ModelLoader {

    private ModelLoader() {
    }

    /** Loads {@code path}, reporting it as {@code displayName} in messages. */
    public static LoadedModel load(Path path, String displayName) throws ModelLoadException {
        RsamlValidationSetup.registerPackage();
        ResourceSet resourceSet = RsamlStandaloneSetup.newResourceSet();
        URI uri = URI.createFileURI(path.toAbsolutePath().toString());
        LocatingResource resource;
        if (ModelFormats.isText(path.toString())) {
            Resource.Factory factory = resourceSet.getResourceFactoryRegistry()
                    .getFactory(URI.createURI("model." + ModelFormats.TEXT_EXTENSION));
            Resource created = factory == null ? null : factory.createResource(uri);
            if (!(created instanceof LocatingResource located)) {
                throw new ModelLoadException(displayName, 0, 0, "textual models (." + ModelFormats.TEXT_EXTENSION
                        + ") cannot be read here: the org.rsaml.text bundle is missing", null);
            }
            resource = located;
            resourceSet.getResources().add(resource);
        } else {
            resource = new RsamlResource(uri);
            resourceSet.getResources().add(resource);
        }
        try {
            resource.load(resourceSet.getLoadOptions());
            if (!resource.getErrors().isEmpty()) {
                // A textual model is read whatever its errors (an editor shows them); a command stops here.
                throw describe(displayName, resource, null);
            }
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
            return new ModelLoadException(file, 0, 0, "the file cannot be read: " + (thrown == null ? "" : thrown.getMessage()), thrown);
        }
        Resource.Diagnostic first = resource.getErrors().get(0);
        List<ModelLoadException.Problem> more = new ArrayList<>();
        for (Resource.Diagnostic next : resource.getErrors().subList(1, resource.getErrors().size())) {
            more.add(new ModelLoadException.Problem(new SourceLocation(file, next.getLine(), next.getColumn()), next.getMessage()));
        }
        return new ModelLoadException(file, first.getLine(), first.getColumn(), first.getMessage(), more,
                first instanceof Exception e ? e : thrown);
    }

    private static void checkCrossReferences(String file, URI uri, LocatingResource resource) throws ModelLoadException {
        Map<EObject, Collection<EStructuralFeature.Setting>> unresolved = EcoreUtil.UnresolvedProxyCrossReferencer.find(resource);
        if (unresolved.isEmpty()) {
            return;
        }
        List<ModelLoadException.Problem> problems = new ArrayList<>();
        for (Map.Entry<EObject, Collection<EStructuralFeature.Setting>> proxy : unresolved.entrySet()) {
            URI target = ((InternalEObject) proxy.getKey()).eProxyURI();
            String why = unresolvedBecause(uri, resource, target);
            for (EStructuralFeature.Setting setting : proxy.getValue()) {
                SourceLocation at = resource.locate(setting.getEObject());
                problems.add(new ModelLoadException.Problem(new SourceLocation(file, at.line(), at.column()),
                        "reference " + setting.getEStructuralFeature().getName() + " points to '" + named(uri, target) + "'" + why));
            }
        }
        // In the order of the file, whatever order the references were found in.
        problems.sort(Comparator.comparingInt((ModelLoadException.Problem p) -> p.location().line())
                .thenComparingInt(p -> p.location().column()).thenComparing(ModelLoadException.Problem::message));
        ModelLoadException.Problem first = problems.get(0);
        throw new ModelLoadException(file, first.location().line(), first.location().column(), first.message(),
                problems.subList(1, problems.size()), null);
    }

    /** A reference's target as written, relative to the model, never as an absolute path the user did not give. */
    private static String named(URI uri, URI target) {
        return target.trimFragment().equals(uri) ? target.fragment() : target.deresolve(uri).toString();
    }

    private static String unresolvedBecause(URI uri, LocatingResource resource, URI target) {
        Resource other = target.trimFragment().equals(uri) ? null : resource.getResourceSet().getResource(target.trimFragment(), false);
        if (other != null && !other.getErrors().isEmpty()) {
            Resource.Diagnostic problem = other.getErrors().get(0);
            return ", which cannot be loaded: " + new SourceLocation(target.trimFragment().deresolve(uri).toString(),
                    problem.getLine(), problem.getColumn()) + ": " + problem.getMessage();
        }
        return other != null && !other.isLoaded() ? ", which cannot be loaded" : ", which does not exist";
    }
}
