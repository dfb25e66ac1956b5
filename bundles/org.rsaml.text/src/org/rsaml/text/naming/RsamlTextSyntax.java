/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.naming;

import java.util.Set;
import java.util.regex.Pattern;

import org.eclipse.xtext.GrammarUtil;
import org.rsaml.text.services.RsamlTextGrammarAccess;

import com.google.inject.Inject;
import com.google.inject.Singleton;

/**
 * How names and text are written in the textual syntax: an identifier stays bare, anything else
 * (and a word of the language where a reference starts) goes in double quotes with Java escapes.
 * The writer, the name converter and the language server all spell names this way.
 */
@Singleton
public class RsamlTextSyntax {

    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

    private final Set<String> keywords;

    @Inject
    public RsamlTextSyntax(RsamlTextGrammarAccess grammar) {
        this.keywords = Set.copyOf(GrammarUtil.getAllKeywords(grammar.getGrammar()));
    }

    /** Whether the word is a keyword of the language. */
    public boolean isKeyword(String word) {
        return keywords.contains(word);
    }

    /** A name where a name is declared: bare when it is an identifier or a word of the language, else quoted. */
    public String declaredName(String name) {
        return IDENTIFIER.matcher(name).matches() ? name : quote(name);
    }

    /** A name inside a reference; the first one of a reference is quoted when it is a word of the language. */
    public String referenceSegment(String name, boolean first) {
        return IDENTIFIER.matcher(name).matches() && !(first && isKeyword(name)) ? name : quote(name);
    }

    /** A string literal: double quotes, Java escapes for quotes, backslashes and every character that is not plainly visible. */
    public static String quote(String text) {
        StringBuilder out = new StringBuilder(text.length() + 2).append('"');
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (c < 0x20 || (c >= 0x7f && c <= 0x9f) || Character.isSurrogate(c) && !pairedSurrogate(text, i)
                            || Character.getType(c) == Character.FORMAT || c == '\u2028' || c == '\u2029') {
                        out.append(String.format("\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        return out.append('"').toString();
    }

    /**
     * The text of a string literal (with or without its quotes): Java escapes are replaced.
     *
     * @throws IllegalArgumentException naming the escape that is not one
     */
    public static String unquote(String literal) {
        String body = literal.length() >= 2 && literal.startsWith("\"") && literal.endsWith("\"")
                ? literal.substring(1, literal.length() - 1) : literal.startsWith("\"") ? literal.substring(1) : literal;
        if (body.indexOf('\\') < 0) {
            return body;
        }
        StringBuilder out = new StringBuilder(body.length());
        for (int i = 0; i < body.length(); i++) {
            char c = body.charAt(i);
            if (c != '\\') {
                out.append(c);
                continue;
            }
            if (++i >= body.length()) {
                throw new IllegalArgumentException("a string ends with a lone backslash; write \\\\ for a backslash");
            }
            char e = body.charAt(i);
            switch (e) {
                case 'n' -> out.append('\n');
                case 'r' -> out.append('\r');
                case 't' -> out.append('\t');
                case 'b' -> out.append('\b');
                case 'f' -> out.append('\f');
                case '"', '\'', '\\' -> out.append(e);
                case 'u' -> {
                    String hex = body.substring(i + 1, Math.min(i + 5, body.length()));
                    if (!hex.matches("[0-9a-fA-F]{4}")) {
                        throw new IllegalArgumentException("'\\u" + hex + "' is not an escape; '\\u' must be followed by four hexadecimal digits");
                    }
                    out.append((char) Integer.parseInt(hex, 16));
                    i += 4;
                }
                default -> throw new IllegalArgumentException("'\\" + e + "' is not an escape; write \\\\ for a backslash");
            }
        }
        return out.toString();
    }

    private static boolean pairedSurrogate(String text, int i) {
        char c = text.charAt(i);
        if (Character.isHighSurrogate(c)) {
            return i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1));
        }
        return i > 0 && Character.isHighSurrogate(text.charAt(i - 1));
    }
}
