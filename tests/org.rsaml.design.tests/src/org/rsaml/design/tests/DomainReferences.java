/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.rsaml.design.tests.SiriusSpecifications.get;
import static org.rsaml.design.tests.SiriusSpecifications.is;
import static org.rsaml.design.tests.SiriusSpecifications.list;
import static org.rsaml.design.tests.SiriusSpecifications.ref;
import static org.rsaml.design.tests.SiriusSpecifications.where;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.rsaml.model.RsamlPackage;

/**
 * Checks that a Sirius specification speaks of RsaML as rsaml.ecore defines it: every domain class,
 * type and target class is an EClass of rsaml.ecore, every {@code feature:} and {@code featureName}
 * a feature of the class at hand, every {@code aql:} navigation ({@code self.layer.architecture})
 * a chain of features followed class by class, every {@code model::Type} a classifier, and every
 * service called a public method of the viewpoint's Java services class that takes the element it is
 * called on.
 *
 * <p>"The class at hand" follows Sirius's rules: a mapping's candidates are computed on its parent's
 * element, its styles on its own element; an element-based edge finds its ends from its own element,
 * a relation-based edge from its source's; a creation tool's {@code container}, {@code source} and
 * {@code target} are the elements of the views it is used on; {@code ChangeContext} and
 * {@code CreateInstance} change {@code self}.
 */
final class DomainReferences {

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
    private static final Pattern APPLIES_TO = Pattern.compile("aql:self\\.oclIsKindOf\\(model::(\\w+)\\)");
    private static final Pattern NUMBER = Pattern.compile("-?\\d+(\\.\\d+)?");

    private final EPackage rsaml;
    private final Class<?> services;
    private final Map<EObject, EClass> domainClasses = new HashMap<>();
    private final Set<String> problems = new TreeSet<>();

    private DomainReferences(EPackage rsaml, Class<?> services) {
        this.rsaml = rsaml;
        this.services = services;
    }

    /** The problems of a loaded specification, sorted; {@code services} is the class of its Java services. */
    static List<String> check(SiriusSpecifications.Loaded specification, Class<?> services) {
        DomainReferences checker = new DomainReferences(specification.rsaml(), services);
        for (EObject viewpoint : list(specification.group(), "ownedViewpoints")) {
            for (EObject representation : list(viewpoint, "ownedRepresentations")) {
                if (is(representation, "DiagramDescription")) {
                    checker.diagram(representation);
                } else {
                    checker.problems.add(where(representation) + ": a " + representation.eClass().getName()
                            + " is not checked here; only diagrams are");
                }
            }
        }
        return new ArrayList<>(checker.problems);
    }

    private void diagram(EObject diagram) {
        EClass root = eClass(diagram, "domainClass");
        Scope scope = Scope.of("self", root);
        expression(diagram, "titleExpression", scope);
        expression(diagram, "preconditionExpression", scope);
        List<EObject> layers = new ArrayList<>(list(diagram, "additionalLayers"));
        if (ref(diagram, "defaultLayer") != null) {
            layers.add(0, ref(diagram, "defaultLayer"));
        }
        for (EObject layer : layers) {
            for (EObject mapping : concat(list(layer, "nodeMappings"), list(layer, "containerMappings"))) {
                nodeMapping(mapping, root, root);
            }
        }
        // Edges and tools name mappings anywhere in the diagram: read every mapping's class first.
        for (EObject layer : layers) {
            for (EObject edge : list(layer, "edgeMappings")) {
                edgeMapping(edge, root);
            }
            for (EObject section : list(layer, "toolSections")) {
                toolSection(section, root);
            }
            EObject decorations = ref(layer, "decorationDescriptionsSet");
            if (decorations != null) {
                for (EObject decoration : list(decorations, "decorationDescriptions")) {
                    Scope target = Scope.of("self", eClass(decoration, "domainClass"));
                    expression(decoration, "preconditionExpression", target);
                    expression(decoration, "tooltipExpression", target);
                }
            }
        }
    }

