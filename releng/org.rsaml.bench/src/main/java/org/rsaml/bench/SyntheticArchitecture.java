/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Processor;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.util.RsamlResourceFactoryImpl;

/**
 * The layered architecture every benchmark measures: 4 layers; per module an entry and an output
 * port, and a connection from each module's output port to the next module's entry port. What a
 * module holds besides its ports is the benchmark's {@link Shape}: {@link #of} gives the validation,
 * generation and diagram benchmarks a periodic RM function of 3 actions with start dates and a
 * function of 2 actions run on each arrival of data, the module sporadic (data at most every 100 ms,
 * so that its reaction is analysed too) (11 elements a module), clean or with a few defects for validation
 * to find (about 1% of modules over their layer's budget, RSA-08, and 1% of connections between
 * ports of different data types, RSA-02); {@code TimingBench} gives real-time periodic modules.
 */
final class SyntheticArchitecture {

    static final int LAYERS = 4;
    /** The module, 2 ports, 2 functions, 5 actions, 1 connection. */
    static final int ELEMENTS_PER_MODULE = 11;

    /** What module {@code i} of {@code modules} holds besides its two ports. */
    @FunctionalInterface
    interface Shape {
        void shape(Module module, int i, int modules);
    }

    /** An architecture and the ports of its modules, in module order. */
    record Built(Architecture architecture, List<Layer> layers, List<EntryPort> ins, List<OutputPort> outs) {
    }

    private SyntheticArchitecture() {
    }

    /** The number of modules that gives about {@code elements} elements. */
    static int modulesFor(int elements) {
        return Math.max(LAYERS, elements / ELEMENTS_PER_MODULE);
    }

    static Architecture of(int modules, boolean defects) {
        return build("synthetic", ArchitectureCategory.HIERARCHICAL, modules, (m, i, n) -> {
            m.setExecDuration(defects && i % 97 == 5 ? 7.5 : 2.0);
            // The module reacts to its data at most every 100 ms (sporadic), so that its reaction is analysed
            // and does not take the analysis of its periodic function with it (RSA-24)
            m.setExecType(ExecutionType.SPORADIC);
            m.setPeriod(100);
            if (defects && i % 101 == 7) {
                ((EntryPort) m.getPorts().get(0)).setDataType(DataType.BOOLEAN);
            }
            RsamlFactory f = RsamlFactory.eINSTANCE;
            Function periodic = f.createFunction();
            periodic.setName("control");
            periodic.setExecType(ExecutionType.PERIODIC);
            periodic.setPeriod(20 + 10 * (i % 5));
            periodic.setSchedPolicy(SchedulingPolicy.RM);
            m.getFunctions().add(periodic);
            for (int j = 0; j < 3; j++) {
                var action = f.createAction();
                action.setName("step" + j);
                action.setExecDuration(0.5);
                action.setStartDate(j * 0.5);
                periodic.getActions().add(action);
            }
            Function onData = f.createFunction();
            onData.setName("update");
            onData.setType(ElementType.SIMPLE);
            m.getFunctions().add(onData);
            for (int j = 0; j < 2; j++) {
                var action = f.createAction();
                action.setName("apply" + j);
                onData.getActions().add(action);
            }
        }).architecture();
    }

    /**
     * {@code modules} modules named {@code m0, m1, ...} spread in order over {@link #LAYERS} layers
     * (at least one module), each with an entry port {@code in} (numeric) and an output port
     * {@code out}, each connected to the next, and shaped by {@code shape}.
     */
    static Built build(String name, ArchitectureCategory category, int modules, Shape shape) {
        if (modules < 1) {
            throw new IllegalArgumentException("a synthetic architecture needs at least 1 module, not " + modules);
        }
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName(name);
        a.setCategory(category);
        a.setDeclaredLayers(LAYERS);
        List<Layer> layers = new ArrayList<>();
        for (int l = 0; l < LAYERS; l++) {
            Layer layer = f.createLayer();
            layer.setName("layer" + l);
            layer.setLevel(l);
            layer.setMaxExecTime(5.0);
            a.getLayers().add(layer);
            layers.add(layer);
        }
        List<EntryPort> ins = new ArrayList<>();
        List<OutputPort> outs = new ArrayList<>();
        for (int i = 0; i < modules; i++) {
            Module m = f.createModule();
            m.setName("m" + i);
            layers.get((int) ((long) i * LAYERS / modules)).getModules().add(m);
            EntryPort in = f.createEntryPort();
            in.setName("in");
            in.setDataType(DataType.NUMERIC);
            OutputPort out = f.createOutputPort();
            out.setName("out");
            m.getPorts().add(in);
            m.getPorts().add(out);
            shape.shape(m, i, modules);
            if (i > 0) {
                connect(a, outs.get(i - 1), in);
            }
            ins.add(in);
            outs.add(out);
        }
        return new Built(a, layers, ins, outs);
    }

    static void connect(Architecture a, OutputPort from, EntryPort to) {
        Connection c = RsamlFactory.eINSTANCE.createConnection();
        c.setSource(from);
        c.setTarget(to);
        a.getConnections().add(c);
    }

    /**
     * Allocates the modules, in order, to processors of {@code perProcessor} modules, each with a
     * core of its own, so that a clean architecture's timing holds too (on one processor the
     * periodic functions of 1,000 modules would need many times its capacity: RSA-22).
     */
    static Architecture deploy(Architecture a, int perProcessor) {
        List<Module> all = a.getLayers().stream().flatMap(l -> l.getModules().stream()).toList();
        for (int i = 0; i < all.size(); i += perProcessor) {
            Processor p = RsamlFactory.eINSTANCE.createProcessor();
            p.setName("cpu" + i / perProcessor);
            p.setCore(i / perProcessor);
            p.getModules().addAll(all.subList(i, Math.min(all.size(), i + perProcessor)));
            a.getProcessors().add(p);
        }
        return a;
    }

    static void write(Architecture a, Path file) throws Exception {
        ResourceSetImpl set = new ResourceSetImpl();
        set.getResourceFactoryRegistry().getExtensionToFactoryMap().put("rsaml", new RsamlResourceFactoryImpl());
        Resource r = set.createResource(URI.createFileURI(file.toString()));
        r.getContents().add(a);
        r.save(Map.of());
        r.unload();
    }
}
