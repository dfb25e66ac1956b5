/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.tests.support.models;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Random;
import java.util.Set;

import org.eclipse.emf.common.util.EList;
import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.util.EcoreUtil;

/**
 * Seeded random models, built through the metamodel (every concrete class its containments allow, every attribute
 * and reference the metamodel lets a file store), for the property tests that hold two implementations to each other:
 * the compiled invariants to classic OCL, text to XMI and back, a save to a reload. What varies between them is said
 * by {@link Values} (what attributes hold) and {@link Shape} (how much of the model is filled in, whether names are
 * apart); the same seed, values and shape give the same model. It reads the metamodel only, so it needs nothing of
 * RsaML but the package it is given.
 */
public final class RandomModels {

    /** What the attributes of a model hold. */
    public interface Values {
        /** A name, when names are kept apart ({@link Shape#namedApart()}). */
        String name(Random random);

        /** Any other string (and a name otherwise); may be {@code null}. */
        String string(Random random);

        double real(Random random);

        int integer(Random random);

        /**
         * At the edges of what validation judges: names missing, empty, repeated or too long, topics and message types
         * malformed, numbers negative, tiny, huge and rounded.
         */
        Values EDGES = new Values() {
            private static final double[] REALS = { 0, 1, 2.5, 10, 100, -1, -0.5, 1e-9, 1e9, 1e15, 1e300, Double.MAX_VALUE, 0.001 };
            private static final int[] INTS = { 0, 1, 2, 3, -1, 4, Integer.MAX_VALUE, Integer.MIN_VALUE };
            private static final String[] STRINGS = { null, "", "a", "b", "a", "x y", "/bad//topic", "~/t", "msg/Type", "\u00e9t\u00e9",
                    "n".repeat(101), "robot", "control" };

            @Override
            public String name(Random random) {
                return string(random);
            }

            @Override
            public String string(Random random) {
                return STRINGS[random.nextInt(STRINGS.length)];
            }

            @Override
            public double real(Random random) {
                double v = REALS[random.nextInt(REALS.length)];
                return random.nextBoolean() ? v : Math.rint(v * 10) / 10;
            }

            @Override
            public int integer(Random random) {
                return INTS[random.nextInt(INTS.length)];
            }
        };

        /**
         * At the edges of what a file can carry: names that are words of the textual syntax, empty, blank, quoted,
         * with escapes, line breaks, non-Latin letters, an emoji, a right-to-left override; NaN, infinities, -0, the
         * smallest and largest doubles, random magnitudes; the extreme integers.
         */
        Values ODD = new Values() {
            private static final String[] NAMES = { "a", "b", "lidarDriver", "scan", "plan", "module", "s", "ms", "NaN", "x1",
                    "caf\u00e9", "a b", "a.b", "\"quoted\"", "back\\slash", "", " ", "\u6a21\u5757", "\ud83e\udd16robot", "\u202eevil",
                    "line\nbreak", "tab\there", "_", "Z9", "type", "connect", "lifecycle", "managed" };
            private static final double[] NUMBERS = { 0, 1, 2.5, 50, 1e-9, 1e21, -1, -0.0, Double.NaN, Double.POSITIVE_INFINITY,
                    Double.NEGATIVE_INFINITY, Double.MIN_VALUE, Double.MAX_VALUE, 0.1, 1.0 / 3, 123456789012345.0, 1e15 };
            private static final int[] INTEGERS = { 0, 1, -1, 7, Integer.MAX_VALUE, Integer.MIN_VALUE };

            @Override
            public String name(Random random) {
                return NAMES[random.nextInt(NAMES.length)];
            }

            @Override
            public String string(Random random) {
                return random.nextInt(4) == 0 ? "" : name(random) + " " + name(random);
            }

            @Override
            public double real(Random random) {
                return random.nextInt(4) == 0 ? random.nextDouble() * Math.pow(10, random.nextInt(40) - 20)
                        : NUMBERS[random.nextInt(NUMBERS.length)];
            }

            @Override
            public int integer(Random random) {
                return random.nextBoolean() ? random.nextInt(100) - 10 : INTEGERS[random.nextInt(INTEGERS.length)];
            }
        };

