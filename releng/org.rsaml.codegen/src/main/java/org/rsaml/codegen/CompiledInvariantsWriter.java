/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import java.util.List;

import org.rsaml.codegen.OclToJava.Translation;

/**
 * Writes the source of {@code CompiledInvariants} (org.rsaml.validation) from the translations of
 * {@link OclToJava}: the table of the compiled invariants' texts (so that validation runs a method only while the
 * {@code .ecore} still says what was compiled), the table of those left to the interpreter with the reason, and
 * one method per compiled invariant.
 */
public final class CompiledInvariantsWriter {

    private CompiledInvariantsWriter() {
    }

    /** The class's source for {@code translations}, in the order of the {@code .ecore}. */
    static String source(List<Translation> translations) {
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
                    .append(OclExpressionTranslator.javaClass(compiled.get(i).eClass())).append(") self);\n");
        }
        s.append("        default:\n            throw new IllegalArgumentException(\"no compiled invariant \" + index);\n        }\n    }\n");
        for (int i = 0; i < compiled.size(); i++) {
            Translation t = compiled.get(i);
            s.append("\n    /** ").append(t.constraint()).append(" on ").append(t.eClass().getName()).append(". */\n");
            s.append("    private static Boolean inv").append(i).append("(").append(OclExpressionTranslator.javaClass(t.eClass())).append(" self) {\n");
            s.append("        return ").append(t.java()).append(";\n    }\n");
        }
        s.append("}\n");
        return s.toString();
    }

    /** {@code text} as a Java string literal, in ASCII. */
    public static String literal(String text) {
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

}
