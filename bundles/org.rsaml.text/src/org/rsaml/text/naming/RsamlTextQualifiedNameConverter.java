/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.naming;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.QualifiedName;

import com.google.inject.Inject;

/**
 * Qualified names as the text writes them: names separated by dots, each bare or in double quotes
 * (so a name may itself hold a dot or a space).
 */
public class RsamlTextQualifiedNameConverter implements IQualifiedNameConverter {

    @Inject
    private RsamlTextSyntax syntax;

    @Override
    public String toString(QualifiedName name) {
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < name.getSegmentCount(); i++) {
            if (i > 0) {
                out.append('.');
            }
            out.append(syntax.referenceSegment(name.getSegment(i), i == 0));
        }
        return out.toString();
    }

    @Override
    public QualifiedName toQualifiedName(String text) {
        return QualifiedName.create(segments(text));
    }

    /** The names of a reference as written; white space between the names is ignored. */
    public static List<String> segments(String text) {
        List<String> segments = new ArrayList<>();
        int i = 0;
        int n = text.length();
        while (i < n) {
            while (i < n && Character.isWhitespace(text.charAt(i))) {
                i++;
            }
            if (i < n && text.charAt(i) == '"') {
                int start = i++;
                while (i < n && text.charAt(i) != '"') {
                    i += text.charAt(i) == '\\' ? 2 : 1;
                }
                i = Math.min(i + 1, n);
                segments.add(RsamlTextSyntax.unquote(text.substring(start, i)));
            } else {
                int start = i;
                while (i < n && text.charAt(i) != '.' && !Character.isWhitespace(text.charAt(i))) {
                    i++;
                }
                String word = text.substring(start, i);
                segments.add(word.startsWith("^") ? word.substring(1) : word);
            }
            while (i < n && Character.isWhitespace(text.charAt(i))) {
                i++;
            }
            if (i < n && text.charAt(i) == '.') {
                i++;
            }
        }
        return segments;
    }

}
