/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;

/**
 * A file's XML comments, each anchored to the element it stood before (or, after an element's last
 * child, to the end of that element; after the root, to the end of the document), so that saving
 * writes them back where they were. A comment moves with its element and goes when it is deleted.
 */
final class Comments {

    private final Map<EObject, List<String>> before = new IdentityHashMap<>();
    private final Map<EObject, List<String>> atEnd = new IdentityHashMap<>();
    private final List<String> afterRoot = new ArrayList<>();

    void addBefore(EObject element, List<String> comments) {
        before.computeIfAbsent(element, e -> new ArrayList<>()).addAll(comments);
    }

    void addAtEnd(EObject element, List<String> comments) {
        atEnd.computeIfAbsent(element, e -> new ArrayList<>()).addAll(comments);
    }

    void addAfterRoot(List<String> comments) {
        afterRoot.addAll(comments);
    }

    List<String> before(EObject element) {
        return before.getOrDefault(element, List.of());
    }

    List<String> atEnd(EObject element) {
        return atEnd.getOrDefault(element, List.of());
    }

    List<String> afterRoot() {
        return afterRoot;
    }

    int size() {
        return before.values().stream().mapToInt(List::size).sum() + atEnd.values().stream().mapToInt(List::size).sum()
                + afterRoot.size();
    }

    void clear() {
        before.clear();
        atEnd.clear();
        afterRoot.clear();
    }
}
