/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import java.io.IOException;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.eclipse.emf.codegen.ecore.generator.Generator;
import org.eclipse.emf.codegen.ecore.generator.GeneratorAdapterFactory;
import org.eclipse.emf.codegen.ecore.genmodel.GenModel;
import org.eclipse.emf.codegen.ecore.genmodel.GenModelFactory;
import org.eclipse.emf.codegen.ecore.genmodel.GenModelPackage;
import org.eclipse.emf.codegen.ecore.genmodel.GenPackage;
import org.eclipse.emf.codegen.ecore.genmodel.generator.GenBaseGeneratorAdapter;
import org.eclipse.emf.codegen.ecore.genmodel.generator.GenModelGeneratorAdapterFactory;
import org.eclipse.emf.common.util.BasicMonitor;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.plugin.EcorePlugin;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.xmi.impl.EcoreResourceFactoryImpl;
import org.eclipse.emf.ecore.xmi.impl.XMIResourceFactoryImpl;
import org.eclipse.xtext.Grammar;
import org.eclipse.xtext.XtextStandaloneSetup;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.rsaml.model.RsamlPackage;
import org.rsaml.text.grammar.Constructs;
import org.rsaml.text.grammar.LanguageReference;
import org.rsaml.validation.RulesDocument;

/**
 * Generates RsaML's EMF code (model, edit and editor) from {@code rsaml.ecore} outside Eclipse, and
 * the rule table of {@code docs/rules.md} from the rule catalogue, the language reference of
 * {@code docs/textual-syntax.md} from the grammar of the textual syntax.
 *
 * <p>The genmodel is rebuilt from the current .ecore on every run (keeping its settings), so that
 * a change to the metamodel needs nothing but this command. Everything is generated into a scratch
 * folder first; {@code write} then replaces the committed files, {@code check} only compares.
 */
public final class RsamlCodegen {

    /**
     * What is generated, per bundle: the folders and files the generator owns. Every bundle's
     * plugin.xml is written by hand, to register RsaML's subclasses of generated classes.
     */
    static final Map<String, List<String>> GENERATED = new TreeMap<>(Map.of(
            "org.rsaml.model", List.of("src-gen", "plugin.properties"),
            "org.rsaml.model.edit", List.of("src-gen", "plugin.properties"),
            "org.rsaml.model.editor", List.of("src-gen", "plugin.properties", "icons")));

    static final String MODEL_DIR = "bundles/org.rsaml.model/model/";

    /*
     * The invariants of rsaml.ecore are RsaML's rules, judged by the one validator of the package,
     * org.rsaml.validation's RuleEValidator. EMF's generator would add a validator of its own, which
     * the generated package registers when it is initialised; its switch EMF_NO_CONSTRAINTS leaves
     * both out (the invariants stay in the package's annotations). It is read once, when the
     * generator's GenPackageImpl is loaded, hence here, before any generator class.
     */
    static {
        System.setProperty("EMF_NO_CONSTRAINTS", "true");
    }