    private void nodeMapping(EObject mapping, EClass parent, EClass root) {
        EClass domain = eClass(mapping, "domainClass");
        domainClasses.put(mapping, domain);
        expression(mapping, "semanticCandidatesExpression", Scope.of("self", parent));
        expression(mapping, "preconditionExpression", Scope.of("self", domain, "container", parent));
        Scope own = Scope.of("self", domain);
        expression(mapping, "semanticElements", own);
        styles(mapping, own);
        for (String children : List.of("borderedNodeMappings", "subNodeMappings", "subContainerMappings")) {
            if (mapping.eClass().getEStructuralFeature(children) != null) {
                for (EObject child : list(mapping, children)) {
                    nodeMapping(child, domain, root);
                }
            }
        }
    }

    private void edgeMapping(EObject edge, EClass root) {
        List<EClass> sources = mappedClasses(edge, "sourceMapping");
        List<EClass> targets = mappedClasses(edge, "targetMapping");
        if (get(edge, "domainClass") != null) {
            EClass domain = eClass(edge, "domainClass");
            expression(edge, "semanticCandidatesExpression", Scope.of("self", root));
            Scope own = Scope.of("self", domain);
            conforms(edge, "sourceFinderExpression", expression(edge, "sourceFinderExpression", own), sources);
            conforms(edge, "targetFinderExpression", expression(edge, "targetFinderExpression", own), targets);
            styles(edge, own);
        } else {
            if (sources.size() == 1) {
                // A relation's edge stands for its source element: that is what its delete tool gets as 'element'.
                domainClasses.put(edge, sources.get(0));
            }
            for (EClass source : sources) {
                Scope own = Scope.of("self", source);
                conforms(edge, "targetFinderExpression", expression(edge, "targetFinderExpression", own), targets);
                styles(edge, own);
            }
        }
    }

    /** The style and conditional styles of a mapping: every expression in them is computed on the mapping's element. */
    private void styles(EObject mapping, Scope own) {
        List<EObject> styles = new ArrayList<>();
        if (ref(mapping, "style") != null) {
            styles.add(ref(mapping, "style"));
        }
        for (EObject conditional : list(mapping, "conditionnalStyles")) {
            expression(conditional, "predicateExpression", own);
            if (ref(conditional, "style") != null) {
                styles.add(ref(conditional, "style"));
            }
        }
        for (EObject style : styles) {
            expressions(style, own);
            for (EObject inner : (Iterable<EObject>) style::eAllContents) {
                expressions(inner, own);
            }
        }
    }

    private void toolSection(EObject section, EClass root) {
        for (EObject tool : list(section, "ownedTools")) {
            tool(tool, root);
        }
        for (EObject sub : list(section, "subSections")) {
            toolSection(sub, root);
        }
    }

    private void tool(EObject tool, EClass root) {
        Scope scope;
        if (is(tool, "NodeCreationDescription") || is(tool, "ContainerCreationDescription")) {
            List<EObject> created = list(tool, is(tool, "NodeCreationDescription") ? "nodeMappings" : "containerMappings");
            EClass container = common(tool, "the container of " + names(created), created.stream().map(m -> parentClass(m, root)).toList());
            scope = Scope.of("self", container, name(ref(tool, "variable"), "container"), container);
        } else if (is(tool, "EdgeCreationDescription")) {
            List<EObject> edges = list(tool, "edgeMappings");
            EClass source = common(tool, "the sources of " + names(edges),
                    edges.stream().flatMap(e -> mappedClasses(e, "sourceMapping").stream()).toList());
            EClass target = common(tool, "the targets of " + names(edges),
                    edges.stream().flatMap(e -> mappedClasses(e, "targetMapping").stream()).toList());
            expression(tool, "precondition", Scope.of("preSource", source, "preTarget", target));
            scope = Scope.of("self", source, name(ref(tool, "sourceVariable"), "source"), source,
                    name(ref(tool, "targetVariable"), "target"), target);
        } else if (is(tool, "DeleteElementDescription")) {
            List<EClass> deleted = domainClasses.entrySet().stream().filter(e -> ref(e.getKey(), "deletionDescription") == tool)
                    .map(Map.Entry::getValue).toList();
            if (deleted.isEmpty()) {
                problems.add(where(tool) + ": no mapping deletes its elements with this tool");
                return;
            }
            EClass element = common(tool, "the elements it deletes", deleted);
            scope = Scope.of("self", element, name(ref(tool, "element"), "element"), element);
            // Deleting an edge: its view's ends hold the elements of its source and target mappings.
            List<EObject> edges = domainClasses.keySet().stream().filter(m -> ref(m, "deletionDescription") == tool)
                    .filter(m -> is(m, "EdgeMapping")).toList();
            if (!edges.isEmpty()) {
                String view = name(ref(tool, "elementView"), "elementView");
                scope = scope.with(view + ".sourceNode.target", common(tool, "the sources of " + names(edges),
                        edges.stream().flatMap(e -> mappedClasses(e, "sourceMapping").stream()).toList()));
                scope = scope.with(view + ".targetNode.target", common(tool, "the targets of " + names(edges),
                        edges.stream().flatMap(e -> mappedClasses(e, "targetMapping").stream()).toList()));
            }
        } else if (is(tool, "ToolDescription")) {
            // A tool applied to the element clicked: its precondition names the class it applies to.
            Matcher kind = APPLIES_TO.matcher(String.valueOf(get(tool, "precondition")));
            EClassifier element = kind.matches() ? rsaml.getEClassifier(kind.group(1)) : null;
            if (!(element instanceof EClass eClass)) {
                problems.add(where(tool) + ": cannot tell which RsaML class the tool applies to; its precondition must be "
                        + "'aql:self.oclIsKindOf(model::<Class>)' naming a class of rsaml.ecore");
                return;
            }
            scope = Scope.of("self", eClass, name(ref(tool, "element"), "element"), eClass);
        } else {
            problems.add(where(tool) + ": a " + tool.eClass().getName() + " is not checked here; only creation, deletion and generic tools are");
            return;
        }
        if (!is(tool, "EdgeCreationDescription")) {
            expression(tool, "precondition", scope);
        }
        EObject initial = ref(tool, "initialOperation");
        if (initial != null) {
            operations(List.of(ref(initial, "firstModelOperations")), scope);
        }
    }