        /** Plain values a person would write: short words, small numbers. */
        Values PLAIN = new Values() {
            private static final String[] WORDS = { "lidar", "scan", "planner", "wheels", "control", "map", "goal", "motor" };

            @Override
            public String name(Random random) {
                return WORDS[random.nextInt(WORDS.length)];
            }

            @Override
            public String string(Random random) {
                return name(random) + " " + name(random);
            }

            @Override
            public double real(Random random) {
                return 0.5 * (1 + random.nextInt(200));
            }

            @Override
            public int integer(Random random) {
                return 1 + random.nextInt(9);
            }
        };
    }

    /**
     * How much of a model is filled in.
     *
     * @param maxDepth     how deep containment goes below the root
     * @param maxChildren  the most children of one kind an element holds
     * @param unsetOneIn   an attribute is left unset one time in this many (0: every attribute is set, to a value other
     *                     than its default)
     * @param maxReferences the most targets of a many-valued reference
     * @param namedApart   every element below the root is named, apart from the other children of its container, and
     *                     references only such elements (the textual syntax and XMI's name keys name them)
     * @param everyKind    each containment holds one child of every concrete class it allows (a child of its
     *                     container's own class counts three levels), and every reference is set
     */
    public record Shape(int maxDepth, int maxChildren, int unsetOneIn, int maxReferences, boolean namedApart, boolean everyKind) {
        /** Anything the metamodel allows: unnamed and alike elements, references to anything, the root included. */
        public static final Shape ANY = new Shape(4, 3, 6, 2, false, false);
        /** Elements named apart, each attribute set or not. */
        public static final Shape NAMED_APART = new Shape(4, 3, 2, 2, true, false);
        /** Every concrete class, every attribute set to a value other than its default, every reference set. */
        public static final Shape EVERY_KIND = new Shape(4, 1, 0, 2, true, true);
    }

    private final EPackage ePackage;
    private final Random random;
    private final Values values;
    private final Shape shape;
    private final List<EObject> all = new ArrayList<>();
    private final Map<EObject, Set<String>> namesUsed = new HashMap<>();

    /**
     * A generator drawing from {@code random}: a test that makes many models from one seed passes the same
     * {@code Random} to each.
     */
    public RandomModels(EPackage ePackage, Random random, Values values, Shape shape) {
        this.ePackage = ePackage;
        this.random = random;
        this.values = values;
        this.shape = shape;
    }

    /** The model of {@code seed}: the same seed, values and shape always give the same model. */
    public static EObject model(EPackage ePackage, EClass root, long seed, Values values, Shape shape) {
        return new RandomModels(ePackage, new Random(seed), values, shape).create(root);
    }

    /** A new model whose root is an instance of {@code root}, with its references set. */
    public EObject create(EClass root) {
        all.clear();
        namesUsed.clear();
        EObject model = element(root, null, 0);
        for (EObject e : all) {
            references(e, model);
        }
        return model;
    }

    private EObject element(EClass eClass, EObject container, int depth) {
        EObject e = EcoreUtil.create(eClass);
        all.add(e);
        for (EAttribute a : eClass.getEAllAttributes()) {
            if (!a.isChangeable() || a.isDerived() || a.isTransient() || a.isMany()) {
                continue;
            }
            boolean set = shape.unsetOneIn() == 0 || random.nextInt(shape.unsetOneIn()) > 0;
            if (shape.namedApart() && isName(a)) {
                if (container != null || set) {
                    e.eSet(a, container == null ? values.name(random) : nameApart(container));
                }
            } else if (set) {
                Object value = value(a);
                if (value != null || !a.getEAttributeType().getInstanceClass().isPrimitive()) {
                    e.eSet(a, value);
                }
            }
        }
        if (depth >= shape.maxDepth()) {
            return e;
        }
        for (EReference r : eClass.getEAllContainments()) {
            if (!r.isChangeable()) {
                continue;
            }
            List<EClass> kinds = concrete(r.getEReferenceType());
            List<EClass> children = new ArrayList<>();
            if (shape.everyKind()) {
                children.addAll(r.isMany() ? kinds : kinds.subList(0, Math.min(1, kinds.size())));
            } else {
                int n = r.isMany() ? random.nextInt(depth < 2 ? shape.maxChildren() + 1 : shape.maxChildren()) : random.nextInt(2);
                for (int i = 0; i < n && !kinds.isEmpty(); i++) {
                    children.add(kinds.get(random.nextInt(kinds.size())));
                }
            }
            for (EClass kind : children) {
                EObject child = element(kind, e, depth + (shape.everyKind() && kind == eClass ? 3 : 1));
                if (r.isMany()) {
                    @SuppressWarnings("unchecked")
                    EList<EObject> list = (EList<EObject>) e.eGet(r);
                    list.add(child);
                } else {
                    e.eSet(r, child);
                }
            }
        }
        return e;
    }

