/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.docgen;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EEnumLiteral;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.rsaml.model.RsamlPackage;
import org.rsaml.text.grammar.Constructs;
import org.rsaml.text.grammar.Constructs.Attribute;
import org.rsaml.text.grammar.Constructs.Construct;
import org.rsaml.text.grammar.Constructs.ValueKind;

/**
 * The language reference of docs/textual-syntax.md, made from the grammar ({@link Constructs}) and rsaml.ecore: every
 * concept with its keyword and what its braces hold, every attribute with the feature it sets and its values, every
 * unit; each with an example, taken from the textual examples ({@code examples-text/}) where one uses the keyword,
 * else made from the grammar. {@link RsamlDocgen} writes it between {@link #BEGIN} and {@link #END} when the
 * generated files are regenerated, and checks that the committed page is what it writes. It lives here, not in
 * {@code org.rsaml.text}: it is a build-time writer of a page, no part of the runtime.
 */
final class LanguageReference {

    static final String PATH = "docs/textual-syntax.md";
    static final String BEGIN = "<!-- begin: generated from RsamlText.xtext and rsaml.ecore by releng/org.rsaml.docgen; do not edit -->";
    static final String END = "<!-- end: generated -->";

    private static final int LONGEST_EXAMPLE = 110;

    private LanguageReference() {
    }

    /** The page with its generated part replaced. */
    static String update(String page, Constructs constructs, List<String> exampleTexts) {
        int begin = page.indexOf(BEGIN);
        int end = page.indexOf(END);
        if (begin < 0 || end < begin) {
            throw new IllegalArgumentException(PATH + " has no part between '" + BEGIN + "' and '" + END + "' to generate");
        }
        return page.substring(0, begin + BEGIN.length()) + "\n" + reference(constructs, exampleTexts) + page.substring(end);
    }

    /** The generated part: concepts, attributes, units. */
    static String reference(Constructs constructs, List<String> exampleTexts) {
        List<String> lines = new ArrayList<>();
        List<String> enclosing = new ArrayList<>();
        for (String text : exampleTexts) {
            List<String> open = new ArrayList<>();
            for (String line : text.lines().map(String::strip).toList()) {
                lines.add(line);
                enclosing.add(open.isEmpty() ? "" : open.get(open.size() - 1));
                int depth = count(line, '{') - count(line, '}');
                for (int k = 0; k < depth; k++) {
                    open.add(line.split(" ", 2)[0]);
                }
                for (int k = 0; k > depth && !open.isEmpty(); k--) {
                    open.remove(open.size() - 1);
                }
            }
        }
        StringBuilder out = new StringBuilder();
        out.append("\n## Concepts\n\n");
        out.append("| Keyword | Concept (rsaml.ecore) | Inside its braces | Example |\n|---|---|---|---|\n");
        for (Construct c : constructs.all()) {
            String keywords = String.join(", ", c.keywords().stream().map(LanguageReference::code).toList());
            String concept = c.keywords().size() > 1 ? subclasses(c) : c.type().getName();
            String inside = c.hasBody() ? String.join(", ", c.members().stream().map(LanguageReference::code).toList())
                    : "no braces: " + c.keywords().get(0) + " SOURCE -> TARGET";
            out.append("| ").append(keywords).append(" | ").append(concept).append(" | ").append(inside).append(" | ")
                    .append(code(conceptExample(c, lines))).append(" |\n");
        }

        out.append("\n## Attributes\n\n");
        out.append("| Keyword | Written in | Sets (rsaml.ecore) | Value | Example |\n|---|---|---|---|---|\n");
        Map<String, List<Object[]>> rows = new LinkedHashMap<>();
        for (Construct c : constructs.all()) {
            if (!c.hasBody()) {
                continue;
            }
            for (Attribute a : c.attributes()) {
                String key = a.keyword() + "\u0000" + a.describe();
                rows.computeIfAbsent(key, k -> new ArrayList<>()).add(new Object[] { c, a });
            }
        }
        for (List<Object[]> row : rows.values()) {
            Attribute a = (Attribute) row.get(0)[1];
            List<String> in = new ArrayList<>();
            List<String> sets = new ArrayList<>();
            List<String> contexts = new ArrayList<>();
            for (Object[] r : row) {
                Construct c = (Construct) r[0];
                in.add(String.join(", ", c.keywords()));
                contexts.addAll(c.keywords());
                String feature = owner(c.type(), a.feature());
                if (!sets.contains(feature)) {
                    sets.add(feature);
                }
            }
            out.append("| ").append(code(a.keyword())).append(" | ").append(String.join(", ", in)).append(" | ")
                    .append(String.join(", ", sets)).append(" | ").append(value(a)).append(" | ")
                    .append(code(attributeExample(a, lines, enclosing, contexts))).append(" |\n");
        }

        out.append("\n## Units\n\n");
        out.append("A time is a number followed by its unit. An element has one unit for all its times (rsaml.ecore's `timeUnit`, ")
                .append("`").append(defaultUnit()).append("` when none is written); `unit` states it for an element that writes no time.\n\n");
        out.append("| Unit | Length |\n|---|---|\n");
        EEnum units = RsamlPackage.Literals.TIME_UNIT;
        for (String literal : constructs.literalsOf("TimeUnit")) {
            EEnumLiteral l = units.getEEnumLiteralByLiteral(literal);
            out.append("| ").append(code(literal)).append(" | ").append(String.format(Locale.ROOT, "%,d", l.getValue()))
                    .append(" ns |\n");
        }
        out.append('\n');
        return out.toString();
    }

