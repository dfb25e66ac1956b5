/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.naming;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.naming.QualifiedName;

/**
 * The names a reference of a given type can use in one model: every element's full name, and every
 * shorter ending of it ({@code obstacleDetector.speedLimit}, {@code speedLimit}) that names no other
 * element of that type. When two elements share a full name, the first one has it. Linking, the
 * writer and completion all use this one table.
 */
public final class RsamlTextNameIndex {

    private RsamlTextNameIndex() {
    }

    /** The names usable for elements of the type in the resource, each with the element it names, in model order. */
    public static Map<QualifiedName, EObject> names(Resource resource, EClass type) {
        List<EObject> candidates = new ArrayList<>();
        List<QualifiedName> fullNames = new ArrayList<>();
        for (var it = resource.getAllContents(); it.hasNext();) {
            EObject e = it.next();
            if (type.isInstance(e)) {
                QualifiedName name = RsamlTextQualifiedNameProvider.qualifiedName(e);
                if (name != null) {
                    candidates.add(e);
                    fullNames.add(name);
                }
            }
        }
        Map<QualifiedName, Integer> endings = new HashMap<>();
        for (QualifiedName name : fullNames) {
            for (int i = 1; i < name.getSegmentCount(); i++) {
                endings.merge(name.skipFirst(i), 1, Integer::sum);
            }
        }
        Map<QualifiedName, EObject> result = new LinkedHashMap<>();
        for (int k = 0; k < candidates.size(); k++) {
            result.putIfAbsent(fullNames.get(k), candidates.get(k));
        }
        for (int k = 0; k < candidates.size(); k++) {
            QualifiedName name = fullNames.get(k);
            for (int i = 1; i < name.getSegmentCount(); i++) {
                QualifiedName ending = name.skipFirst(i);
                if (endings.get(ending) == 1 && !result.containsKey(ending)) {
                    result.put(ending, candidates.get(k));
                }
            }
        }
        return result;
    }
}
