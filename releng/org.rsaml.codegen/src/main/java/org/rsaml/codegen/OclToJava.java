/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAnnotation;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EDataType;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EEnumLiteral;
import org.eclipse.emf.ecore.EOperation;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EParameter;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
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
 * The build-time translator of the invariants of rsaml.ecore into Java for org.rsaml.validation: each invariant's text is parsed by classic OCL
 * (as the interpreter parses it) and its expression tree written as a Java method of {@code CompiledInvariants}
 * ({@code src-gen/} of this bundle), with OCL's semantics of null, invalid and the logical operators taken from
 * {@code CompiledOcl} (org.rsaml.validation). The generated class records each invariant's text, so that validation runs the Java only while
 * the {@code .ecore} still says what was compiled. A construct the translator does not know leaves its invariant to
 * the interpreter, and the translator says so. Run by the regeneration command, from the {@code .ecore} file (it
 * needs nothing of RsaML compiled); never at run time.
 */
public final class OclToJava {

    /** Where the generated class lives, relative to the repository's root. */
    public static final String TARGET = "bundles/org.rsaml.validation/src-gen/org/rsaml/validation/internal/CompiledInvariants.java";

    private static final String MODEL = "org.rsaml.model.";

    /** An invariant of the package: its class, name and text, and the Java method or why there is none. */
    public record Translation(EClass eClass, String constraint, String ocl, String java, String notTranslated) {
    }

    /** The metamodel, relative to the repository's root. */
    public static final String ECORE = "bundles/org.rsaml.model/model/rsaml.ecore";

    /** The delegate URI under which rsaml.ecore declares its invariants. */
    static final String OCL_URI = "http://www.eclipse.org/emf/2002/Ecore/OCL";

    private final OCL ocl;
    private final EPackage model;

    private OclToJava(EPackage model) {
        this.model = model;
        org.eclipse.ocl.ecore.EcorePackage.eINSTANCE.getNsURI(); // classic OCL's packages in EMF's registry
        ocl = OCL.newInstance(EcoreEnvironmentFactory.INSTANCE);
    }

    /** The invariant's body parsed by classic OCL in the context of {@code eClass}, as the interpreter parses it. */
    private OCLExpression<EClassifier> parse(EClass eClass, String body) throws ParserException {
        OCL.Helper helper = ocl.createOCLHelper();
        helper.setContext(eClass);
        Constraint parsed = helper.createInvariant(body);
        return parsed.getSpecification().getBodyExpression();
    }

    /**
     * The metamodel as the file says now (not the package compiled into this JVM, which regeneration is about to
     * replace).
     */
    public static EPackage read(Path root) {
        ResourceSet resources = new ResourceSetImpl();
        resources.getResourceFactoryRegistry().getExtensionToFactoryMap().put("ecore", new EcoreResourceFactoryImpl());
        resources.getPackageRegistry().put(EcorePackage.eNS_URI, EcorePackage.eINSTANCE);
        Resource resource = resources.getResource(URI.createFileURI(root.resolve(ECORE).toAbsolutePath().toString()), true);
        return (EPackage) resource.getContents().get(0);
    }

    /** Every invariant of {@code ePackage}, in the order of the {@code .ecore}. */
    public static List<Translation> translate(EPackage ePackage) {
        OclToJava translator = new OclToJava(ePackage);
        List<Translation> result = new ArrayList<>();
        for (EClassifier classifier : ePackage.getEClassifiers()) {
            if (!(classifier instanceof EClass eClass)) {
                continue;
            }
            EAnnotation bodies = eClass.getEAnnotation(OCL_URI);
            for (String constraint : EcoreUtil.getConstraints(eClass)) {
                String body = bodies == null ? null : bodies.getDetails().get(constraint);
                if (body == null) {
                    continue; // org.rsaml.validation reports it at start-up and RuleDefinitionTest fails
                }
                String java;
                try {
                    java = translator.expression(translator.parse(eClass, body)).code;
                } catch (NotTranslated e) {
                    result.add(new Translation(eClass, constraint, body, null, e.getMessage()));
                    continue;
                } catch (ParserException e) {
                    throw new IllegalStateException(constraint + " on " + eClass.getName() + " does not parse: " + e.getLocalizedMessage(), e);
                }
                result.add(new Translation(eClass, constraint, body, java, null));
            }
        }
        return result;
    }

    /** The source of {@code CompiledInvariants} for the rsaml.ecore under {@code root}. */
    public static String generate(Path root) {
        return source(translate(read(root)));
    }

    /** Writes {@link #TARGET} under {@code root} (left alone when up to date) and says what was left to the interpreter. */
    public static void write(Path root) throws IOException {
        List<Translation> translations = translate(read(root));
        String source = source(translations);
        Path file = root.resolve(TARGET);
        if (!Files.exists(file) || !Files.readString(file, StandardCharsets.UTF_8).equals(source)) {
            Files.createDirectories(file.getParent());
            Files.writeString(file, source, StandardCharsets.UTF_8);
        }
        long compiled = translations.stream().filter(t -> t.java() != null).count();
        System.out.println("Compiled " + compiled + " of " + translations.size() + " OCL invariants of rsaml.ecore to Java in " + file);
        for (Translation t : translations) {
            if (t.java() == null) {
                System.out.println("  " + t.constraint() + " on " + t.eClass().getName() + " is left to the OCL interpreter: "
                        + t.notTranslated());
            }
        }
    }

