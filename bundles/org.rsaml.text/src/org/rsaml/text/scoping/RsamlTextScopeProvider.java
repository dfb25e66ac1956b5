/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.scoping;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.EObjectDescription;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.impl.MapBasedScope;
import org.eclipse.xtext.util.IResourceScopeCache;
import org.eclipse.xtext.util.Tuples;
import org.rsaml.text.naming.RsamlTextNameIndex;

import com.google.inject.Inject;

/**
 * A reference sees the elements of its type in its own file, by full or unambiguous shorter name
 * ({@link RsamlTextNameIndex}); nothing of other files, so a model never reaches outside itself.
 */
public class RsamlTextScopeProvider extends AbstractRsamlTextScopeProvider {

    @Inject
    private IResourceScopeCache cache;

    @Override
    public IScope getScope(EObject context, EReference reference) {
        Resource resource = context.eResource();
        if (resource == null) {
            return IScope.NULLSCOPE;
        }
        EClass type = reference.getEReferenceType();
        return cache.get(Tuples.create(RsamlTextScopeProvider.class, type), resource, () -> scope(resource, type));
    }

    private static IScope scope(Resource resource, EClass type) {
        Map<QualifiedName, EObject> names = RsamlTextNameIndex.names(resource, type);
        List<IEObjectDescription> descriptions = new ArrayList<>(names.size());
        names.forEach((name, element) -> descriptions.add(EObjectDescription.create(name, element)));
        return MapBasedScope.createScope(IScope.NULLSCOPE, descriptions);
    }
}
