/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.Collection;
import java.util.HashSet;
import java.util.Objects;
import java.util.Set;

/**
 * What the invariants compiled from rsaml.ecore ({@code CompiledInvariants}, written by releng/org.rsaml.codegen's OclToJava) need of
 * OCL's semantics, as classic OCL's evaluator gives them: {@code invalid} (a navigation from {@code null}, an
 * undefined operand of an arithmetic or ordering operator) is the exception {@link Invalid}; {@code null} is Java's
 * {@code null}; the logical operators decide on a defined operand even when the other is undefined. The
 * interpreter stays the definition: {@code CompiledInvariantsTest} compares the two on every fixture, example and
 * random model.
 */
public final class CompiledOcl {

    private CompiledOcl() {
    }

    /** OCL's {@code invalid}: thrown, never caught but by the logical operators and the invariant's caller. */
    public static final class Invalid extends RuntimeException {
        private static final long serialVersionUID = 1L;

        private Invalid() {
            super("invalid", null, false, false);
        }
    }

    public static final Invalid INVALID = new Invalid();

    /** A deferred Boolean operand. */
    @FunctionalInterface
    public interface Operand {
        Boolean get();
    }

    /** An iterator's body. */
    @FunctionalInterface
    public interface Body<T, R> {
        R apply(T element);
    }

    /** A value navigated from: {@code invalid} when it is {@code null}. */
    public static <T> T source(T value) {
        if (value == null) {
            throw INVALID;
        }
        return value;
    }

    /** The operand's value, or {@code null} standing for both undefined values (null and invalid). */
    private static Boolean defined(Operand operand) {
        try {
            return operand.get();
        } catch (Invalid e) {
            return null;
        }
    }

    public static Boolean and(Operand left, Operand right) {
        return shortCircuit(left, Boolean.FALSE, right, Boolean.FALSE, false);
    }

    public static Boolean or(Operand left, Operand right) {
        return shortCircuit(left, Boolean.TRUE, right, Boolean.TRUE, true);
    }

    public static Boolean implies(Operand left, Operand right) {
        return shortCircuit(left, Boolean.FALSE, right, Boolean.TRUE, true);
    }

    /**
     * OCL's two-operand logic: the result is {@code decided} as soon as the left operand is {@code leftDecides} or the
     * right one is {@code rightDecides} (whatever the other, even undefined); else undefined if either operand is,
     * else the opposite of {@code decided}.
     */
    private static Boolean shortCircuit(Operand left, Boolean leftDecides, Operand right, Boolean rightDecides, boolean decided) {
        Boolean l = defined(left);
        if (leftDecides.equals(l)) {
            return decided;
        }
        Boolean r = defined(right);
        if (rightDecides.equals(r)) {
            return decided;
        }
        if (l == null || r == null) {
            throw INVALID;
        }
        return !decided;
    }

    public static Boolean not(Boolean value) {
        return !source(value);
    }

    /** The condition of an {@code if}: a Boolean, else invalid. */
    public static boolean test(Boolean condition) {
        return source(condition);
    }

    /** OCL's {@code =}: numbers by value (an Integer equals the same Real), everything else by identity or equals. */
    public static Boolean eq(Object left, Object right) {
        if (left instanceof Number l && right instanceof Number r) {
            return integral(l) && integral(r) ? l.longValue() == r.longValue() : l.doubleValue() == r.doubleValue();
        }
        return left == null ? right == null : left.equals(right);
    }

    public static Boolean ne(Object left, Object right) {
        return !eq(left, right);
    }

    /** Compares two numbers: negative, zero or positive; invalid when one is undefined. */
    private static int compare(Object left, Object right) {
        Number l = (Number) source(left);
        Number r = (Number) source(right);
        if (integral(l) && integral(r)) {
            return Long.compare(l.longValue(), r.longValue());
        }
        double a = l.doubleValue();
        double b = r.doubleValue();
        return a < b ? -1 : a > b ? 1 : a == b ? 0 : Integer.MIN_VALUE;
    }

    public static Boolean lt(Object left, Object right) {
        int c = compare(left, right);
        return c != Integer.MIN_VALUE && c < 0;
    }

    public static Boolean le(Object left, Object right) {
        int c = compare(left, right);
        return c != Integer.MIN_VALUE && c <= 0;
    }

