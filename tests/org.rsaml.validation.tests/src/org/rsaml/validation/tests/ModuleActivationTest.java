/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.Suppressor;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.internal.ModuleActivation;
import org.rsaml.validation.internal.OclRules;

/**
 * RSA-19 (every module is activated) is evaluated by a graph traversal once per validation; its
 * definition stays the OCL invariant of rsaml.ecore. The interpreted invariant is the oracle here:
 * on every example, every rule model and seeded random architectures, both say the same of every
 * module. Long chains and dense graphs, where the invariant evaluated per module is quadratic and
 * recursive, are validated with the right findings.
 */
class ModuleActivationTest {

    private static final RsamlFactory F = RsamlFactory.eINSTANCE;
    private static final long SEED = 20261126L;

    @Test
    void theTraversalAgreesWithTheInvariantOnEveryExampleAndRuleModel() throws Exception {
        List<Path> files = new ArrayList<>();
        for (Path folder : List.of(TestRepository.root().resolve("examples"),
                TestRepository.root().resolve("tests/org.rsaml.validation.tests/resources/rules"))) {
            try (Stream<Path> s = Files.list(folder)) {
                s.filter(p -> p.toString().endsWith(".rsaml")).sorted().forEach(files::add);
            }
        }
        assertTrue(files.size() > 20, "examples and rule models found: " + files);
        int modules = 0;
        for (Path file : files) {
            LoadedModel model;
            try {
                model = ModelLoader.load(file, file.getFileName().toString());
            } catch (ModelLoadException e) {
                continue; // rule models of unreadable files
            }
            modules += agree(model.resource().getContents().get(0), file.getFileName().toString());
        }
        assertTrue(modules > 50, "modules compared: " + modules);
    }

    @Test
    void theTraversalAgreesWithTheInvariantOnRandomArchitectures() {
        Random random = new Random(SEED);
        int activated = 0;
        int compared = 0;
        for (int i = 0; i < 300; i++) {
            Architecture a = random(random);
            compared += agree(a, "random architecture " + i);
            ModuleActivation facts = new ModuleActivation();
            activated += (int) modules(a).stream().filter(facts::isActivated).count();
        }
        // Both outcomes occur often enough for the comparison to mean something.
        assertTrue(activated > compared / 5 && activated < compared * 4 / 5, activated + " of " + compared + " modules activated");
    }

    @Test
    void aChainOfTwentyThousandModulesFedByOneTimedModuleIsActivated() {
        int n = 20_000;
        Architecture a = chain(n);
        assertEquals(List.of(), rsa19(a), "every module of the chain is fed by the periodic first one");
        // Cut the chain after module 14,999: the 5,000 modules after it are fed by nothing timed.
        Connection cut = a.getConnections().get(14_999);
        cut.setSource(null);
        cut.setTarget(null);
        a.getConnections().remove(cut);
        List<String> found = rsa19(a);
        assertEquals(5_000, found.size(), "the modules after the cut are not activated");
        assertTrue(found.get(0).startsWith("Module 'm15000' is never activated"), found.get(0));
        assertTrue(found.get(4_999).startsWith("Module 'm19999' is never activated"), found.get(4_999));
    }

