/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.Enumerator;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.rsaml.design.services.RsamlServices;
import org.rsaml.model.RsamlPackage;

/**
 * Evaluates the expressions of rsaml.odesign on RsaML models as Sirius would, so that a test can say
 * what a diagram shows for an element instead of how the expression is spelled. It knows the part of
 * AQL and Sirius's {@code feature:} interpreter the specification uses: variables, navigation (on a
 * collection, collected), calls of the viewpoint's Java services, {@code ->sortedBy}, {@code ->reverse},
 * {@code ->filter}, {@code ->size}, {@code +}, {@code =}, string and number literals and
 * {@code model::Type::literal}. Anything else is refused, never guessed.
 */
final class Expressions {

    private final RsamlServices services = new RsamlServices();
    private final Map<String, Object> variables;
    private String text;
    private int at;

    private Expressions(Map<String, Object> variables) {
        this.variables = variables;
    }

    /** The value of {@code expression} ({@code aql:...} or {@code feature:...}) with {@code self} bound to {@code self}. */
    static Object evaluate(Object expression, EObject self) {
        return evaluate(expression, Map.of("self", self));
    }

    static Object evaluate(Object expression, Map<String, Object> variables) {
        String source = String.valueOf(expression);
        Expressions e = new Expressions(variables);
        if (source.startsWith("feature:")) {
            return e.navigate(variables.get("self"), source.substring("feature:".length()).trim());
        }
        if (!source.startsWith("aql:")) {
            throw new IllegalArgumentException("not an aql: or feature: expression: " + source);
        }
        e.text = source.substring(4);
        e.at = 0;
        Object value = e.equality();
        e.skip();
        if (e.at != e.text.length()) {
            throw e.unsupported();
        }
        return value;
    }

    private Object equality() {
        Object left = concatenation();
        if (eat("<>")) {
            return !same(left, concatenation());
        }
        if (eat("=")) {
            return same(left, concatenation());
        }
        return left;
    }

    private Object concatenation() {
        Object value = postfix();
        while (eat("+")) {
            Object right = postfix();
            value = value instanceof Number a && right instanceof Number b ? a.intValue() + b.intValue() : string(value) + string(right);
        }
        return value;
    }

    private Object postfix() {
        Object value = primary();
        while (true) {
            if (eat("->")) {
                value = collectionCall(value, identifier());
            } else if (eat(".")) {
                String name = identifier();
                if (eat("(")) {
                    if (name.equals("eAllContents")) {
                        EClassifier type = eat(")") ? null : (EClassifier) primary();
                        if (type != null) {
                            expect(")");
                        }
                        value = contents(value, type);
                    } else {
                        expect(")");
                        value = service(value, name);
                    }
                } else {
                    value = navigate(value, name);
                }
            } else {
                return value;
            }
        }
    }

    private Object primary() {
        skip();
        if (eat("(")) {
            Object value = equality();
            expect(")");
            return value;
        }
        if (peek('\'')) {
            int end = text.indexOf('\'', at + 1);
            String literal = text.substring(at + 1, end);
            at = end + 1;
            return literal;
        }
        if (at < text.length() && Character.isDigit(text.charAt(at))) {
            int start = at;
            while (at < text.length() && Character.isDigit(text.charAt(at))) {
                at++;
            }
            return Integer.parseInt(text.substring(start, at));
        }
        String name = identifier();
        if (eat("::")) {
            EClassifier classifier = RsamlPackage.eINSTANCE.getEClassifier(identifier());
            if (!name.equals(RsamlPackage.eINSTANCE.getName()) || classifier == null) {
                throw unsupported();
            }
            return eat("::") && classifier instanceof EEnum e ? e.getEEnumLiteral(identifier()).getInstance() : classifier;
        }
        if (!variables.containsKey(name)) {
            throw unsupported();
        }
        return variables.get(name);
    }