    /** What follows the keyword, enumeration literals as code. */
    private static String value(Attribute a) {
        return a.kind() == ValueKind.ENUM ? "one of " + String.join(", ", a.literals().stream().map(LanguageReference::code).toList())
                : a.describe();
    }

    private static String subclasses(Construct c) {
        return String.join(", ", concreteNames(c));
    }

    private static List<String> concreteNames(Construct c) {
        List<String> names = new ArrayList<>();
        for (EClass e : RsamlPackage.eINSTANCE.getEClassifiers().stream().filter(EClass.class::isInstance).map(EClass.class::cast).toList()) {
            if (!e.isAbstract() && (e == c.type() || c.type().isSuperTypeOf(e))) {
                names.add(e.getName());
            }
        }
        return names;
    }

    /** The class that declares the feature, as Class.feature. */
    private static String owner(EClass type, String feature) {
        EStructuralFeature f = type.getEStructuralFeature(feature);
        return (f == null ? type.getName() : f.getEContainingClass().getName()) + "." + feature;
    }

    private static String defaultUnit() {
        EAttribute unit = (EAttribute) RsamlPackage.Literals.TIME_SCALED.getEStructuralFeature("timeUnit");
        Object value = unit.getDefaultValue();
        return value == null ? "ms" : value.toString();
    }

    /** The first element of the kind in the examples, on one line when it is short, else its first line. */
    private static String conceptExample(Construct c, List<String> lines) {
        String keyword = c.keywords().get(0);
        String head = null;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (!line.startsWith(keyword + " ")) {
                continue;
            }
            if (!line.endsWith("{")) {
                return line;
            }
            StringBuilder one = new StringBuilder(line);
            int depth = 1;
            for (int j = i + 1; j < lines.size() && depth > 0 && one.length() <= LONGEST_EXAMPLE; j++) {
                String next = lines.get(j);
                if (next.isEmpty() || next.startsWith("//") || next.startsWith("description ")) {
                    continue;
                }
                depth += count(next, '{') - count(next, '}');
                one.append(' ').append(next);
            }
            if (depth == 0 && one.length() <= LONGEST_EXAMPLE) {
                return one.toString();
            }
            if (head == null) {
                head = shortHead(lines, i);
            }
        }
        if (head != null) {
            return head;
        }
        if (!c.hasBody()) {
            return keyword + " module1.output1 -> module2.input1";
        }
        Attribute first = c.attributes().stream().filter(a -> !a.keyword().equals("description")).findFirst().orElse(null);
        return keyword + " " + c.type().getName().substring(0, 1).toLowerCase(Locale.ROOT) + c.type().getName().substring(1) + "1 { "
                + (first == null ? "" : first.keyword() + " " + sample(first) + " ") + "}";
    }

    /** An element's first line and the attribute lines after it that fit, then "... }". */
    private static String shortHead(List<String> lines, int start) {
        StringBuilder head = new StringBuilder(lines.get(start));
        for (int j = start + 1; j < lines.size(); j++) {
            String next = lines.get(j);
            if (next.isEmpty() || next.startsWith("//") || next.startsWith("description ")) {
                continue;
            }
            if (next.contains("{") || next.contains("}") || head.length() + next.length() + 7 > LONGEST_EXAMPLE) {
                break;
            }
            head.append(' ').append(next);
        }
        return head.append(" ... }").toString();
    }

    private static String attributeExample(Attribute a, List<String> lines, List<String> enclosing, List<String> contexts) {
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.startsWith(a.keyword() + " ") && !line.endsWith("{") && line.length() <= LONGEST_EXAMPLE && fits(a, line)
                    && contexts.contains(enclosing.get(i))) {
                return line;
            }
        }
        return a.keyword() + " " + sample(a);
    }

    /** Whether an example line shows this attribute's kind of value (kind as a string is not kind as an enumeration). */
    private static boolean fits(Attribute a, String line) {
        String value = line.substring(a.keyword().length()).strip();
        return switch (a.kind()) {
            case STRING -> value.startsWith("\"");
            case ENUM -> a.literals().contains(value);
            case WHOLE_NUMBER, NUMBER, TIME -> !value.isEmpty() && (Character.isDigit(value.charAt(0)) || value.charAt(0) == '-');
            default -> true;
        };
    }

    private static String sample(Attribute a) {
        if (a.kind() == ValueKind.REFERENCE || a.kind() == ValueKind.REFERENCES) {
            String name = a.referenced().getName();
            String one = name.substring(0, 1).toLowerCase(Locale.ROOT) + name.substring(1) + "1";
            return a.kind() == ValueKind.REFERENCES ? one + ", " + one.substring(0, one.length() - 1) + "2" : one;
        }
        return a.sample();
    }

    private static int count(String text, char c) {
        int n = 0;
        boolean quoted = false;
        for (int i = 0; i < text.length(); i++) {
            char x = text.charAt(i);
            if (x == '"' && (i == 0 || text.charAt(i - 1) != '\\')) {
                quoted = !quoted;
            } else if (x == c && !quoted) {
                n++;
            }
        }
        return n;
    }

    /** Markdown code; a '|' inside a table cell is escaped. */
    private static String code(String text) {
        return "`" + text.replace("|", "\\|") + "`";
    }
}
