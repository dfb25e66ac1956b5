/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import java.util.List;
import java.util.Locale;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EDataType;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EEnumLiteral;
import org.eclipse.emf.ecore.EOperation;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EParameter;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.ocl.ParserException;
import org.eclipse.ocl.ecore.Constraint;
import org.eclipse.ocl.ecore.EcoreEnvironmentFactory;
import org.eclipse.ocl.ecore.OCL;
import org.eclipse.ocl.expressions.BooleanLiteralExp;
import org.eclipse.ocl.expressions.EnumLiteralExp;
import org.eclipse.ocl.expressions.IfExp;
import org.eclipse.ocl.expressions.IntegerLiteralExp;
import org.eclipse.ocl.expressions.IteratorExp;
import org.eclipse.ocl.expressions.LetExp;
import org.eclipse.ocl.expressions.NullLiteralExp;
import org.eclipse.ocl.expressions.OCLExpression;
import org.eclipse.ocl.expressions.OperationCallExp;
import org.eclipse.ocl.expressions.PropertyCallExp;
import org.eclipse.ocl.expressions.RealLiteralExp;
import org.eclipse.ocl.expressions.StringLiteralExp;
import org.eclipse.ocl.expressions.TypeExp;
import org.eclipse.ocl.expressions.Variable;
import org.eclipse.ocl.expressions.VariableExp;
import org.eclipse.ocl.types.CollectionType;
import org.eclipse.ocl.types.PrimitiveType;

/**
 * Translates one OCL expression tree, as classic OCL parses an invariant of rsaml.ecore, into a Java expression over
 * the EMF interfaces of the model and {@code CompiledOcl} (org.rsaml.validation), which carries OCL's semantics of
 * null, invalid and the logical operators. A construct it does not know is refused with {@link NotTranslated}.
 */
final class OclExpressionTranslator {

    private static final String MODEL = "org.rsaml.model.";

    private final OCL ocl;
    private final EPackage model;

    OclExpressionTranslator(EPackage model) {
        this.model = model;
        org.eclipse.ocl.ecore.EcorePackage.eINSTANCE.getNsURI(); // classic OCL's packages in EMF's registry
        ocl = OCL.newInstance(EcoreEnvironmentFactory.INSTANCE);
    }

    /** The invariant's body parsed by classic OCL in the context of {@code eClass}, as the interpreter parses it. */
    OCLExpression<EClassifier> parse(EClass eClass, String body) throws ParserException {
        OCL.Helper helper = ocl.createOCLHelper();
        helper.setContext(eClass);
        Constraint parsed = helper.createInvariant(body);
        return parsed.getSpecification().getBodyExpression();
    }

    /** Thrown for a construct the translator does not know; its invariant is left to the interpreter. */
    static final class NotTranslated extends Exception {
        private static final long serialVersionUID = 1L;

        NotTranslated(String message) {
            super(message);
        }
    }

    /** A Java expression and its static type. */
    record Code(String code, String type) {
    }

    /** The Java of an OCL expression; throws {@link NotTranslated} for a construct the translator does not know. */
    Code expression(OCLExpression<EClassifier> e) throws NotTranslated {
        if (e instanceof OperationCallExp<?, ?> call) {
            return operation(call);
        }
        if (e instanceof PropertyCallExp<?, ?> call) {
            @SuppressWarnings("unchecked")
            OCLExpression<EClassifier> source = (OCLExpression<EClassifier>) call.getSource();
            EStructuralFeature feature = (EStructuralFeature) call.getReferredProperty();
            Code from = expression(source);
            String getter = (isBoolean(feature.getEType()) && !feature.isMany() ? "is" : "get") + capitalised(feature.getName());
            return value(defined(source, from) + "." + getter + "()", feature.getEType(), feature.isMany(), e.getType());
        }
        if (e instanceof VariableExp<?, ?> variable) {
            String name = variable.getReferredVariable().getName();
            return new Code("self".equals(name) ? "self" : "v_" + name, javaType(e.getType()));
        }
        if (e instanceof IteratorExp<?, ?> iterator) {
            return iterator(iterator);
        }
        if (e instanceof LetExp<?, ?> let) {
            @SuppressWarnings("unchecked")
            Variable<EClassifier, ?> v = (Variable<EClassifier, ?>) let.getVariable();
            @SuppressWarnings("unchecked")
            Code init = expression((OCLExpression<EClassifier>) v.getInitExpression());
            @SuppressWarnings("unchecked")
            Code in = expression((OCLExpression<EClassifier>) let.getIn());
            return new Code("let(" + init.code + ", " + body(javaType(v.getType()), in.type, "v_" + v.getName(), in.code) + ")", in.type);
        }
        if (e instanceof IfExp<?> ifExp) {
            @SuppressWarnings("unchecked")
            IfExp<EClassifier> x = (IfExp<EClassifier>) ifExp;
            String type = javaType(e.getType());
            return new Code("(test(" + expression(x.getCondition()).code + ") ? (" + type + ") " + expression(x.getThenExpression()).code
                    + " : (" + type + ") " + expression(x.getElseExpression()).code + ")", type);
        }
        if (e instanceof IntegerLiteralExp<?> i) {
            return new Code("Long.valueOf(" + i.getLongSymbol() + "L)", "Number");
        }
        if (e instanceof RealLiteralExp<?> r) {
            return new Code("Double.valueOf(" + r.getRealSymbol() + "d)", "Number");
        }
        if (e instanceof BooleanLiteralExp<?> b) {
            return new Code(Boolean.TRUE.equals(b.getBooleanSymbol()) ? "Boolean.TRUE" : "Boolean.FALSE", "Boolean");
        }
        if (e instanceof StringLiteralExp<?> s) {
            return new Code(CompiledInvariantsWriter.literal(s.getStringSymbol()), "String");
        }
        if (e instanceof NullLiteralExp<?>) {
            return new Code("null", "Object");
        }
        if (e instanceof EnumLiteralExp<?, ?> literal) {
            EEnumLiteral l = (EEnumLiteral) literal.getReferredEnumLiteral();
            return new Code(javaClass(l.getEEnum()) + "." + constant(l.getName()), javaClass(l.getEEnum()));
        }
        throw new NotTranslated(e.eClass().getName() + " is not translated");
    }

