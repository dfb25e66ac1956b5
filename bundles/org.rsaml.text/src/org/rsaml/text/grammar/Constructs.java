/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.grammar;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.AbstractElement;
import org.eclipse.xtext.AbstractRule;
import org.eclipse.xtext.Alternatives;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.EnumLiteralDeclaration;
import org.eclipse.xtext.EnumRule;
import org.eclipse.xtext.Grammar;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Group;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ParserRule;
import org.eclipse.xtext.RuleCall;

/**
 * What the grammar {@code RsamlText.xtext} says a user may write, read from the grammar itself: each concept with
 * its keyword, the attributes written inside its braces (keyword, value) and the concepts it holds. The syntax
 * error messages and the language reference (docs/textual-syntax.md) are both made from it, so neither can drift
 * from the grammar.
 */
public final class Constructs {

    /** What an attribute's keyword is followed by. */
    public enum ValueKind {
        WHOLE_NUMBER("a whole number", "2"), NUMBER("a number", "2.5"), TIME("a time: a number and its unit", "50 ms"),
        STRING("a string in double quotes", "\"text\""), ENUM("one of", null), REFERENCE("a reference", null),
        REFERENCES("references, separated by commas", null);

        private final String description;
        private final String sample;

        ValueKind(String description, String sample) {
            this.description = description;
            this.sample = sample;
        }

        public String description() {
            return description;
        }

        public String sample() {
            return sample;
        }
    }

    /**
     * An attribute of a concept: its keyword, the feature it sets, what follows it, the literals when that is an
     * enumeration, the referenced concept when a reference.
     */
    public record Attribute(String keyword, String feature, ValueKind kind, List<String> literals, EClass referenced) {

        /** What follows the keyword, in words: "a whole number", "one of simple, realTime", "a reference to a module". */
        public String describe() {
            return switch (kind) {
                case ENUM -> "one of " + String.join(", ", literals);
                case REFERENCE -> "a reference to " + (isAny() ? "any element" : article(referenced.getName()));
                case REFERENCES -> "references to " + (isAny() ? "any elements" : plural(referenced.getName())) + ", separated by commas";
                default -> kind.description();
            };
        }

        private boolean isAny() {
            return "NamedElement".equals(referenced.getName());
        }

        /** A value to show in an example. */
        public String sample() {
            return switch (kind) {
                case ENUM -> literals.get(0);
                case REFERENCE, REFERENCES -> "name";
                default -> kind.sample();
            };
        }
    }

    /** A concept: its class in rsaml.ecore, the keywords that begin it, its attributes and the keywords of what it holds. */
    public record Construct(EClass type, String rule, List<String> keywords, List<Attribute> attributes, List<String> children,
            boolean hasBody) {

        /** The attribute written with this keyword, or null. */
        public Attribute attribute(String keyword) {
            return attributes.stream().filter(a -> a.keyword().equals(keyword)).findFirst().orElse(null);
        }

        /** Every keyword that may begin an entry inside this concept's braces, attributes first. */
        public List<String> members() {
            List<String> all = new ArrayList<>();
            attributes.forEach(a -> {
                if (!all.contains(a.keyword())) {
                    all.add(a.keyword());
                }
            });
            children.forEach(c -> {
                if (!all.contains(c)) {
                    all.add(c);
                }
            });
            return all;
        }
    }

    private final Map<String, Construct> byRule = new LinkedHashMap<>();
    private final Map<String, List<String>> units = new LinkedHashMap<>();

    public Constructs(Grammar grammar) {
        for (ParserRule rule : GrammarUtil.allParserRules(grammar)) {
            EClassifier type = rule.getType() == null ? null : rule.getType().getClassifier();
            if (rule.isFragment() || GrammarUtil.isDatatypeRule(rule) || !(type instanceof EClass eClass)) {
                continue;
            }
            byRule.put(rule.getName(), read(rule, eClass));
        }
        for (EnumRule rule : GrammarUtil.allEnumRules(grammar)) {
            units.put(rule.getName(), literals(rule));
        }
    }

    /** Every concept, in the grammar's order. */
    public List<Construct> all() {
        return List.copyOf(byRule.values());
    }

    /** The concept its parser rule defines, or null. */
    public Construct ofRule(String ruleName) {
        return byRule.get(ruleName);
    }

    /** The literals of an enumeration rule of the grammar (TimeUnit: ns, us, ms, s). */
    public List<String> literalsOf(String enumRule) {
        return units.getOrDefault(enumRule, List.of());
    }

