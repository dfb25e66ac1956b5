/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.RsamlPackage;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.tests.support.models.RandomModels;
import org.rsaml.tests.support.models.RandomModels.Shape;
import org.rsaml.tests.support.models.RandomModels.Values;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlValidationSetup;
import org.rsaml.validation.internal.OclRules;

/**
 * The invariants compiled to Java at build time against classic OCL's interpreter, their definition: on every rule
 * fixture, every example, the mutated examples of {@link MutatedFilesTest} and seeded random models ({@link RandomModels}: values
 * at the edges, names missing and repeated, references anywhere), every invariant
 * of every element gives the same result (true, false, or undefined) both ways. Also: classic OCL's own evaluation
 * environment agrees with the one validation interprets in.
 */
class CompiledInvariantsTest {

    private static final long SEED = 20261127L;
    private static final int RANDOM_MODELS = 300;

    private static OclRules compiled;
    private static OclRules interpreted;

    @TempDir
    Path dir;

    @BeforeAll
    static void rules() {
        RsamlValidationSetup.init();
        compiled = OclRules.instance();
        interpreted = OclRules.interpreted(RsamlPackage.eINSTANCE, true);
    }

    /** The committed code is up to date with the .ecore (GeneratedCodeUpToDateTest compares it with the translator's output). */
    @Test
    void everyInvariantButThoseTheTranslatorLeavesToTheInterpreterRunsCompiled() {
        assertTrue(compiled.isCompiled(), "validation must run the compiled invariants");
        assertEquals(Map.of("Module.RSA19_activatedModule", "closure() is not translated"), compiled.interpreted(),
                "only RSA-19's closure() is left to the interpreter (validation decides RSA-19 by its traversal)");
        assertEquals(interpreted.size(), compiled.size(), "both must know every invariant");
        assertEquals(compiled.size() - 1, compiled.compiledCount(), "every other invariant must run compiled");
    }

    @Test
    void compiledAgreesWithTheInterpreterOnFixturesAndExamples() throws Exception {
        List<String> differences = new ArrayList<>();
        int[] compared = new int[1];
        for (Path file : models()) {
            LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
            for (EObject root : model.resource().getContents()) {
                compare(root, file.getFileName().toString(), differences, compared);
            }
        }
        report(differences, compared[0], 2_000);
    }