    private void operations(List<EObject> operations, Scope scope) {
        for (EObject operation : operations) {
            Scope inner = scope;
            if (is(operation, "ChangeContext")) {
                EClassifier context = expression(operation, "browseExpression", scope);
                if (!(context instanceof EClass eClass)) {
                    problems.add(where(operation) + ": cannot tell which RsaML class '" + get(operation, "browseExpression")
                            + "' leads to, so the operations inside are not checked");
                    continue;
                }
                inner = scope.with("self", eClass);
            } else if (is(operation, "CreateInstance")) {
                EClass type = eClass(operation, "typeName");
                EStructuralFeature reference = feature(operation, "referenceName", scope.self());
                if (type != null && type.isAbstract()) {
                    problems.add(where(operation) + ": '" + get(operation, "typeName") + "' is abstract and cannot be created");
                }
                if (reference != null && !(reference instanceof EReference r && r.isContainment())) {
                    problems.add(where(operation) + ": '" + reference.getName() + "' of " + scope.self().getName()
                            + " does not contain elements; a created element needs a containment reference");
                } else if (reference != null && type != null && !((EClass) reference.getEType()).isSuperTypeOf(type)) {
                    problems.add(where(operation) + ": '" + reference.getName() + "' holds " + reference.getEType().getName()
                            + " elements, not " + type.getName());
                }
                inner = scope.with("self", type).with(variable(operation), type);
            } else if (is(operation, "MoveElement")) {
                // The feature is the new container's, not the moved element's.
                EClassifier container = expression(operation, "newContainerExpression", scope);
                if (container instanceof EClass eClass) {
                    feature(operation, "featureName", eClass);
                }
            } else if (is(operation, "For")) {
                EClassifier each = expression(operation, "expression", scope);
                inner = scope.with(String.valueOf(get(operation, "iteratorName")), each instanceof EClass eClass ? eClass : null);
            } else if (is(operation, "SetValue")) {
                EStructuralFeature feature = feature(operation, "featureName", scope.self());
                EClassifier value = expression(operation, "valueExpression", scope);
                if (feature instanceof EReference && value instanceof EClass valueClass
                        && !((EClass) feature.getEType()).isSuperTypeOf(valueClass)) {
                    problems.add(where(operation) + ": '" + feature.getName() + "' takes " + feature.getEType().getName()
                            + ", but '" + get(operation, "valueExpression") + "' is a " + valueClass.getName());
                }
            } else {
                expressions(operation, scope);
                if (operation.eClass().getEStructuralFeature("featureName") != null) {
                    feature(operation, "featureName", scope.self());
                }
            }
            if (operation.eClass().getEStructuralFeature("subModelOperations") != null) {
                operations(list(operation, "subModelOperations"), inner);
            }
        }
    }

