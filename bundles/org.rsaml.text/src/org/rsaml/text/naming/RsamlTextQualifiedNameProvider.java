/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.naming;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.rsaml.model.Architecture;
import org.rsaml.model.NamedElement;

/**
 * An element's full name: its name preceded by the names of its containers up to, not including, the
 * architecture ({@code navigation.obstacleDetector.speedLimit}). An element with a container without a
 * name has none.
 */
public class RsamlTextQualifiedNameProvider extends IQualifiedNameProvider.AbstractImpl {

    @Override
    public QualifiedName getFullyQualifiedName(EObject element) {
        return qualifiedName(element);
    }

    /** The same as {@link #getFullyQualifiedName(EObject)}, for code without an injector. */
    public static QualifiedName qualifiedName(EObject element) {
        if (!(element instanceof NamedElement) || element instanceof Architecture) {
            return null;
        }
        List<String> segments = new ArrayList<>();
        for (EObject e = element; e != null && !(e instanceof Architecture); e = e.eContainer()) {
            if (!(e instanceof NamedElement named) || named.getName() == null) {
                return null;
            }
            segments.add(named.getName());
        }
        Collections.reverse(segments);
        return QualifiedName.create(segments);
    }
}