    public static Boolean gt(Object left, Object right) {
        int c = compare(left, right);
        return c != Integer.MIN_VALUE && c > 0;
    }

    public static Boolean ge(Object left, Object right) {
        int c = compare(left, right);
        return c != Integer.MIN_VALUE && c >= 0;
    }

    public static Number minus(Object left, Object right) {
        Number l = (Number) source(left);
        Number r = (Number) source(right);
        return integral(l) && integral(r) ? (Number) Long.valueOf(l.longValue() - r.longValue()) : (Number) Double.valueOf(l.doubleValue() - r.doubleValue());
    }

    public static Number plus(Object left, Object right) {
        Number l = (Number) source(left);
        Number r = (Number) source(right);
        return integral(l) && integral(r) ? (Number) Long.valueOf(l.longValue() + r.longValue()) : (Number) Double.valueOf(l.doubleValue() + r.doubleValue());
    }

    public static Number abs(Object value) {
        Number n = (Number) source(value);
        return integral(n) ? (Number) Long.valueOf(Math.abs(n.longValue())) : (Number) Double.valueOf(Math.abs(n.doubleValue()));
    }

    /** {@code String::size()}. */
    public static Long size(String value) {
        return (long) source(value).length();
    }

    /** {@code Collection::size()}. */
    public static Long size(Collection<?> value) {
        return (long) source(value).size();
    }

    /** {@code oclAsType(T)}: the value as a {@code T}, invalid when it is not one. */
    public static <T> T as(Class<T> type, Object value) {
        if (!type.isInstance(value)) {
            throw INVALID;
        }
        return type.cast(value);
    }

    /** {@code oclIsKindOf(T)}. */
    public static Boolean isKindOf(Class<?> type, Object value) {
        return type.isInstance(source(value));
    }

    /** {@code forAll}: false at the first false, invalid at the first undefined body. */
    public static <T> Boolean forAll(Collection<? extends T> collection, Body<T, Boolean> body) {
        for (T element : source(collection)) {
            Boolean b = body.apply(element);
            if (b == null) {
                throw INVALID;
            }
            if (!b) {
                return Boolean.FALSE;
            }
        }
        return Boolean.TRUE;
    }

    /** {@code exists}: true at the first true, invalid at the first undefined body. */
    public static <T> Boolean exists(Collection<? extends T> collection, Body<T, Boolean> body) {
        for (T element : source(collection)) {
            Boolean b = body.apply(element);
            if (b == null) {
                throw INVALID;
            }
            if (b) {
                return Boolean.TRUE;
            }
        }
        return Boolean.FALSE;
    }

    /** {@code isUnique}: false at the first value seen before ({@code null} is a value). */
    public static <T> Boolean isUnique(Collection<? extends T> collection, Body<T, ?> body) {
        Collection<? extends T> elements = source(collection);
        if (elements.size() <= SMALL) {
            // most collections of a model are a few elements (or none): compared pairwise, without a set
            Object[] seen = new Object[elements.size()];
            int n = 0;
            for (T element : elements) {
                Object v = comparable(body.apply(element));
                for (int i = 0; i < n; i++) {
                    if (Objects.equals(seen[i], v)) {
                        return Boolean.FALSE;
                    }
                }
                seen[n++] = v;
            }
            return Boolean.TRUE;
        }
        Set<Object> seen = new HashSet<>();
        for (T element : elements) {
            if (!seen.add(comparable(body.apply(element)))) {
                return Boolean.FALSE;
            }
        }
        return Boolean.TRUE;
    }

    /** Up to how many elements {@link #isUnique} compares pairwise. */
    private static final int SMALL = 8;

    /** A value as {@code isUnique} compares it: an integral number as a long, any other number as a double, anything else itself. */
    private static Object comparable(Object v) {
        return v instanceof Number n ? (integral(n) ? (Object) n.longValue() : (Object) n.doubleValue()) : v;
    }

    /** {@code let v = init in body}. */
    public static <T, R> R let(T init, Body<T, R> body) {
        return body.apply(init);
    }

    private static boolean integral(Number n) {
        return n instanceof Long || n instanceof Integer || n instanceof Short || n instanceof Byte;
    }
}