    @Test
    void compiledAgreesWithTheInterpreterOnMutatedExamples() throws Exception {
        List<byte[]> examples = new ArrayList<>();
        try (Stream<Path> files = Files.list(TestRepository.root().resolve("examples"))) {
            for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".rsaml")).sorted()::iterator) {
                examples.add(Files.readAllBytes(f));
            }
        }
        Random random = new Random(SEED);
        List<String> differences = new ArrayList<>();
        int[] compared = new int[1];
        for (int i = 0; i < 300; i++) {
            byte[] bytes = MutatedFilesTest.mutate(examples.get(random.nextInt(examples.size())), random.nextInt(12), random);
            Path file = dir.resolve("mutant-" + i + ".rsaml");
            Files.write(file, bytes);
            LoadedModel model;
            try {
                model = ModelLoader.load(file, file.getFileName().toString());
            } catch (ModelLoadException e) {
                continue;
            }
            for (EObject root : model.resource().getContents()) {
                compare(root, "mutant " + i, differences, compared);
            }
        }
        report(differences, compared[0], 10_000);
    }

    @Test
    void compiledAgreesWithTheInterpreterOnRandomModels() {
        Random random = new Random(SEED);
        List<String> differences = new ArrayList<>();
        int[] compared = new int[1];
        for (int i = 0; i < RANDOM_MODELS; i++) {
            EObject root = new RandomModels(RsamlPackage.eINSTANCE, random, Values.EDGES, Shape.ANY).create(RsamlPackage.Literals.ARCHITECTURE);
            compare(root, "random model " + i, differences, compared);
        }
        report(differences, compared[0], 10_000);
    }

    /** Classic OCL's own Ecore evaluation environment against the one that remembers collection kinds. */
    @Test
    void theCachingEnvironmentAgreesWithClassicOclsOwn() throws Exception {
        OclRules plain = OclRules.interpreted(RsamlPackage.eINSTANCE, false);
        List<String> differences = new ArrayList<>();
        int compared = 0;
        for (Path file : models()) {
            LoadedModel model = ModelLoader.load(file, file.getFileName().toString());
            for (Iterator<EObject> it = EcoreUtil.getAllContents(model.resource().getContents()); it.hasNext();) {
                EObject e = it.next();
                for (Map.Entry<String, EClass> invariant : invariants(e).entrySet()) {
                    String a = outcome(interpreted, invariant.getValue(), invariant.getKey(), e);
                    String b = outcome(plain, invariant.getValue(), invariant.getKey(), e);
                    compared++;
                    if (!a.equals(b)) {
                        differences.add(file.getFileName() + ": " + invariant.getKey() + " on " + EcoreUtil.getURI(e).fragment()
                                + ": caching " + a + ", classic OCL's " + b);
                    }
                }
            }
        }
        report(differences, compared, 2_000);
    }

    /** Every example and every fixture of the rules and the timing rules. */
    static List<Path> models() throws Exception {
        List<Path> files = new ArrayList<>();
        for (Path folder : List.of(TestRepository.root().resolve("examples"),
                TestRepository.root().resolve("tests/org.rsaml.validation.tests/resources/rules"),
                TestRepository.root().resolve("tests/org.rsaml.validation.tests/resources/timing"))) {
            try (Stream<Path> s = Files.list(folder)) {
                s.filter(p -> p.toString().endsWith(".rsaml")).sorted().forEach(files::add);
            }
        }
        assertTrue(files.size() > 60, "the fixtures and examples must be found, got " + files.size());
        return files;
    }

    private static void compare(EObject root, String where, List<String> differences, int[] compared) {
        List<EObject> elements = new ArrayList<>();
        elements.add(root);
        root.eAllContents().forEachRemaining(elements::add);
        for (EObject e : elements) {
            for (Map.Entry<String, EClass> invariant : invariants(e).entrySet()) {
                String expected = outcome(interpreted, invariant.getValue(), invariant.getKey(), e);
                String actual = outcome(compiled, invariant.getValue(), invariant.getKey(), e);
                compared[0]++;
                if (!expected.equals(actual)) {
                    differences.add(where + ": " + invariant.getKey() + " on " + e.eClass().getName() + " "
                            + EcoreUtil.getURI(e).fragment() + ": interpreted " + expected + ", compiled " + actual);
                }
            }
        }
    }

    /** Every invariant the element must satisfy, by name, with the class that declares it. */
    private static Map<String, EClass> invariants(EObject e) {
        Map<String, EClass> result = new TreeMap<>();
        List<EClass> classes = new ArrayList<>(e.eClass().getEAllSuperTypes());
        classes.add(e.eClass());
        for (EClass c : classes) {
            for (String constraint : EcoreUtil.getConstraints(c)) {
                result.put(constraint, c);
            }
        }
        return result;
    }

    private static String outcome(OclRules rules, EClass declaredOn, String constraint, EObject e) {
        try {
            return String.valueOf(rules.check(declaredOn, constraint, e));
        } catch (RuntimeException ex) {
            return "exception " + ex.getClass().getName() + ": " + ex.getMessage();
        }
    }

    private static void report(List<String> differences, int compared, int atLeast) {
        if (!differences.isEmpty()) {
            fail(differences.size() + " of " + compared + " evaluations differ:\n"
                    + String.join("\n", differences.subList(0, Math.min(30, differences.size()))));
        }
        assertTrue(compared >= atLeast, "too few evaluations compared: " + compared);
    }
}
