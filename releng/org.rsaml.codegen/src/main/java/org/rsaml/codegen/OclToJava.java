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

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EAnnotation;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EClassifier;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.eclipse.ocl.ParserException;

/**
 * The build-time translation of the invariants of rsaml.ecore into Java for org.rsaml.validation: each invariant's text is parsed by classic OCL
 * (as the interpreter parses it), its expression tree translated ({@link OclExpressionTranslator}) and written as a Java method of
 * {@code CompiledInvariants} ({@code src-gen/} of that bundle; {@link CompiledInvariantsWriter}), with OCL's semantics of null, invalid and the logical operators taken from
 * {@code CompiledOcl} (org.rsaml.validation). The generated class records each invariant's text, so that validation runs the Java only while
 * the {@code .ecore} still says what was compiled. A construct the translator does not know leaves its invariant to
 * the interpreter, and the translator says so. Run by the regeneration command, from the {@code .ecore} file (it
 * needs nothing of RsaML compiled); never at run time.
 */
public final class OclToJava {

    /** Where the generated class lives, relative to the repository's root. */
    public static final String TARGET = "bundles/org.rsaml.validation/src-gen/org/rsaml/validation/internal/CompiledInvariants.java";

    /** An invariant of the package: its class, name and text, and the Java method or why there is none. */
    public record Translation(EClass eClass, String constraint, String ocl, String java, String notTranslated) {
    }

    /** The metamodel, relative to the repository's root. */
    public static final String ECORE = "bundles/org.rsaml.model/model/rsaml.ecore";

    /** The delegate URI under which rsaml.ecore declares its invariants. */
    static final String OCL_URI = "http://www.eclipse.org/emf/2002/Ecore/OCL";

    private OclToJava() {
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
        OclExpressionTranslator translator = new OclExpressionTranslator(ePackage);
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
                    java = translator.expression(translator.parse(eClass, body)).code();
                } catch (OclExpressionTranslator.NotTranslated e) {
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
        return CompiledInvariantsWriter.source(translate(read(root)));
    }

    /** Writes {@link #TARGET} under {@code root} (left alone when up to date) and says what was left to the interpreter. */
    public static void write(Path root) throws IOException {
        List<Translation> translations = translate(read(root));
        String source = CompiledInvariantsWriter.source(translations);
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

}
