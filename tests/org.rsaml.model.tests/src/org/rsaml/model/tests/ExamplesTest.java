/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.ElementType;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Suppressor;
import org.rsaml.tests.support.TestRepository;

/** The example models open in Eclipse's way (content type, no explicit registration) and are what they claim. */
class ExamplesTest {

    static Path examples() {
        return TestRepository.root().resolve("examples");
    }

    static Stream<String> exampleFiles() throws Exception {
        try (Stream<Path> s = Files.list(examples())) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted()
                    .collect(Collectors.toList()).stream();
        }
    }

    static Architecture load(String name) {
        Resource r = new ResourceSetImpl().getResource(URI.createFileURI(examples().resolve(name).toString()), true);
        assertTrue(r.getErrors().isEmpty(), () -> name + ": " + r.getErrors());
        EcoreUtil.resolveAll(r);
        assertTrue(EcoreUtil.UnresolvedProxyCrossReferencer.find(r).isEmpty(), name + " has unresolved references");
        return assertInstanceOf(Architecture.class, r.getContents().get(0), name + "'s root is an architecture");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("exampleFiles")
    void exampleLoadsWithEveryReferenceResolved(String name) {
        Architecture a = load(name);
        assertFalse(a.getLayers().isEmpty(), name + " has no layer");
    }

    /** Each model the README's "Examples" section describes is in examples/ and loads; adding an example breaks nothing. */
    @Test
    void theExamplesTheReadmeDescribesAreThereAndLoad() throws Exception {
        String readme = Files.readString(TestRepository.root().resolve("README.md"));
        int start = readme.indexOf("\n## Examples\n");
        assertTrue(start >= 0, "README.md has an \"Examples\" section");
        int end = readme.indexOf("\n## ", start + 1);
        String section = readme.substring(start, end < 0 ? readme.length() : end);
        List<String> described = Pattern.compile("`([\\w.-]+\\.rsaml)`").matcher(section).results().map(m -> m.group(1))
                .distinct().toList();
        assertFalse(described.isEmpty(), "the README's \"Examples\" section names example models");
        List<String> present = exampleFiles().toList();
        for (String name : described) {
            assertTrue(present.contains(name), "the README describes examples/" + name + ", which is not there");
            assertFalse(load(name).getLayers().isEmpty(), "the README's example " + name + " has no layer");
        }
    }

    private static Module module(Architecture a, String name) {
        return a.getLayers().stream().flatMap(l -> l.getModules().stream()).filter(m -> name.equals(m.getName()))
                .findFirst().orElseThrow(() -> new AssertionError("no module " + name));
    }

    @Test
    void experimentTwoCarriesThePapersFiveDefects() {
        Architecture a = load("exp2-defects.rsaml");
        // 1. four layers declared, three created
        assertEquals(4, a.getDeclaredLayers(), "defect 1: exp2 declares four layers");
        assertEquals(List.of("decision", "control", "functional"), a.getLayers().stream().map(Layer::getName).toList(), "defect 1: exp2 creates three layers");
        // 2. alphanumeric entry e0_prodExec fed by numeric output s0_ressourceCheck
        Connection c = a.getConnections().stream().filter(x -> "e0_prodExec".equals(x.getTarget().getName())).findFirst().orElseThrow();
        assertEquals("s0_ressourceCheck", c.getSource().getName(), "defect 2: the offending connection comes from resourceChecker's output s0_ressourceCheck");
        assertEquals(DataType.NUMERIC, c.getSource().getDataType(), "defect 2: the connection's source is numeric");
        assertEquals(DataType.ALPHANUMERIC, c.getTarget().getDataType(), "defect 2: the connection's target is alphanumeric");
        // 3. proceduralExec suppresses entry e0_m01 of m01, two layers below
        Module exec = module(a, "proceduralExec");
        Suppressor s = exec.getSuppressors().get(0);
        assertEquals("e0_m01", s.getTarget().getName(), "defect 3: proceduralExec suppresses entry e0_m01");
        assertEquals("m01", s.getTarget().getModule().getName(), "defect 3: the suppressed entry belongs to m01");
        assertEquals(2, exec.getLayer().getLevel() - s.getTarget().getModule().getLayer().getLevel(), "defect 3: the suppressed module is two layers below");
        // 4. resourceChecker takes 2.5 in a layer allowing 2.0
        Module checker = module(a, "resourceChecker");
        assertEquals(2.5, checker.getExecDuration(), "defect 4: resourceChecker takes 2.5 ms");
        assertEquals(2.0, checker.getLayer().getMaxExecTime(), "defect 4: its layer allows at most 2.0 ms");
        // 5. real-time f0_m01 holds the simple action a0_f0_m01
        Function f = module(a, "m01").getFunctions().stream().filter(x -> "f0_m01".equals(x.getName())).findFirst().orElseThrow();
        assertEquals(ElementType.REAL_TIME, f.getType(), "defect 5: f0_m01 is real-time");
        assertEquals(ElementType.SIMPLE, f.getActions().stream().filter(x -> "a0_f0_m01".equals(x.getName())).findFirst().orElseThrow().getType(), "defect 5: its action a0_f0_m01 is a simple (non-real-time) action");
    }

    @Test
    void experimentThreeHasSixPeriodicInstructions() {
        Architecture a = load("exp3-task-interpreter.rsaml");
        assertEquals(ArchitectureCategory.OTHER, a.getCategory(), "exp3's category is 'other'");
        Module controller = a.getLayers().stream().flatMap(l -> l.getModules().stream())
                .filter(m -> m.getName().toLowerCase().contains("motion")).findFirst().orElseThrow();
        var actions = controller.getFunctions().stream().flatMap(fn -> fn.getActions().stream()).toList();
        assertEquals(6, actions.size(), "the motion controller has six instructions");
        for (var action : actions) {
            assertEquals(ExecutionType.PERIODIC, action.getExecType(), action.getName() + " runs periodically");
            assertEquals(20.0, action.toMilliseconds(action.getPeriod()), action.getName() + " runs every 20 ms");
            assertEquals(1.0, action.toMilliseconds(action.getExecDuration()), action.getName() + " takes 1 ms");
        }
    }
}
