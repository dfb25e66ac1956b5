/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.analysis.LatencyResult;
import org.rsaml.analysis.TimingAnalysis;
import org.rsaml.analysis.Verdict;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.OutputPort;
import org.rsaml.model.RsamlFactory;

/**
 * The plan of a clean model of any size: a chain of 100,000 modules that react to each other's
 * data, fed by one timed module, is planned and searched for reactive cycles without running out
 * of stack (the search is iterative); closed into a ring, it is one cycle of all its reacting modules;
 * a latency requirement along a chain of 20,000 is searched to its end.
 */
class ExecutionPlanScaleTest {

    private static final int MODULES = 100_000;

    /** m0 (periodic, 10 ms) -> m1 -> ... -> m(n-1), each reacting to data; with {@code ring}, m(n-1) -> m1 too. */
    private static Architecture chain(int n, boolean ring) {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        Architecture a = f.createArchitecture();
        a.setName("chain");
        Layer layer = f.createLayer();
        layer.setName("reactive");
        a.getLayers().add(layer);
        OutputPort previous = null;
        EntryPort first = null;
        for (int i = 0; i < n; i++) {
            Module m = f.createModule();
            m.setName("m" + i);
            if (i == 0) {
                m.setExecType(ExecutionType.PERIODIC);
                m.setPeriod(10);
            } else {
                m.setExecType(ExecutionType.SPORADIC);
                m.setPeriod(10);
            }
            layer.getModules().add(m);
            if (i > 0) {
                EntryPort in = f.createEntryPort();
                in.setName("in");
                m.getPorts().add(in);
                a.getConnections().add(connection(previous, in));
                if (i == 1) {
                    first = in;
                }
            }
            OutputPort out = f.createOutputPort();
            out.setName("out");
            m.getPorts().add(out);
            previous = out;
        }
        if (ring) {
            a.getConnections().add(connection(previous, first));
        }
        return a;
    }

    private static Connection connection(OutputPort source, EntryPort target) {
        Connection c = RsamlFactory.eINSTANCE.createConnection();
        c.setSource(source);
        c.setTarget(target);
        return c;
    }

    @Test
    void aChainOf100000ReactingModulesIsPlannedAndClosedIntoARingIsOneCycle() throws Exception {
        Architecture architecture = chain(MODULES, false);
        ExecutionPlan plan = ExecutionPlan.of(architecture);
        assertEquals(MODULES, plan.modules().size(), "every module is planned");
        assertEquals(MODULES - 1, plan.flows().size(), "every connection carries data");
        assertEquals(MODULES - 1, plan.reactions().size(), "every module but the first reacts to data");
        assertEquals(1, plan.releases().size(), "the first module is released every 10 ms");
        assertTrue(plan.warnings().isEmpty(), () -> "a clean model plans without warnings: " + plan.warnings());
        assertEquals(List.of(), plan.reactiveCycles(), "a chain has no reactive cycle");

        Module last = architecture.getLayers().get(0).getModules().get(MODULES - 1);
        Module second = architecture.getLayers().get(0).getModules().get(1);
        architecture.getConnections().add(connection((OutputPort) last.getPorts().get(1), (EntryPort) second.getPorts().get(0)));
        List<List<PlannedModule>> cycles = ExecutionPlan.of(architecture).reactiveCycles();
        assertEquals(1, cycles.size(), "the ring is one cycle");
        List<PlannedModule> cycle = cycles.get(0);
        assertEquals(MODULES - 1, cycle.size(), "every reacting module is in it, the timed one is not");
        assertEquals("reactive/m1", cycle.get(0).qualifiedName(), "in module order");
        assertEquals("reactive/m" + (MODULES - 1), cycle.get(cycle.size() - 1).qualifiedName(), "in module order");
    }

    /**
     * A latency requirement along the whole chain, each module on a processor (and core) of its own:
     * the search follows its one path to the end without running out of stack, 10 ms a hop (each
     * module waits up to its period or minimum interval, and takes no time).
     */
    @Test
    void aLatencyRequirementAlongA20000ModuleChainIsSearchedToItsEnd() throws Exception {
        RsamlFactory f = RsamlFactory.eINSTANCE;
        int n = 20_000; // deep enough to overflow a recursive search; each module is a processor to analyse
        Architecture architecture = chain(n, false);
        List<Module> modules = architecture.getLayers().get(0).getModules();
        for (int i = 0; i < n; i++) {
            org.rsaml.model.Processor p = f.createProcessor();
            p.setName("p" + i);
            p.setCore(i);
            p.getModules().add(modules.get(i));
            architecture.getProcessors().add(p);
        }
        org.rsaml.model.Sensor laser = f.createSensor();
        laser.setName("laser");
        architecture.getSensors().add(laser);
        modules.get(0).getSensors().add(laser);
        org.rsaml.model.Actuator wheels = f.createActuator();
        wheels.setName("wheels");
        architecture.getActuators().add(wheels);
        modules.get(n - 1).getActuators().add(wheels);
        org.rsaml.model.LatencyRequirement r = f.createLatencyRequirement();
        r.setName("end");
        r.setSource(laser);
        r.setTarget(wheels);
        r.setTimeUnit(org.rsaml.model.TimeUnit.S);
        r.setMaxLatency(2000);
        architecture.getLatencyRequirements().add(r);

        LatencyResult result = TimingAnalysis.analyse(architecture).latencies().get(0);
        assertEquals(Verdict.MEETS, result.verdict(), result.explanation());
        assertEquals(1, result.paths(), result.explanation());
        assertEquals(n * 10_000_000L, result.reactionNs(), "10 ms for each of the chain's modules");
        assertEquals(n, result.worstPath().size(), "a hop per module");
    }

    @Test
    void cyclesAreFoundAmongOthersAndSelfLoopsCount() throws Exception {
        // m0 -> m1 -> m2 -> m3 -> m1 (a cycle of three), plus m3 -> m3's own entry (a self-loop inside it)
        Architecture a = chain(4, true);
        Module m3 = a.getLayers().get(0).getModules().get(3);
        Module m4 = RsamlFactory.eINSTANCE.createModule();
        m4.setName("m4");
        a.getLayers().get(0).getModules().add(m4);
        EntryPort in4 = RsamlFactory.eINSTANCE.createEntryPort();
        in4.setName("in");
        OutputPort out4 = RsamlFactory.eINSTANCE.createOutputPort();
        out4.setName("out");
        m4.getPorts().add(in4);
        m4.getPorts().add(out4);
        a.getConnections().add(connection((OutputPort) m3.getPorts().get(1), in4));
        a.getConnections().add(connection(out4, in4));
        List<List<String>> cycles = ExecutionPlan.of(a).reactiveCycles().stream()
                .map(c -> c.stream().map(PlannedModule::qualifiedName).toList()).toList();
        assertEquals(List.of(List.of("reactive/m4"), List.of("reactive/m1", "reactive/m2", "reactive/m3")), cycles,
                "a module feeding itself is a cycle, found first as the search finishes it first");
    }
}