    private RsamlCodegen() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2 || !(args[0].equals("write") || args[0].equals("check"))) {
            System.err.println("usage: RsamlCodegen write|check <repository root>");
            System.exit(2);
        }
        Path root = Path.of(args[1]).toAbsolutePath().normalize();
        if (args[0].equals("write")) {
            write(root);
        } else {
            List<String> stale = check(root);
            stale.forEach(s -> System.err.println("out of date: " + s));
            System.exit(stale.isEmpty() ? 0 : 1);
        }
    }

    /** Regenerates and replaces the committed generated files and the genmodel. */
    public static void write(Path root) throws IOException {
        Path scratch = Files.createTempDirectory("rsaml-codegen");
        try {
            generate(root, scratch);
            for (Map.Entry<String, List<String>> bundle : GENERATED.entrySet()) {
                for (String item : bundle.getValue()) {
                    Path from = scratch.resolve(bundle.getKey()).resolve(item);
                    Path to = root.resolve("bundles").resolve(bundle.getKey()).resolve(item);
                    deleteTree(to);
                    copyTree(from, to);
                }
            }
            Files.copy(scratch.resolve("rsaml.genmodel"), root.resolve(MODEL_DIR + "rsaml.genmodel"),
                    java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            System.out.println("Regenerated RsaML code from " + root.resolve(MODEL_DIR + "rsaml.ecore"));
        } finally {
            deleteTree(scratch);
        }
        writeRulesDocument(root);
        writeLanguageReference(root);
    }

    /** The grammar of the textual syntax as its source says (the generated parser may be older: it is regenerated after this). */
    static Grammar grammar(Path root) {
        RsamlPackage.eINSTANCE.eClass();
        XtextResourceSet resources = new XtextStandaloneSetup().createInjectorAndDoEMFRegistration().getInstance(XtextResourceSet.class);
        Resource resource = resources.getResource(URI.createFileURI(root.resolve(GRAMMAR).toAbsolutePath().toString()), true);
        if (!resource.getErrors().isEmpty()) {
            throw new IllegalStateException(GRAMMAR + " has errors: " + resource.getErrors());
        }
        return (Grammar) resource.getContents().get(0);
    }

    static final String GRAMMAR = "bundles/org.rsaml.text/src/org/rsaml/text/RsamlText.xtext";

    /** Rewrites the language reference of docs/textual-syntax.md from the textual grammar and the textual examples. */
    static void writeLanguageReference(Path root) throws IOException {
        Path page = root.resolve(LanguageReference.PATH);
        String current = Files.readString(page, StandardCharsets.UTF_8);
        List<String> examples = new ArrayList<>();
        try (Stream<Path> files = Files.list(root.resolve("examples-text"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".rsa")).sorted().toList()) {
                examples.add(Files.readString(file, StandardCharsets.UTF_8));
            }
        }
        String updated = LanguageReference.update(current, new Constructs(grammar(root)), examples);
        if (!updated.equals(current)) {
            Files.writeString(page, updated, StandardCharsets.UTF_8);
        }
        System.out.println("Regenerated the language reference of " + page + " from the grammar of the textual syntax");
    }

    /** Rewrites the rule table of docs/rules.md from the catalogue (the file is left alone when it is up to date). */
    static void writeRulesDocument(Path root) throws IOException {
        Path page = root.resolve(RulesDocument.PATH);
        String current = Files.readString(page, StandardCharsets.UTF_8);
        String updated = rulesDocument(root, current);
        if (!updated.equals(current)) {
            Files.writeString(page, updated, StandardCharsets.UTF_8);
        }
        System.out.println("Regenerated the rule table of " + page + " from " + root.resolve(RulesDocument.CATALOGUE));
    }

    /** The page with its rule table produced from the catalogue of the clone at {@code root}. */
    static String rulesDocument(Path root, String page) throws IOException {
        try (Reader catalogue = Files.newBufferedReader(root.resolve(RulesDocument.CATALOGUE), StandardCharsets.UTF_8)) {
            return RulesDocument.update(page, RulesDocument.read(catalogue));
        }
    }

    /** Regenerates into a scratch folder and lists every committed file that differs from it. */
    public static List<String> check(Path root) throws IOException {
        Path scratch = Files.createTempDirectory("rsaml-codegen");
        try {
            generate(root, scratch);
            List<String> stale = new ArrayList<>();
            for (Map.Entry<String, List<String>> bundle : GENERATED.entrySet()) {
                for (String item : bundle.getValue()) {
                    compare(scratch.resolve(bundle.getKey()).resolve(item),
                            root.resolve("bundles").resolve(bundle.getKey()).resolve(item),
                            "bundles/" + bundle.getKey() + "/" + item, stale);
                }
            }
            compare(scratch.resolve("rsaml.genmodel"), root.resolve(MODEL_DIR + "rsaml.genmodel"),
                    MODEL_DIR + "rsaml.genmodel", stale);
            String page = Files.readString(root.resolve(RulesDocument.PATH), StandardCharsets.UTF_8);
            if (!rulesDocument(root, page).equals(page)) {
                stale.add(RulesDocument.PATH + " (the rule table)");
            }
            return stale;
        } finally {
            deleteTree(scratch);
        }
    }

    private static void generate(Path root, Path scratch) throws IOException {
        ResourceSet resourceSet = new ResourceSetImpl();
        resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put("ecore", new EcoreResourceFactoryImpl());
        resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put("genmodel", new XMIResourceFactoryImpl());
        resourceSet.getPackageRegistry().put(EcorePackage.eNS_URI, EcorePackage.eINSTANCE);
        resourceSet.getPackageRegistry().put(GenModelPackage.eNS_URI, GenModelPackage.eINSTANCE);

        // The genmodel names its output folders as platform:/resource/<bundle>/...; point them at the scratch folder.
        for (String bundle : GENERATED.keySet()) {
            EcorePlugin.getPlatformResourceMap().put(bundle, URI.createFileURI(scratch.resolve(bundle).toString() + "/"));
        }
        Files.copy(root.resolve(MODEL_DIR + "rsaml.ecore"), scratch.resolve("rsaml.ecore"));
        Files.copy(root.resolve(MODEL_DIR + "rsaml.genmodel"), scratch.resolve("settings.genmodel"));

        Resource ecore = resourceSet.getResource(URI.createFileURI(scratch.resolve("rsaml.ecore").toString()), true);
        EPackage ePackage = (EPackage) ecore.getContents().get(0);
        Resource old = resourceSet.getResource(URI.createFileURI(scratch.resolve("settings.genmodel").toString()), true);
        GenModel settings = (GenModel) old.getContents().get(0);

        GenModel genModel = GenModelFactory.eINSTANCE.createGenModel();
        Resource genModelResource = resourceSet.createResource(URI.createFileURI(scratch.resolve("rsaml.genmodel").toString()));
        genModelResource.getContents().add(genModel);
        genModel.initialize(List.of(ePackage));
        genModel.reconcile(settings);
        genModel.getForeignModel().clear();
        genModel.getForeignModel().add("rsaml.ecore");
        genModel.setCanGenerate(true);

        for (GenPackage genPackage : genModel.getGenPackages()) {
            if (genPackage.hasConstraints()) {
                throw new IllegalStateException("EMF's generator would generate and register a validator for "
                        + genPackage.getPackageName() + ": EMF_NO_CONSTRAINTS was read before RsamlCodegen set it");
            }
        }
        Diagnostic diagnostic = genModel.diagnose();
        if (diagnostic.getSeverity() == Diagnostic.ERROR) {
            throw new IllegalStateException("rsaml.genmodel is not valid: " + diagnostic);
        }
        genModelResource.save(Map.of());

        GeneratorAdapterFactory.Descriptor.Registry.INSTANCE.addDescriptor(GenModelPackage.eNS_URI,
                GenModelGeneratorAdapterFactory.DESCRIPTOR);
        Generator generator = new Generator();
        generator.setInput(genModel);
        for (String projectType : Arrays.asList(GenBaseGeneratorAdapter.MODEL_PROJECT_TYPE,
                GenBaseGeneratorAdapter.EDIT_PROJECT_TYPE, GenBaseGeneratorAdapter.EDITOR_PROJECT_TYPE)) {
            Diagnostic result = generator.generate(genModel, projectType, new BasicMonitor());
            if (result.getSeverity() == Diagnostic.ERROR) {
                throw new IllegalStateException("EMF generation failed: " + result);
            }
        }
        for (String bundle : GENERATED.keySet()) {
            if (!Files.isDirectory(scratch.resolve(bundle).resolve("src-gen"))) {
                throw new IllegalStateException("EMF generated nothing for " + bundle);
            }
            // EMF's template names a placeholder vendor; RsaML's bundles name their own.
            Path properties = scratch.resolve(bundle).resolve("plugin.properties");
            Files.writeString(properties, Files.readString(properties)
                    .replace("providerName = www.example.org", "providerName = RsaML"));
        }
    }

    private static void compare(Path generated, Path committed, String label, List<String> stale) throws IOException {
        if (Files.isDirectory(generated) || Files.isDirectory(committed)) {
            TreeMap<String, Boolean> names = new TreeMap<>();
            for (Path dir : List.of(generated, committed)) {
                if (Files.isDirectory(dir)) {
                    try (Stream<Path> files = Files.walk(dir)) {
                        files.filter(Files::isRegularFile).forEach(f -> names.put(dir.relativize(f).toString(), true));
                    }
                }
            }
            for (String name : names.keySet()) {
                compare(generated.resolve(name), committed.resolve(name), label + "/" + name, stale);
            }
        } else if (!Files.exists(generated)) {
            stale.add(label + " (no longer generated)");
        } else if (!Files.exists(committed)) {
            stale.add(label + " (missing)");
        } else if (!Arrays.equals(Files.readAllBytes(generated), Files.readAllBytes(committed))) {
            stale.add(label);
        }
    }

    static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path target = to.resolve(from.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(target);
                } else {
                    Files.createDirectories(target.getParent());
                    Files.copy(f, target);
                }
            }
        }
    }

    private static void deleteTree(Path path) throws IOException {
        if (!Files.exists(path)) {
            return;
        }
        try (Stream<Path> files = Files.walk(path)) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> {
                try {
                    Files.delete(f);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        }
    }
}