    /** The source of a navigation, made invalid when null (self and iterator variables over EMF lists never are). */
    private static String defined(OCLExpression<EClassifier> source, Code from) {
        if (source instanceof VariableExp<?, ?> v && ("self".equals(v.getReferredVariable().getName())
                || v.getReferredVariable().eContainer() instanceof IteratorExp<?, ?>)) {
            return from.code;
        }
        return "source(" + from.code + ")";
    }

    /** A feature's or an operation's Java value as OCL sees it (numbers boxed as Long or Double). */
    private Code value(String access, EClassifier eType, boolean many, EClassifier oclType) throws NotTranslated {
        if (many) {
            return new Code(access, javaType(oclType));
        }
        Class<?> c = eType.getInstanceClass();
        if (c == int.class || c == long.class || c == short.class || c == byte.class) {
            return new Code("Long.valueOf(" + access + ")", "Number");
        }
        if (c == double.class || c == float.class) {
            return new Code("Double.valueOf(" + access + ")", "Number");
        }
        if (c == boolean.class) {
            return new Code("Boolean.valueOf(" + access + ")", "Boolean");
        }
        if (c == String.class || eType instanceof EClass || eType instanceof EEnum) {
            return new Code(access, javaType(oclType));
        }
        throw new NotTranslated("a value of type " + eType.getName() + " is not translated");
    }

    @SuppressWarnings("unchecked")
    private Code operation(OperationCallExp<?, ?> call) throws NotTranslated {
        EOperation op = (EOperation) call.getReferredOperation();
        OCLExpression<EClassifier> source = (OCLExpression<EClassifier>) call.getSource();
        List<OCLExpression<EClassifier>> args = (List<OCLExpression<EClassifier>>) (List<?>) call.getArgument();
        if (op.getEContainingClass() != null && op.getEContainingClass().getEPackage() == model) {
            Code from = expression(source);
            StringBuilder b = new StringBuilder(defined(source, from)).append('.').append(op.getName()).append('(');
            for (int i = 0; i < args.size(); i++) {
                EParameter p = op.getEParameters().get(i);
                String a = expression(args.get(i)).code;
                Class<?> c = p.getEType().getInstanceClass();
                b.append(i == 0 ? "" : ", ");
                if (c == double.class) {
                    b.append("((Number) source(").append(a).append(")).doubleValue()");
                } else if (c == int.class) {
                    b.append("((Number) source(").append(a).append(")).intValue()");
                } else if (p.getEType() instanceof EClass || c == String.class) {
                    b.append('(').append(javaType(p.getEType())).append(") ").append(a);
                } else {
                    throw new NotTranslated("a parameter of type " + p.getEType().getName() + " is not translated");
                }
            }
            return value(b.append(')').toString(), op.getEType(), op.isMany(), (EClassifier) call.getType());
        }
        String name = op.getName();
        Code s = expression(source);
        Code a = args.isEmpty() ? null : args.get(0) instanceof TypeExp<?> ? null : expression(args.get(0));
        switch (name) {
        case "and", "or", "implies":
            return new Code(name + "(" + operand(s.code) + ", " + operand(a.code) + ")", "Boolean");
        case "not":
            return new Code("not(" + s.code + ")", "Boolean");
        case "=":
            return new Code("eq(" + s.code + ", " + a.code + ")", "Boolean");
        case "<>":
            return new Code("ne(" + s.code + ", " + a.code + ")", "Boolean");
        case "<":
            return new Code("lt(" + s.code + ", " + a.code + ")", "Boolean");
        case "<=":
            return new Code("le(" + s.code + ", " + a.code + ")", "Boolean");
        case ">":
            return new Code("gt(" + s.code + ", " + a.code + ")", "Boolean");
        case ">=":
            return new Code("ge(" + s.code + ", " + a.code + ")", "Boolean");
        case "-":
            if (a != null) {
                return new Code("minus(" + s.code + ", " + a.code + ")", "Number");
            }
            break;
        case "+":
            return new Code("plus(" + s.code + ", " + a.code + ")", "Number");
        case "abs":
            return new Code("abs(" + s.code + ")", "Number");
        case "size":
            if (source.getType() instanceof CollectionType<?, ?>) {
                return new Code("size(" + s.code + ")", "Number");
            }
            return new Code("size((String) " + s.code + ")", "Number");
        case "oclIsKindOf", "oclAsType":
            if (args.get(0) instanceof TypeExp<?> t && t.getReferredType() instanceof EClass target
                    && target.getEPackage() == model) {
                return name.equals("oclIsKindOf") ? new Code("isKindOf(" + javaClass(target) + ".class, " + s.code + ")", "Boolean")
                        : new Code("as(" + javaClass(target) + ".class, " + s.code + ")", javaClass(target));
            }
            break;
        default:
            break;
        }
        throw new NotTranslated("the operation " + name + "() is not translated");
    }

