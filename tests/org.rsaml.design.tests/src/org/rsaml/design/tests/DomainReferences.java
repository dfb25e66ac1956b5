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
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;

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
 * {@code CreateInstance} change {@code self}. This class walks the specification and knows which class is at hand
 * where; {@link ExpressionReferences} checks each expression against it.
 */
final class DomainReferences {

    private static final Pattern APPLIES_TO = Pattern.compile("aql:self\\.oclIsKindOf\\(model::(\\w+)\\)");

    private final EPackage rsaml;
    private final Map<EObject, EClass> domainClasses = new HashMap<>();
    private final Set<String> problems = new TreeSet<>();
    private final ExpressionReferences expressions;

    private DomainReferences(EPackage rsaml, Class<?> services) {
        this.rsaml = rsaml;
        this.expressions = new ExpressionReferences(rsaml, services, problems);
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

    // ---------------------------------------------------------------- expressions (ExpressionReferences)

    private void expressions(EObject owner, Scope scope) {
        expressions.checkAll(owner, scope);
    }

    private EClassifier expression(EObject owner, String attribute, Scope scope) {
        return expressions.check(owner, attribute, scope);
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
}