    private static Construct read(ParserRule rule, EClass type) {
        List<String> keywords = new ArrayList<>();
        List<Attribute> attributes = new ArrayList<>();
        List<String> children = new ArrayList<>();
        AbstractElement body = rule.getAlternatives();
        List<AbstractElement> head = body instanceof Group g ? g.getElements() : List.of(body);
        boolean hasBody = false;
        boolean named = false;
        for (AbstractElement element : head) {
            if (element instanceof Assignment) {
                named = true;
            } else if (element instanceof Keyword k && k.getValue().equals("{")) {
                hasBody = true;
            } else if (element instanceof Alternatives alternatives && hasBody) {
                for (AbstractElement member : alternatives.getElements()) {
                    member(member, attributes, children);
                }
            } else if (!hasBody && !named) {
                leadingKeywords(element, keywords);
            }
        }
        if (!hasBody) {
            // a concept without braces (connect source -> target): its references are its attributes
            for (Assignment a : GrammarUtil.containedAssignments(rule.getAlternatives())) {
                if (a.getTerminal() instanceof CrossReference x) {
                    attributes.add(new Attribute(a.getFeature().equals("source") ? "" : "->", a.getFeature(), ValueKind.REFERENCE,
                            List.of(), (EClass) x.getType().getClassifier()));
                }
            }
        }
        return new Construct(type, rule.getName(), List.copyOf(keywords), List.copyOf(attributes), List.copyOf(children), hasBody);
    }

    private static void leadingKeywords(AbstractElement element, List<String> into) {
        if (element instanceof Keyword k) {
            into.add(k.getValue());
        } else if (element instanceof Group g) {
            for (AbstractElement e : g.getElements()) {
                if (e instanceof Keyword || e instanceof Alternatives || e instanceof Group) {
                    leadingKeywords(e, into);
                    return;
                }
            }
        } else if (element instanceof Alternatives alternatives) {
            alternatives.getElements().forEach(e -> leadingKeywords(e, into));
        }
    }

    private static void member(AbstractElement member, List<Attribute> attributes, List<String> children) {
        if (member instanceof RuleCall call && call.getRule() instanceof ParserRule fragment && fragment.isFragment()) {
            AbstractElement body = fragment.getAlternatives();
            for (AbstractElement e : body instanceof Alternatives a ? a.getElements() : List.of(body)) {
                member(e, attributes, children);
            }
        } else if (member instanceof Assignment a && a.getTerminal() instanceof RuleCall call
                && call.getRule() instanceof ParserRule child) {
            List<String> keywords = new ArrayList<>();
            AbstractElement body = child.getAlternatives();
            for (AbstractElement e : body instanceof Group g ? g.getElements() : List.of(body)) {
                if (e instanceof Keyword || e instanceof Alternatives) {
                    leadingKeywords(e, keywords);
                    break;
                }
            }
            keywords.stream().filter(k -> !children.contains(k)).forEach(children::add);
        } else if (member instanceof Group group && group.getElements().get(0) instanceof Keyword keyword
                && group.getElements().size() > 1 && group.getElements().get(1) instanceof Assignment value) {
            attributes.add(attribute(keyword.getValue(), value, group));
        }
    }

    private static Attribute attribute(String keyword, Assignment value, Group group) {
        AbstractElement terminal = value.getTerminal();
        if (terminal instanceof CrossReference x) {
            boolean list = group.getElements().size() > 2;
            return new Attribute(keyword, value.getFeature(), list ? ValueKind.REFERENCES : ValueKind.REFERENCE, List.of(),
                    (EClass) x.getType().getClassifier());
        }
        AbstractRule rule = ((RuleCall) terminal).getRule();
        if (rule instanceof EnumRule e) {
            return new Attribute(keyword, value.getFeature(), ValueKind.ENUM, literals(e), null);
        }
        boolean withUnit = group.getElements().size() > 2 && group.getElements().get(2) instanceof Assignment unit
                && unit.getFeature().equals("timeUnit");
        ValueKind kind = switch (rule.getName()) {
            case "Integer" -> ValueKind.WHOLE_NUMBER;
            case "Real" -> withUnit ? ValueKind.TIME : ValueKind.NUMBER;
            default -> ValueKind.STRING;
        };
        return new Attribute(keyword, value.getFeature(), kind, List.of(), null);
    }

    private static List<String> literals(EnumRule rule) {
        List<String> literals = new ArrayList<>();
        for (EObject e : rule.getAlternatives() instanceof Alternatives a ? a.getElements() : List.of(rule.getAlternatives())) {
            literals.add(((EnumLiteralDeclaration) e).getLiteral().getValue());
        }
        return List.copyOf(literals);
    }

    /** "a module", "an actuator". */
    public static String article(String typeName) {
        String word = words(typeName);
        return ("aeiou".indexOf(word.charAt(0)) >= 0 ? "an " : "a ") + word;
    }

    /** "modules", "activities". */
    public static String plural(String typeName) {
        String word = words(typeName);
        return word.endsWith("y") ? word.substring(0, word.length() - 1) + "ies" : word + "s";
    }

    /** A class name as words: EntryPort → "entry port", RTAction → "rt action". */
    public static String words(String typeName) {
        return typeName.replaceAll("([a-z])([A-Z])", "$1 $2").replaceAll("([A-Z]+)([A-Z][a-z])", "$1 $2").toLowerCase(java.util.Locale.ROOT);
    }
}