    // ---------------------------------------------------------------- expressions

    /** Checks every interpreted expression held by one element. */
    private void expressions(EObject owner, Scope scope) {
        for (var attribute : owner.eClass().getEAllAttributes()) {
            if ("InterpretedExpression".equals(attribute.getEAttributeType().getName())) {
                expression(owner, attribute.getName(), scope);
            }
        }
    }

    /** Checks one expression and returns the RsaML classifier it yields, when that can be told. */
    private EClassifier expression(EObject owner, String attribute, Scope scope) {
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

    // ---------------------------------------------------------------- classes and features

    /**
     * The EClass a type name denotes. Sirius qualifies classes by their EPackage's name
     * ({@code model.Layer} or {@code model::Layer}), not by its nsPrefix.
     */
    private EClass eClass(EObject owner, String attribute) {
        Object value = get(owner, attribute);
        String at = where(owner) + " " + attribute;
        if (!(value instanceof String name) || name.isBlank()) {
            problems.add(at + ": no class given");
            return null;
        }
        String[] parts = name.split("::|\\.");
        if (parts.length == 2 && !parts[0].equals(rsaml.getName())) {
            problems.add(at + ": '" + name + "' names package '" + parts[0] + "', but rsaml.ecore's package is called '"
                    + rsaml.getName() + "'");
            return null;
        }
        EClassifier classifier = parts.length <= 2 ? rsaml.getEClassifier(parts[parts.length - 1]) : null;
        if (!(classifier instanceof EClass eClass)) {
            problems.add(at + ": '" + name + "' is not a class of rsaml.ecore");
            return null;
        }
        return eClass;
    }

    private EStructuralFeature feature(EObject owner, String attribute, EClass of) {
        Object name = get(owner, attribute);
        if (of == null || !(name instanceof String featureName)) {
            return null;
        }
        EStructuralFeature feature = of.getEStructuralFeature(featureName);
        if (feature == null) {
            problems.add(where(owner) + " " + attribute + ": " + of.getName() + " has no feature '" + featureName + "'");
        }
        return feature;
    }

    private void conforms(EObject edge, String attribute, EClassifier found, List<EClass> mapped) {
        if (found instanceof EClass eClass && !mapped.isEmpty()
                && mapped.stream().noneMatch(c -> c.isSuperTypeOf(eClass) || eClass.isSuperTypeOf(c))) {
            problems.add(where(edge) + " " + attribute + ": '" + get(edge, attribute) + "' yields " + eClass.getName()
                    + ", which none of its mappings shows (" + mapped.stream().map(EClass::getName).toList() + ")");
        }
    }

    private EClass parentClass(EObject mapping, EClass root) {
        EObject parent = mapping.eContainer();
        return parent != null && domainClasses.containsKey(parent) ? domainClasses.get(parent) : root;
    }

    private List<EClass> mappedClasses(EObject edge, String attribute) {
        List<EClass> classes = new ArrayList<>();
        for (EObject mapping : list(edge, attribute)) {
            EClass eClass = domainClasses.get(mapping);
            if (eClass != null) {
                classes.add(eClass);
            }
        }
        return classes;
    }

    private EClass common(EObject tool, String what, List<EClass> classes) {
        if (classes.isEmpty() || classes.contains(null)) {
            return null;
        }
        if (classes.stream().distinct().count() > 1) {
            problems.add(where(tool) + ": " + what + " are of different classes " + classes.stream().map(EClass::getName).toList());
            return null;
        }
        return classes.get(0);
    }

    // ---------------------------------------------------------------- helpers

    private static String name(EObject variable, String fallback) {
        Object name = variable == null ? null : get(variable, "name");
        return name instanceof String s && !s.isBlank() ? s : fallback;
    }

    private static String variable(EObject createInstance) {
        return get(createInstance, "variableName") instanceof String s && !s.isBlank() ? s : "instance";
    }

    private static String names(List<EObject> objects) {
        return objects.stream().map(o -> String.valueOf(get(o, "name"))).toList().toString();
    }

    private static List<EObject> concat(List<EObject> a, List<EObject> b) {
        List<EObject> all = new ArrayList<>(a);
        all.addAll(b);
        return all;
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

    /** The variables an expression can use, with the RsaML class of each (null when it cannot be told). */
    private record Scope(Map<String, EClass> variables) {
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
}