    @Test
    void aDenseGraphIsActivatedExactlyWhereATimedModuleFeedsIt() {
        // 60 modules, each feeding every other; one periodic module outside the clique feeds module 0.
        Architecture a = architecture();
        Layer layer = a.getLayers().get(0);
        List<Module> clique = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            clique.add(module(layer, "c" + i, false));
        }
        for (Module from : clique) {
            for (Module to : clique) {
                if (from != to) {
                    connect(a, from, to, DataType.NUMERIC);
                }
            }
        }
        assertEquals(60, rsa19(a).size(), "nothing timed feeds the clique: " + rsa19(a));
        connect(a, module(layer, "timer", true), clique.get(0), DataType.NUMERIC);
        assertEquals(List.of(), rsa19(a), "one timed feeder activates the whole clique");
    }

    @Test
    void theTraversalAgreesWithTheInvariantOnASmallDenseGraph() {
        // The interpreter's closure per module is too slow on the 60-module clique: the oracle gets 8.
        Architecture a = architecture();
        Layer layer = a.getLayers().get(0);
        List<Module> clique = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            clique.add(module(layer, "c" + i, false));
        }
        for (Module from : clique) {
            for (Module to : clique) {
                if (from != to) {
                    connect(a, from, to, DataType.NUMERIC);
                }
            }
        }
        assertEquals(8, agree(a, "unfed clique"), "the interpreted and the compiled check were compared on every module of the unfed clique");
        connect(a, module(layer, "timer", true), clique.get(3), DataType.NUMERIC);
        assertEquals(9, agree(a, "fed clique"), "the interpreted and the compiled check were compared on every module once the clique is fed");
    }

    /** Compares the two on every module below the root; returns how many were compared. */
    private static int agree(EObject root, String where) {
        OclRules ocl = OclRules.instance();
        ModuleActivation facts = new ModuleActivation();
        int n = 0;
        for (Iterator<EObject> it = root.eAllContents(); it.hasNext();) {
            if (it.next() instanceof Module m) {
                Boolean interpreted = ocl.check(RsamlPackage.Literals.MODULE, ModuleActivation.CONSTRAINT, m);
                assertEquals(interpreted, facts.isActivated(m), () -> where + ": module " + m.getName());
                n++;
            }
        }
        return n;
    }

    private static List<String> rsa19(Architecture a) {
        return RsamlModelValidator.validate(a).stream().filter(f -> f.ruleId().equals("RSA-19")).map(Finding::message)
                .collect(Collectors.toList());
    }

    private static List<Module> modules(Architecture a) {
        return a.getLayers().stream().flatMap(l -> l.getModules().stream()).toList();
    }

    private static Architecture architecture() {
        Architecture a = F.createArchitecture();
        a.setName("robot");
        a.setDeclaredLayers(1);
        Layer layer = F.createLayer();
        layer.setName("functional");
        a.getLayers().add(layer);
        return a;
    }

    private static Architecture chain(int n) {
        Architecture a = architecture();
        Layer layer = a.getLayers().get(0);
        Module previous = module(layer, "m0", true);
        for (int i = 1; i < n; i++) {
            Module next = module(layer, "m" + i, false);
            connect(a, previous, next, DataType.NUMERIC);
            previous = next;
        }
        return a;
    }

    private static Module module(Layer layer, String name, boolean periodic) {
        Module m = F.createModule();
        m.setName(name);
        if (periodic) {
            m.setExecType(ExecutionType.PERIODIC);
            m.setPeriod(10);
        }
        layer.getModules().add(m);
        return m;
    }

    private static void connect(Architecture a, Module from, Module to, DataType type) {
        OutputPort out = F.createOutputPort();
        out.setName("out" + from.getPorts().size());
        out.setDataType(type);
        from.getPorts().add(out);
        EntryPort in = F.createEntryPort();
        in.setName("in" + to.getPorts().size());
        in.setDataType(DataType.NUMERIC);
        to.getPorts().add(in);
        Connection c = F.createConnection();
        c.setSource(out);
        c.setTarget(in);
        a.getConnections().add(c);
    }

    /**
     * Up to 12 modules, some timed (by their own period, a function's or an action's, some with
     * period 0), connections and suppressors between random ports, some carrying another data type
     * or message type than their entry port.
     */
    private static Architecture random(Random random) {
        Architecture a = architecture();
        Layer layer = a.getLayers().get(0);
        int n = 1 + random.nextInt(12);
        List<Module> modules = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Module m = module(layer, "m" + i, false);
            switch (random.nextInt(8)) {
                case 0 -> {
                    m.setExecType(ExecutionType.PERIODIC);
                    m.setPeriod(random.nextBoolean() ? 10 : 0);
                }
                case 1 -> {
                    org.rsaml.model.Function f = F.createFunction();
                    f.setName("f");
                    f.setExecType(ExecutionType.PERIODIC);
                    f.setPeriod(random.nextInt(2) * 5);
                    m.getFunctions().add(f);
                }
                case 2 -> {
                    org.rsaml.model.Function f = F.createFunction();
                    f.setName("f");
                    org.rsaml.model.Action act = F.createAction();
                    act.setName("act");
                    act.setExecType(random.nextBoolean() ? ExecutionType.PERIODIC : ExecutionType.SPORADIC);
                    act.setPeriod(5);
                    f.getActions().add(act);
                    m.getFunctions().add(f);
                }
                case 3 -> m.setExecType(ExecutionType.SPORADIC);
                default -> {
                }
            }
            for (int p = random.nextInt(3); p > 0; p--) {
                EntryPort in = F.createEntryPort();
                in.setName("in" + m.getPorts().size());
                in.setDataType(random.nextInt(4) == 0 ? DataType.STRUCTURED : DataType.NUMERIC);
                in.setMessageType(random.nextBoolean() ? "Pose" : "Twist");
                m.getPorts().add(in);
            }
            for (int p = random.nextInt(3); p > 0; p--) {
                OutputPort out = F.createOutputPort();
                out.setName("out" + m.getPorts().size());
                out.setDataType(random.nextInt(4) == 0 ? DataType.STRUCTURED : DataType.NUMERIC);
                out.setMessageType(random.nextBoolean() ? "Pose" : "Twist");
                m.getPorts().add(out);
            }
            modules.add(m);
        }
        List<OutputPort> outs = modules.stream().flatMap(m -> m.getPorts().stream()).filter(OutputPort.class::isInstance)
                .map(OutputPort.class::cast).toList();
        List<EntryPort> ins = modules.stream().flatMap(m -> m.getPorts().stream()).filter(EntryPort.class::isInstance)
                .map(EntryPort.class::cast).toList();
        if (!outs.isEmpty() && !ins.isEmpty()) {
            for (int c = random.nextInt(2 * n); c > 0; c--) {
                OutputPort out = outs.get(random.nextInt(outs.size()));
                EntryPort in = ins.get(random.nextInt(ins.size()));
                if (random.nextInt(4) == 0) {
                    Suppressor s = F.createSuppressor();
                    s.setName("s" + c);
                    s.setTrigger(out);
                    s.setTarget(in);
                    in.getModule().getSuppressors().add(s);
                } else {
                    Connection connection = F.createConnection();
                    connection.setSource(out);
                    connection.setTarget(in);
                    a.getConnections().add(connection);
                }
            }
        }
        return a;
    }
}
