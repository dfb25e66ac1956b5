/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.xmi.XMLHelper;
import org.eclipse.emf.ecore.xmi.impl.XMISaveImpl;

/**
 * EMF's XMI save, writing back the comments the file had when it was read ({@link Comments}): each
 * before the start tag of its element, indented like it, or before the end tag of the element it
 * ended, or after the root.
 */
final class CommentKeepingSave extends XMISaveImpl {

    private final Comments comments;

    CommentKeepingSave(XMLHelper helper, Comments comments) {
        super(helper);
        this.comments = comments;
    }

    @Override
    protected Object writeTopObject(EObject top) {
        // The XML declaration is written; the root's start tag comes next.
        for (String comment : comments.before(top)) {
            doc.add("<!--" + comment + "-->");
            doc.addLine();
        }
        Object mark = super.writeTopObject(top);
        // The root is written whole (its end tag and line end included): what followed it in the file.
        if (!toDOM) {
            for (String comment : comments.afterRoot()) {
                doc.add("<!--" + comment + "-->");
                doc.addLine();
            }
        }
        return mark;
    }

    @Override
    protected void saveElement(EObject o, EStructuralFeature f) {
        writeIndented(comments.before(o), depth(o));
        super.saveElement(o, f);
    }

    @Override
    protected void endSaveFeatures(EObject o, int elementType, String content) {
        List<String> atEnd = comments.atEnd(o);
        if (atEnd.isEmpty() || toDOM || elementType == CONTENT_ELEMENT) {
            super.endSaveFeatures(o, elementType, content);
            return;
        }
        // Comments inside the element: it needs an end tag even when it has no children now.
        writeIndented(atEnd, depth(o) + 1);
        super.endSaveFeatures(o, 0, content);
    }

    /** The comments on lines of their own, indented as an element {@code depth} levels below the root. */
    private void writeIndented(List<String> text, int depth) {
        if (text.isEmpty() || toDOM) {
            return;
        }
        doc.addText(""); // closes the parent's start tag if it is still open
        String indent = "  ".repeat(depth);
        for (String comment : text) {
            doc.add(indent + "<!--" + comment + "-->");
            doc.addLine();
        }
    }

    private static int depth(EObject element) {
        int depth = 0;
        for (EObject e = element.eContainer(); e != null; e = e.eContainer()) {
            depth++;
        }
        return depth;
    }
}
