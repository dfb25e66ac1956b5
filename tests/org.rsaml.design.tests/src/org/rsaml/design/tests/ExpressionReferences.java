/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.rsaml.design.tests.SiriusSpecifications.get;
import static org.rsaml.design.tests.SiriusSpecifications.where;

import java.util.Arrays;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.rsaml.model.RsamlPackage;

/**
 * Checks one interpreted expression of a Sirius specification ({@code var:}, {@code feature:}, {@code aql:},
 * {@code service:}) against rsaml.ecore and the viewpoint's Java services, given the variables in {@link Scope}:
 * every navigation a chain of features followed class by class, every {@code model::Type} a classifier, every
 * service a public method that takes the element it is called on. {@link DomainReferences} tells it the scope.
 */
final class ExpressionReferences {

    /** AQL's own services on objects; anything else called on an RsaML element must be a Java service. */
    private static final Set<String> AQL_SERVICES = Set.of("eContainer", "eContents", "eAllContents", "eClass", "eGet",
            "eInverse", "eResource", "eContainingFeature", "eContainmentFeature", "eCrossReferences", "ancestors",
            "siblings", "precedingSiblings", "followingSiblings", "oclIsKindOf", "oclIsTypeOf", "oclAsType", "toString",
            "trace");
    /** Sirius's {@code feature:} interpreter knows these besides the class's own features. */
    private static final Set<String> SPECIAL_FEATURES = Set.of("eContainer", "eContents", "eAllContents", "eClass",
            "eCrossReferences");
    /** Variables that hold views, not RsaML elements: known to Sirius, nothing to check here. */
    private static final Set<String> VIEW_VARIABLES = Set.of("diagram", "view", "containerView", "sourceView", "targetView",
            "elementView", "viewpoint", "preSourceView", "preTargetView");
    private static final Pattern STRING_LITERAL = Pattern.compile("'(?:[^'\\\\]|\\\\.)*'");
    private static final Pattern TYPE_LITERAL = Pattern.compile("\\b([A-Za-z_]\\w*)::([A-Za-z_]\\w*)(?:::([A-Za-z_]\\w*))?");
    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_]\\w*");
    private static final Pattern NUMBER = Pattern.compile("-?\\d+(\\.\\d+)?");

    private final EPackage rsaml;
    private final Class<?> services;
    private final Set<String> problems;

    /** Problems found are added to {@code problems}. */
    ExpressionReferences(EPackage rsaml, Class<?> services, Set<String> problems) {
        this.rsaml = rsaml;
        this.services = services;
        this.problems = problems;
    }

    /** Checks every interpreted expression held by one element. */
    void checkAll(EObject owner, Scope scope) {
        for (var attribute : owner.eClass().getEAllAttributes()) {
            if ("InterpretedExpression".equals(attribute.getEAttributeType().getName())) {
                check(owner, attribute.getName(), scope);
            }
        }
    }

    /** Checks one expression and returns the RsaML classifier it yields, when that can be told. */
    EClassifier check(EObject owner, String attribute, Scope scope) {
        Object value = get(owner, attribute);
        if (!(value instanceof String text) || text.isBlank()) {
            return null;
        }
        String at = where(owner) + " " + attribute;
        if (text.startsWith("var:")) {
            String name = text.substring(4).trim();
            if (scope.has(name)) {
                return scope.get(name);
            }
            if (!VIEW_VARIABLES.contains(name)) {
                problems.add(at + ": '" + text + "' names no variable known there (" + scope.names() + ")");
            }
            return null;
        }
        if (text.startsWith("feature:")) {
            String name = text.substring(8).trim();
            if (scope.self() == null || SPECIAL_FEATURES.contains(name)) {
                return null;
            }
            EStructuralFeature feature = scope.self().getEStructuralFeature(name);
            if (feature == null) {
                problems.add(at + ": '" + text + "': " + scope.self().getName() + " has no feature '" + name + "'");
                return null;
            }
            return feature.getEType();
        }
        if (text.startsWith("aql:")) {
            return aql(at, text, text.substring(4), scope);
        }
        if (text.startsWith("service:")) {
            String name = text.substring(8).replaceAll("\\(.*", "").trim();
            if (!isService(name)) {
                problems.add(at + ": '" + text + "' calls '" + name + "', which is not a method of the viewpoint's Java services");
            } else {
                receiver(at, text, name, scope.self());
            }
            return null;
        }
        if (!NUMBER.matcher(text.trim()).matches()) {
            problems.add(at + ": '" + text + "' is not an aql:, feature:, var: or service: expression, so it is not checked");
        }
        return null;
    }

    private EClassifier aql(String at, String text, String body, Scope scope) {
        if (scope.has(body.trim())) {
            return scope.get(body.trim()); // a view's end whose element class the tool knows (elementView.targetNode.target)
        }
        String code = STRING_LITERAL.matcher(body).replaceAll("''");
        Matcher literal = TYPE_LITERAL.matcher(code);
        while (literal.find()) {
            typeLiteral(at, text, literal.group(1), literal.group(2), literal.group(3));
        }
        EClassifier whole = null;
        boolean navigationOnly = code.trim().matches("[A-Za-z_]\\w*(\\s*\\.\\s*[A-Za-z_]\\w*)*");
        Matcher head = IDENTIFIER.matcher(code);
        while (head.find()) {
            char before = previousChar(code, head.start());
            if (before == '.' || before == ':' || !scope.has(head.group())) {
                continue;
            }
            EClassifier type = navigation(at, text, code, head.end(), scope.get(head.group()));
            if (navigationOnly) {
                whole = type;
            }
        }
        return whole;
    }

    /** Follows {@code .step.step} from {@code from}, checking each step against the class reached so far. */
    private EClassifier navigation(String at, String text, String code, int position, EClassifier type) {
        int i = position;
        while (true) {
            int dot = skipSpaces(code, i);
            if (dot >= code.length() || code.charAt(dot) != '.') {
                return type;
            }
            Matcher step = IDENTIFIER.matcher(code).region(skipSpaces(code, dot + 1), code.length());
            if (!step.lookingAt()) {
                return type;
            }
            String name = step.group();
            int after = skipSpaces(code, step.end());
            boolean call = after < code.length() && code.charAt(after) == '(';
            if (type == null) {
                return null;
            }
            if (!(type instanceof EClass eClass)) {
                if (call && isService(name)) {
                    receiver(at, text, name, type);
                } else if (!call) {
                    problems.add(at + ": '" + text + "' navigates to '" + name + "' from a " + type.getName()
                            + " value, which has no features");
                }
                return null;
            }
            if (call) {
                if (isService(name)) {
                    receiver(at, text, name, eClass);
                } else if (!AQL_SERVICES.contains(name)) {
                    problems.add(at + ": '" + text + "' calls '" + name
                            + "', which is neither an AQL service nor a method of the viewpoint's Java services");
                }
                return null;
            }
            EStructuralFeature feature = eClass.getEStructuralFeature(name);
            if (feature == null) {
                problems.add(at + ": '" + text + "': " + eClass.getName() + " has no feature '" + name + "'");
                return null;
            }
            type = feature.getEType();
            i = step.end();
        }
    }

    /** Whether the Java services class has a public method of that name (AQL calls any of them). */
    private boolean isService(String name) {
        return Arrays.stream(services.getMethods()).anyMatch(m -> m.getName().equals(name) && m.getDeclaringClass() != Object.class);
    }

    /** AQL passes the receiver as the service's first argument: some method of the name must take it. */
    private void receiver(String at, String text, String name, EClassifier type) {
        Class<?> instance = instanceClass(type);
        if (instance == null) {
            return;
        }
        boolean takes = Arrays.stream(services.getMethods()).anyMatch(m -> m.getName().equals(name) && m.getParameterCount() >= 1
                && m.getParameterTypes()[0].isAssignableFrom(instance));
        if (!takes) {
            problems.add(at + ": '" + text + "' calls '" + name + "' on " + type.getName() + ", which no method '" + name
                    + "' of the viewpoint's Java services takes");
        }
    }

    /** The Java class of an RsaML classifier (rsaml.ecore is read as a dynamic package here) or of an Ecore data type. */
    private static Class<?> instanceClass(EClassifier type) {
        if (type == null) {
            return null;
        }
        EClassifier generated = type.getEPackage() != null && RsamlPackage.eNS_URI.equals(type.getEPackage().getNsURI())
                ? RsamlPackage.eINSTANCE.getEClassifier(type.getName()) : type;
        return generated == null ? null : generated.getInstanceClass();
    }

    private void typeLiteral(String at, String text, String ePackage, String classifier, String literal) {
        if (!ePackage.equals(rsaml.getName())) {
            problems.add(at + ": '" + text + "' names package '" + ePackage + "', but rsaml.ecore's package is called '"
                    + rsaml.getName() + "'");
            return;
        }
        EClassifier found = rsaml.getEClassifier(classifier);
        if (found == null) {
            problems.add(at + ": '" + text + "': rsaml.ecore has no classifier '" + classifier + "'");
        } else if (literal != null && !(found instanceof EEnum e && e.getEEnumLiteral(literal) != null)) {
            problems.add(at + ": '" + text + "': " + classifier + " has no literal '" + literal + "'");
        }
    }

    private static char previousChar(String code, int index) {
        int i = index - 1;
        while (i >= 0 && Character.isWhitespace(code.charAt(i))) {
            i--;
        }
        return i < 0 ? ' ' : code.charAt(i);
    }

    private static int skipSpaces(String code, int index) {
        int i = index;
        while (i < code.length() && Character.isWhitespace(code.charAt(i))) {
            i++;
        }
        return i;
    }
}
