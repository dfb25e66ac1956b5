/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.docgen;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.Grammar;
import org.eclipse.xtext.XtextStandaloneSetup;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.rsaml.codegen.RsamlCodegen;
import org.rsaml.model.RsamlPackage;
import org.rsaml.text.grammar.Constructs;

/**
 * Writes the documentation tables made from RsaML's sources: the rule table of {@code docs/rules.md} from the
 * rule catalogue ({@link RulesDocument}), the catalogue as the Java class org.rsaml.validation runs ({@link CatalogueClass}) and the language reference of {@code docs/textual-syntax.md} from the
 * textual grammar and {@code examples-text/} ({@link LanguageReference}). Run by {@link RsamlCodegen#REGENERATE}
 * after the EMF and Xtext code is generated and the bundles it reads are compiled; {@code write} rewrites the
 * pages (a page already up to date is left alone), {@code check} only compares.
 */
public final class RsamlDocgen {

    /** The grammar of the textual syntax, relative to the repository root. */
    static final String GRAMMAR = "bundles/org.rsaml.text/src/org/rsaml/text/RsamlText.xtext";

    private RsamlDocgen() {
    }

    public static void main(String[] args) throws IOException {
        RsamlCodegen.run("RsamlDocgen", args, RsamlDocgen::write, RsamlDocgen::check);
    }

    /** Rewrites both tables from the sources of the clone at {@code root}. */
    public static void write(Path root) throws IOException {
        rewrite(root, RulesDocument.PATH, rulesDocument(root, read(root, RulesDocument.PATH)));
        System.out.println("Regenerated the rule table of " + root.resolve(RulesDocument.PATH) + " from " + root.resolve(RulesDocument.CATALOGUE));
        rewrite(root, LanguageReference.PATH, languageReference(root, read(root, LanguageReference.PATH)));
        System.out.println("Regenerated the language reference of " + root.resolve(LanguageReference.PATH) + " from " + root.resolve(GRAMMAR));
        Path catalogueClass = root.resolve(CatalogueClass.PATH);
        String source = catalogueClass(root);
        if (!Files.exists(catalogueClass) || !source.equals(read(root, CatalogueClass.PATH))) {
            Files.createDirectories(catalogueClass.getParent());
            Files.writeString(catalogueClass, source, StandardCharsets.UTF_8);
        }
        System.out.println("Regenerated the rule catalogue's class " + catalogueClass + " from " + root.resolve(RulesDocument.CATALOGUE));
    }

    /** The pages whose table differs from what {@link #write} would make of the sources. */
    public static List<String> check(Path root) throws IOException {
        List<String> stale = new ArrayList<>();
        String rules = read(root, RulesDocument.PATH);
        if (!rulesDocument(root, rules).equals(rules)) {
            stale.add(RulesDocument.PATH + " (the rule table)");
        }
        String reference = read(root, LanguageReference.PATH);
        if (!languageReference(root, reference).equals(reference)) {
            stale.add(LanguageReference.PATH + " (the language reference)");
        }
        if (!Files.exists(root.resolve(CatalogueClass.PATH)) || !catalogueClass(root).equals(read(root, CatalogueClass.PATH))) {
            stale.add(CatalogueClass.PATH + " (the rule catalogue as Java)");
        }
        return stale;
    }

    /** The rule catalogue of the clone at {@code root} as the Java class org.rsaml.validation runs. */
    static String catalogueClass(Path root) throws IOException {
        return CatalogueClass.source(Files.readAllBytes(root.resolve(RulesDocument.CATALOGUE)));
    }

    /** The page with its rule table produced from the catalogue of the clone at {@code root}. */
    static String rulesDocument(Path root, String page) throws IOException {
        try (Reader catalogue = Files.newBufferedReader(root.resolve(RulesDocument.CATALOGUE), StandardCharsets.UTF_8)) {
            return RulesDocument.update(page, RulesDocument.read(catalogue));
        }
    }

    /** The page with its language reference made from the grammar's source and the textual examples of the clone at {@code root}. */
    static String languageReference(Path root, String page) throws IOException {
        List<String> examples = new ArrayList<>();
        try (Stream<Path> files = Files.list(root.resolve("examples-text"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".rsa")).sorted().toList()) {
                examples.add(Files.readString(file, StandardCharsets.UTF_8));
            }
        }
        return LanguageReference.update(page, new Constructs(grammar(root)), examples);
    }

    /** The grammar of the textual syntax as its source says. */
    static Grammar grammar(Path root) {
        RsamlPackage.eINSTANCE.eClass();
        XtextResourceSet resources = new XtextStandaloneSetup().createInjectorAndDoEMFRegistration().getInstance(XtextResourceSet.class);
        Resource resource = resources.getResource(URI.createFileURI(root.resolve(GRAMMAR).toAbsolutePath().toString()), true);
        if (!resource.getErrors().isEmpty()) {
            throw new IllegalStateException(GRAMMAR + " has errors: " + resource.getErrors());
        }
        return (Grammar) resource.getContents().get(0);
    }

    private static String read(Path root, String page) throws IOException {
        return Files.readString(root.resolve(page), StandardCharsets.UTF_8);
    }

    private static void rewrite(Path root, String page, String text) throws IOException {
        if (!text.equals(read(root, page))) {
            Files.writeString(root.resolve(page), text, StandardCharsets.UTF_8);
        }
    }
}