    public static void main(String[] args) throws IOException {
        write(Path.of(args.length > 0 ? args[0] : "."));
    }

    private static String source(List<Translation> translations) {
        StringBuilder s = new StringBuilder();
        s.append("/*\n * Copyright (c) 2026 RsaML contributors.\n * SPDX-License-Identifier: EPL-2.0\n */\n");
        s.append("package org.rsaml.validation.internal;\n\n");
        s.append("import static org.rsaml.validation.internal.CompiledOcl.*;\n\n");
        s.append("import org.eclipse.emf.ecore.EObject;\n\n");
        s.append("/**\n * The OCL invariants of rsaml.ecore as Java, written by releng/org.rsaml.codegen (OclToJava) from their text in\n")
                .append(" * the .ecore: do not edit; regenerate with\n * ").append(RsamlCodegen.REGENERATE).append("\n */\n");
        s.append("final class CompiledInvariants {\n\n    private CompiledInvariants() {\n    }\n\n");
        s.append("    /** Class, constraint and OCL text of each compiled invariant; its index is its number in {@link #check}. */\n");
        s.append("    private static final String[][] COMPILED = {\n");
        List<Translation> compiled = translations.stream().filter(t -> t.java() != null).toList();
        for (Translation t : compiled) {
            s.append("        { \"").append(t.eClass().getName()).append("\", \"").append(t.constraint()).append("\", ")
                    .append(literal(t.ocl())).append(" },\n");
        }
        s.append("    };\n\n");
        s.append("    /** Class, constraint, OCL text of each invariant left to the interpreter, and why. */\n");
        s.append("    private static final String[][] INTERPRETED = {\n");
        for (Translation t : translations) {
            if (t.java() == null) {
                s.append("        { \"").append(t.eClass().getName()).append("\", \"").append(t.constraint()).append("\", ")
                        .append(literal(t.ocl())).append(", ").append(literal(t.notTranslated())).append(" },\n");
            }
        }
        s.append("    };\n\n");
        s.append("""
                    /** The index of the compiled invariant, or -1 when it was not compiled or its text has changed since. */
                    static int index(String eClass, String constraint, String ocl) {
                        for (int i = 0; i < COMPILED.length; i++) {
                            if (COMPILED[i][0].equals(eClass) && COMPILED[i][1].equals(constraint)) {
                                return COMPILED[i][2].equals(ocl) ? i : -1;
                            }
                        }
                        return -1;
                    }

                    /** Why the invariant is left to the interpreter, or null when it is not (or its text has changed since). */
                    static String interpreted(String eClass, String constraint, String ocl) {
                        for (String[] entry : INTERPRETED) {
                            if (entry[0].equals(eClass) && entry[1].equals(constraint) && entry[2].equals(ocl)) {
                                return entry[3];
                            }
                        }
                        return null;
                    }

                    /** Evaluates compiled invariant {@code index} on {@code self}: TRUE, FALSE or null; throws {@link Invalid}. */
                    static Boolean check(int index, EObject self) {
                        switch (index) {
                """);
        for (int i = 0; i < compiled.size(); i++) {
            s.append("        case ").append(i).append(":\n            return inv").append(i).append("((")
                    .append(javaClass(compiled.get(i).eClass())).append(") self);\n");
        }
        s.append("        default:\n            throw new IllegalArgumentException(\"no compiled invariant \" + index);\n        }\n    }\n");
        for (int i = 0; i < compiled.size(); i++) {
            Translation t = compiled.get(i);
            s.append("\n    /** ").append(t.constraint()).append(" on ").append(t.eClass().getName()).append(". */\n");
            s.append("    private static Boolean inv").append(i).append("(").append(javaClass(t.eClass())).append(" self) {\n");
            s.append("        return ").append(t.java()).append(";\n    }\n");
        }
        s.append("}\n");
        return s.toString();
    }

    private static String literal(String text) {
        StringBuilder b = new StringBuilder("\"");
        for (char c : text.toCharArray()) {
            switch (c) {
            case '"' -> b.append("\\\"");
            case '\\' -> b.append("\\\\");
            case '\n' -> b.append("\\n");
            case '\r' -> b.append("\\r");
            case '\t' -> b.append("\\t");
            default -> {
                if (c < 0x20 || c > 0x7e) {
                    b.append(String.format("\\u%04x", (int) c));
                } else {
                    b.append(c);
                }
            }
            }
        }
        return b.append('"').toString();
    }

    /** Thrown for a construct the translator does not know; its invariant is left to the interpreter. */
    private static final class NotTranslated extends Exception {
        private static final long serialVersionUID = 1L;

        NotTranslated(String message) {
            super(message);
        }
    }

    /** A Java expression and its static type. */
    private record Code(String code, String type) {
    }

    private Code expression(OCLExpression<EClassifier> e) throws NotTranslated {
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
            return new Code("let(" + init.code + ", (" + javaType(v.getType()) + " v_" + v.getName() + ") -> " + in.code + ")", in.type);
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
            return new Code(literal(s.getStringSymbol()), "String");
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
            return new Code(name + "(() -> " + s.code + ", () -> " + a.code + ")", "Boolean");
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
        return new Code(name + "(" + source.code + ", (" + javaType(v.getType()) + " v_" + v.getName() + ") -> " + body.code + ")",
                "Boolean");
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
    private static String javaClass(EClassifier type) {
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
