/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import java.util.HashMap;
import java.util.Map;
import java.util.TreeSet;

import org.eclipse.emf.ecore.EClass;

/** The variables an expression can use, with the RsaML class of each (null when it cannot be told). */
record Scope(Map<String, EClass> variables) {
    /** {@code of("self", layer, "container", architecture)}; a class may be null when it cannot be told. */
    static Scope of(Object... namesAndClasses) {
        Map<String, EClass> variables = new HashMap<>();
        for (int i = 0; i < namesAndClasses.length; i += 2) {
            variables.put((String) namesAndClasses[i], (EClass) namesAndClasses[i + 1]);
        }
        return new Scope(variables);
    }

    EClass self() {
        return variables.get("self");
    }

    boolean has(String name) {
        return variables.containsKey(name);
    }

    EClass get(String name) {
        return variables.get(name);
    }

    Scope with(String name, EClass eClass) {
        Map<String, EClass> more = new HashMap<>(variables);
        more.put(name, eClass);
        return new Scope(more);
    }

    String names() {
        return new TreeSet<>(variables.keySet()).toString();
    }
}