    @SuppressWarnings("unchecked")
    private Code iterator(IteratorExp<?, ?> iterator) throws NotTranslated {
        String name = iterator.getName();
        if (!List.of("forAll", "exists", "isUnique").contains(name) || iterator.getIterator().size() != 1) {
            throw new NotTranslated(name + "() is not translated");
        }
        Variable<EClassifier, ?> v = (Variable<EClassifier, ?>) iterator.getIterator().get(0);
        Code source = expression((OCLExpression<EClassifier>) iterator.getSource());
        Code body = expression((OCLExpression<EClassifier>) iterator.getBody());
        return new Code(name + "(" + source.code + ", " + body(javaType(v.getType()), name.equals("isUnique") ? "Object" : "Boolean",
                "v_" + v.getName(), body.code) + ")", "Boolean");
    }

    /*
     * Deferred operands and bodies are anonymous classes, not lambdas: the class data of the command line (a CDS archive
     * on Java 17) holds both kinds of class, but each lambda is also linked at its first run through the JVM's bootstrap
     * of method handles, some 0.1 ms apiece in a fresh process, 180 of them in a validation.
     */

    /** A deferred Boolean operand ({@code CompiledOcl.Operand}) evaluating {@code code}. */
    private static String operand(String code) {
        return "new Operand() { public Boolean get() { return " + code + "; } }";
    }

    /** A body ({@code CompiledOcl.Body}) from {@code type variable} to {@code code} of type {@code result}. */
    private static String body(String type, String result, String variable, String code) {
        return "new Body<" + type + ", " + result + ">() { public " + result + " apply(" + type + " " + variable + ") { return " + code
                + "; } }";
    }

    private String javaType(EClassifier type) throws NotTranslated {
        if (type instanceof CollectionType<?, ?> c) {
            return "java.util.Collection<? extends " + javaType((EClassifier) c.getElementType()) + ">";
        }
        if (type instanceof PrimitiveType<?> p) {
            return switch (p.getName()) {
            case "Boolean" -> "Boolean";
            case "Integer", "Real", "UnlimitedNatural" -> "Number";
            case "String" -> "String";
            default -> throw new NotTranslated("the type " + p.getName() + " is not translated");
            };
        }
        if ((type instanceof EClass || type instanceof EEnum) && type.getEPackage() == model) {
            return javaClass(type);
        }
        if (type instanceof EDataType d && d.getInstanceClass() != null) {
            Class<?> c = d.getInstanceClass();
            return c == String.class ? "String" : c == boolean.class ? "Boolean" : c.isPrimitive() ? "Number" : c.getName();
        }
        if (type != null && "OclVoid".equals(type.getName())) {
            return "Object";
        }
        throw new NotTranslated("the type " + (type == null ? "null" : type.getName()) + " is not translated");
    }

    /** The Java interface or enumeration EMF generates for a classifier of the metamodel. */
    static String javaClass(EClassifier type) {
        return MODEL + type.getName();
    }

    private static boolean isBoolean(EClassifier type) {
        return type.getInstanceClass() == boolean.class;
    }

    private static String capitalised(String name) {
        return Character.toUpperCase(name.charAt(0)) + name.substring(1);
    }

    /** EMF's name of an enumeration literal's constant: {@code realTime} is {@code REAL_TIME}. */
    private static String constant(String literal) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < literal.length(); i++) {
            char c = literal.charAt(i);
            if (i > 0 && Character.isUpperCase(c) && !Character.isUpperCase(literal.charAt(i - 1))) {
                b.append('_');
            }
            b.append(c);
        }
        return b.toString().toUpperCase(Locale.ROOT);
    }
}