    private Object collectionCall(Object receiver, String name) {
        List<Object> items = items(receiver);
        expect("(");
        Object result;
        switch (name) {
            case "reverse" -> {
                List<Object> reversed = new ArrayList<>(items);
                java.util.Collections.reverse(reversed);
                result = reversed;
            }
            case "size" -> result = items.size();
            case "filter" -> {
                EClassifier type = (EClassifier) primary();
                result = items.stream().filter(type::isInstance).toList();
            }
            case "sortedBy" -> {
                String variable = identifier();
                expect("|");
                int body = at;
                List<Object> sorted = new ArrayList<>(items);
                // The lambda's body is evaluated per item, from the same place in the text.
                Map<Object, Object> keys = new java.util.IdentityHashMap<>();
                for (Object item : items) {
                    Map<String, Object> scope = new java.util.HashMap<>(variables);
                    scope.put(variable, item);
                    Expressions lambda = new Expressions(scope);
                    lambda.text = text;
                    lambda.at = body;
                    keys.put(item, lambda.equality());
                    at = lambda.at;
                }
                sorted.sort(Comparator.comparing(item -> (Comparable<Object>) keys.get(item)));
                result = sorted;
            }
            default -> throw unsupported();
        }
        expect(")");
        return result;
    }

    /** A feature of an element, or of each element of a collection (AQL collects implicitly). */
    private Object navigate(Object receiver, String name) {
        if (receiver instanceof Collection<?> many) {
            List<Object> values = new ArrayList<>();
            for (Object item : many) {
                Object value = navigate(item, name);
                if (value instanceof Collection<?> c) {
                    values.addAll(c);
                } else if (value != null) {
                    values.add(value);
                }
            }
            return values;
        }
        if (!(receiver instanceof EObject element)) {
            throw new IllegalArgumentException("'" + name + "' of " + receiver + ", which is not a model element");
        }
        EClass eClass = element.eClass();
        EStructuralFeature feature = eClass.getEStructuralFeature(name);
        if (feature == null) {
            throw new IllegalArgumentException(eClass.getName() + " has no feature '" + name + "'");
        }
        return element.eGet(feature);
    }

    /** Everything an element (or each element of a collection) contains, of a type if one is given. */
    private static List<Object> contents(Object receiver, EClassifier type) {
        List<Object> all = new ArrayList<>();
        for (Object item : items(receiver)) {
            ((EObject) item).eAllContents().forEachRemaining(e -> {
                if (type == null || type.isInstance(e)) {
                    all.add(e);
                }
            });
        }
        return all;
    }

    /** A call of the viewpoint's Java services, as AQL makes it: the receiver is the first argument. */
    private Object service(Object receiver, String name) {
        if (receiver instanceof Collection<?> many) {
            return many.stream().map(item -> service(item, name)).toList();
        }
        for (Method method : RsamlServices.class.getMethods()) {
            if (method.getName().equals(name) && method.getParameterCount() == 1 && method.getParameterTypes()[0].isInstance(receiver)) {
                try {
                    return method.invoke(services, receiver);
                } catch (IllegalAccessException | InvocationTargetException e) {
                    throw new IllegalStateException(name + " failed on " + receiver, e);
                }
            }
        }
        throw new IllegalArgumentException("no service " + name + " for " + receiver);
    }

    private static boolean same(Object left, Object right) {
        if (left instanceof Enumerator a && right instanceof Enumerator b) {
            return a.getLiteral().equals(b.getLiteral());
        }
        return java.util.Objects.equals(left, right);
    }

    private static String string(Object value) {
        return value instanceof Enumerator e ? e.getLiteral() : String.valueOf(value);
    }

    private static List<Object> items(Object value) {
        return value instanceof Collection<?> c ? new ArrayList<>(c) : value == null ? List.of() : List.of(value);
    }

    private String identifier() {
        skip();
        int start = at;
        while (at < text.length() && (Character.isLetterOrDigit(text.charAt(at)) || text.charAt(at) == '_')) {
            at++;
        }
        if (start == at) {
            throw unsupported();
        }
        return text.substring(start, at);
    }

    private boolean eat(String token) {
        skip();
        if (text.startsWith(token, at)) {
            at += token.length();
            return true;
        }
        return false;
    }

    private void expect(String token) {
        if (!eat(token)) {
            throw unsupported();
        }
    }

    private boolean peek(char c) {
        skip();
        return at < text.length() && text.charAt(at) == c;
    }

    private void skip() {
        while (at < text.length() && Character.isWhitespace(text.charAt(at))) {
            at++;
        }
    }

    private IllegalArgumentException unsupported() {
        return new IllegalArgumentException("not understood at " + at + ": aql:" + text);
    }
}
