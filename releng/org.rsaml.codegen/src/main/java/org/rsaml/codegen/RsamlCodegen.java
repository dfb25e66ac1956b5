/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import java.io.IOException;
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

/**
 * Generates RsaML's EMF code (model, edit and editor) from {@code rsaml.ecore} outside Eclipse.
 *
 * <p>The genmodel is rebuilt from the current .ecore on every run (keeping its settings), so that
 * a change to the metamodel needs nothing but this command. Everything is generated into a scratch
 * folder first; {@code write} then replaces the committed files, {@code check} only compares.
 *
 * <p>Nothing of RsaML is on this module's class path: the EMF code (and, in the same run, the Xtext code of
 * the textual syntax, see the pom) is generated before any bundle is compiled, so it can be regenerated
 * when the committed generated code no longer compiles. The documentation tables made from the bundles
 * (the rule table, the language reference) are written after them, by {@code releng/org.rsaml.docgen}.
 */
public final class RsamlCodegen {

    /**
     * The one command that regenerates everything generated from a source in the repository: the EMF code
     * (this class), the Xtext code of the textual syntax, then the documentation tables
     * ({@code releng/org.rsaml.docgen}, built after the bundles it reads, which compile against the new code).
     */
    public static final String REGENERATE = "./mvnw -Pregenerate -pl releng/org.rsaml.codegen,releng/org.rsaml.docgen -am process-classes";

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
        run("RsamlCodegen", args, RsamlCodegen::write, RsamlCodegen::check);
    }

    /** A generator's writing: rewrites its generated files in the clone at {@code root}. */
    @FunctionalInterface
    public interface Write {
        void apply(Path root) throws IOException;
    }

    /** A generator's check: the files of the clone at {@code root} that differ from what it would write. */
    @FunctionalInterface
    public interface Check {
        List<String> apply(Path root) throws IOException;
    }

    /**
     * The command line every generator of the regeneration command has, {@code write|check <repository root>}:
     * {@code write} rewrites the generated files, {@code check} lists the stale ones and exits 1 when there are any.
     */
    public static void run(String name, String[] args, Write write, Check check) throws IOException {
        if (args.length != 2 || !(args[0].equals("write") || args[0].equals("check"))) {
            System.err.println("usage: " + name + " write|check <repository root>");
            System.exit(2);
        }
        Path root = Path.of(args[1]).toAbsolutePath().normalize();
        if (args[0].equals("write")) {
            write.apply(root);
        } else {
            List<String> stale = check.apply(root);
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
        OclToJava.write(root);
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
            Path compiled = root.resolve(OclToJava.TARGET);
            if (!Files.exists(compiled) || !Files.readString(compiled, StandardCharsets.UTF_8).equals(OclToJava.generate(root))) {
                stale.add(OclToJava.TARGET + " (the invariants compiled to Java)");
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
