/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.formatting2;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.formatting2.AbstractJavaFormatter;
import org.eclipse.xtext.formatting2.FormatterPreferenceKeys;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormattableDocument;
import org.eclipse.xtext.formatting2.regionaccess.IEObjectRegion;
import org.eclipse.xtext.formatting2.regionaccess.ISemanticRegion;
import org.eclipse.xtext.preferences.MapBasedPreferenceValues;
import org.eclipse.xtext.preferences.TypedPreferenceValues;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.text.grammar.Constructs;
import org.rsaml.text.grammar.Constructs.Construct;
import org.rsaml.text.services.RsamlTextGrammarAccess;

import com.google.inject.Inject;

/**
 * Lays a textual model out as {@link org.rsaml.text.serializer.RsamlTextWriter} writes it: two spaces
 * of indentation a level, one attribute a line, a blank line before each element with a body (and
 * before the first connection), single spaces between words, {@code {}} for an empty body.
 * Comments stay where they are. Formatting formatted text changes nothing.
 */
public class RsamlTextFormatter extends AbstractJavaFormatter {

    /**
     * The keywords that begin an attribute, each starting a line of its own: every attribute the grammar gives a concept
     * with braces ({@link Constructs}), so that a keyword added to the grammar is laid out as the writer writes it.
     */
    private Set<String> lineStarts;

    @Inject
    void lineStarts(RsamlTextGrammarAccess grammar) {
        lineStarts = lineStarts(new Constructs(grammar.getGrammar()));
    }

    /** The keywords of the attributes the grammar gives the concepts written with braces. */
    public static Set<String> lineStarts(Constructs constructs) {
        Set<String> keywords = new TreeSet<>();
        for (Construct construct : constructs.all()) {
            if (construct.hasBody()) {
                construct.attributes().forEach(a -> keywords.add(a.keyword()));
            }
        }
        return Collections.unmodifiableSet(keywords);
    }

    /** The layout is the language's: two spaces a level, whatever the editor's preference. */
    @Override
    protected void initialize(FormatterRequest request) {
        request.setPreferences(TypedPreferenceValues.castOrWrap(new MapBasedPreferenceValues(request.getPreferences(),
                Map.of(FormatterPreferenceKeys.indentation.getId(), "  "))));
        super.initialize(request);
    }

    @Override
    protected void _format(EObject element, IFormattableDocument doc) {
        List<ISemanticRegion> own = new ArrayList<>();
        semanticRegions(element).forEach(own::add);
        for (int i = 1; i < own.size(); i++) {
            ISemanticRegion region = own.get(i);
            if (",".equals(region.getText()) && region.getGrammarElement() instanceof Keyword) {
                doc.prepend(region, this::noSpace);
            } else {
                doc.prepend(region, f -> {
                    f.oneSpace();
                    f.lowPriority();
                });
            }
        }
        ISemanticRegion open = regionFor(element).keyword("{");
        ISemanticRegion close = regionFor(element).keyword("}");
        if (open != null && close != null) {
            if (open.getNextSemanticRegion() == close) {
                doc.append(open, this::noSpace);
            } else {
                doc.append(open, this::newLine);
                doc.prepend(close, this::newLine);
                doc.interior(open, close, this::indent);
            }
            for (ISemanticRegion region : own) {
                if (region.getGrammarElement() instanceof Keyword keyword && lineStarts.contains(keyword.getValue())
                        && region.getOffset() > open.getOffset() && region.getEndOffset() <= close.getOffset()) {
                    doc.prepend(region, this::newLine);
                }
            }
        }
        if (element instanceof Architecture && close != null) {
            doc.append(close, f -> f.setNewLines(1));
        }
        EObject previous = null;
        for (EObject child : element.eContents()) {
            IEObjectRegion region = regionForEObject(child);
            if (region == null) {
                continue;
            }
            boolean afterOpening = open != null && region.getPreviousSemanticRegion() == open;
            boolean connectionAfterConnection = child instanceof Connection && previous instanceof Connection;
            doc.prepend(child, afterOpening || connectionAfterConnection ? this::newLine : f -> f.setNewLines(2));
            doc.format(child);
            previous = child;
        }
    }
}