    private void references(EObject e, EObject root) {
        for (EReference r : e.eClass().getEAllReferences()) {
            if (r.isContainment() || r.isContainer() || r.isDerived() || r.isTransient() || !r.isChangeable()
                    || r.getEOpposite() != null && r.getEOpposite().isContainment()) {
                continue;
            }
            List<EObject> candidates = all.stream().filter(o -> r.getEReferenceType().isInstance(o) && referable(o, root)).toList();
            if (candidates.isEmpty()) {
                continue;
            }
            if (r.isMany()) {
                @SuppressWarnings("unchecked")
                EList<EObject> list = (EList<EObject>) e.eGet(r);
                int n = shape.everyKind() ? 1 + random.nextInt(shape.maxReferences()) : random.nextInt(shape.maxReferences() + 1);
                for (int i = 0; i < n; i++) {
                    EObject o = candidates.get(random.nextInt(candidates.size()));
                    if (!list.contains(o)) {
                        list.add(o);
                    }
                }
            } else if (shape.everyKind() || random.nextInt(5) > 0) {
                e.eSet(r, candidates.get(random.nextInt(candidates.size())));
            }
        }
    }

    /** Whether a reference may name {@code o}: with names apart, only a named element below the root. */
    private boolean referable(EObject o, EObject root) {
        if (!shape.namedApart()) {
            return true;
        }
        EAttribute name = nameOf(o.eClass());
        return o != root && name != null && o.eGet(name) != null;
    }

    /** A name unused among the children of {@code container} (a number appended once a few draws have collided). */
    private String nameApart(EObject container) {
        Set<String> used = namesUsed.computeIfAbsent(container, c -> new HashSet<>());
        String name;
        int tries = 0;
        do {
            name = values.name(random) + (tries++ > 3 ? tries : "");
        } while (!used.add(name));
        return name;
    }

    private Object value(EAttribute a) {
        Object value = draw(a);
        for (int i = 0; shape.unsetOneIn() == 0 && i < 100 && Objects.equals(value, a.getDefaultValue()); i++) {
            value = draw(a);
        }
        return value;
    }

    private Object draw(EAttribute a) {
        EClassifier type = a.getEAttributeType();
        Class<?> c = type.getInstanceClass();
        if (type instanceof EEnum en) {
            return en.getELiterals().get(random.nextInt(en.getELiterals().size())).getInstance();
        }
        if (c == double.class || c == Double.class) {
            return values.real(random);
        }
        if (c == int.class || c == Integer.class) {
            return values.integer(random);
        }
        if (c == long.class || c == Long.class) {
            return (long) values.integer(random);
        }
        if (c == boolean.class || c == Boolean.class) {
            return random.nextBoolean();
        }
        if (c == String.class) {
            return values.string(random);
        }
        return null;
    }

    private List<EClass> concrete(EClass type) {
        List<EClass> result = new ArrayList<>();
        for (EClassifier c : ePackage.getEClassifiers()) {
            if (c instanceof EClass k && !k.isAbstract() && !k.isInterface() && type.isSuperTypeOf(k)) {
                result.add(k);
            }
        }
        return result;
    }

    private static boolean isName(EAttribute a) {
        return a.getName().equals("name") && a.getEAttributeType().getInstanceClass() == String.class;
    }

    private static EAttribute nameOf(EClass eClass) {
        return eClass.getEAllAttributes().stream().filter(RandomModels::isName).findFirst().orElse(null);
    }
}
