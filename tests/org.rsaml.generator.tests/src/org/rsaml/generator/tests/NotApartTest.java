/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.Architecture;
import org.rsaml.model.Module;
import org.rsaml.validation.ModelLoader;

/**
 * {@link PlatformCheck#notApart}, the one rule by which {@link JobTimingTest} (C++) and {@link Ros2LaunchTest} (ROS 2)
 * leave a release's bound unchecked because its threads do not have a CPU to themselves on the machine, as each target
 * places them: a core the machine lacks, the modules without a core of several hosts, EDF deadline threads on every
 * core, the modules without a core (kept to the cores no processor claims by both: the C++ program's threads, the ROS 2
 * launch's processes), two processors without a core.
 */
class NotApartTest {

    private static final PlatformCheck.Placement CPP = PlatformCheck.Placement.CPP;
    private static final PlatformCheck.Placement ROS2 = PlatformCheck.Placement.ROS2;

    private static Architecture model(Path tmp, String modules, String processors) throws Exception {
        Path file = tmp.resolve("apart.rsaml");
        Files.writeString(file, JobTimingTest.modelText("apart", modules, processors));
        return ModelLoader.load(file, "apart.rsaml").architecture();
    }

    private static String processor(String name, String attributes, String... modules) {
        StringBuilder refs = new StringBuilder();
        for (String m : modules) {
            refs.append(refs.length() == 0 ? "" : " ").append("//@layers[name='tasks']/@modules[name='").append(m).append("']");
        }
        return "  <processors name=\"" + name + "\" " + attributes + " modules=\"" + refs + "\"/>\n";
    }

    private static Module module(Architecture arch, String name) {
        return arch.getLayers().get(0).getModules().stream().filter(m -> m.getName().equals(name)).findFirst().orElseThrow();
    }

    private static final String TWO = JobTimingTest.module("a", 10, 1, "RM") + JobTimingTest.module("b", 20, 2, "RM");
    private static final String THREE = TWO + JobTimingTest.module("c", 50, 5, "RM");

    @Test
    void aProcessorWhoseCoreTheMachineLacksRunsAnywhereSoNoProcessorIsApart(@TempDir Path tmp) throws Exception {
        // as hierarchical-nasrem's planningCore (core 2) beside core 1 on a two-CPU machine
        Architecture arch = model(tmp, TWO, processor("primitive", "core=\"1\"", "a") + processor("planning", "core=\"2\"", "b"));
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            String why = PlatformCheck.notApart(arch, module(arch, "a"), target, 2);
            assertEquals("processor planning's core 2 is not among this machine's 2, so its threads run anywhere", why, target.name());
            assertTrue(PlatformCheck.notApart(arch, module(arch, "b"), target, 2) != null, target.name());
            // on a machine with a CPU 2, each has its own
            assertNull(PlatformCheck.notApart(arch, module(arch, "a"), target, 3), target.name());
            assertNull(PlatformCheck.notApart(arch, module(arch, "b"), target, 3), target.name());
        }
    }

    @Test
    void theModulesWithoutACoreOfSeveralHostsAreNotApart(@TempDir Path tmp) throws Exception {
        // b on a board's processor without a core, c on no processor (the main host's), a pinned to core 0
        Architecture arch = model(tmp, THREE, processor("cpu0", "core=\"0\"", "a") + processor("board", "host=\"nav-board\"", "b"));
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            for (String m : new String[] {"a", "b", "c"}) {
                assertEquals("the modules without a core of hosts [main, nav-board] share CPUs the analysis counts apart",
                        PlatformCheck.notApart(arch, module(arch, m), target, 4), target + " " + m);
            }
        }
    }

    @Test
    void aProcessorWithACoreTheMachineHasIsApart(@TempDir Path tmp) throws Exception {
        Architecture arch = model(tmp, TWO, processor("cpu0", "core=\"0\"", "a") + processor("cpu1", "core=\"1\"", "b"));
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            assertNull(PlatformCheck.notApart(arch, module(arch, "a"), target, 2), target.name());
            assertNull(PlatformCheck.notApart(arch, module(arch, "b"), target, 2), target.name());
        }
    }

    @Test
    void theModulesWithoutACoreHaveTheCoresNoProcessorClaimsOnBothTargets(@TempDir Path tmp) throws Exception {
        // a pinned to core 1, b and c on no processor: on both targets kept off core 1 (C++: their threads; ROS 2: their
        // container's taskset), so each processor has CPUs no other's threads use
        Architecture arch = model(tmp, THREE, processor("cpu1", "core=\"1\"", "a"));
        Architecture claimed = model(tmp, THREE, processor("cpu0", "core=\"0\"", "a") + processor("cpu1", "core=\"1\"", "b"));
        Architecture none = model(tmp, TWO, "");
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            assertNull(PlatformCheck.notApart(arch, module(arch, "a"), target, 2), target.name());
            assertNull(PlatformCheck.notApart(arch, module(arch, "b"), target, 2), target.name());
            // b and c on the two cores left of three
            assertNull(PlatformCheck.notApart(arch, module(arch, "b"), target, 3), target.name());
            // every core claimed: c runs on every one, a's and b's included
            assertEquals("no core is left for the modules without one, so they run on every core", PlatformCheck.notApart(claimed, module(claimed, "a"),
                    target, 2), target.name());
            assertEquals("it has no core of its own and no core is left for it, so it runs on every core, the processors' included",
                    PlatformCheck.notApart(claimed, module(claimed, "c"), target, 2), target.name());
            assertNull(PlatformCheck.notApart(claimed, module(claimed, "a"), target, 3), target.name());
            assertNull(PlatformCheck.notApart(claimed, module(claimed, "c"), target, 3), target.name());
            // no processor at all: the 'default' processor's threads alone on every CPU
            assertNull(PlatformCheck.notApart(none, module(none, "a"), target, 1), target.name());
            assertNull(PlatformCheck.notApart(none, module(none, "a"), target, 2), target.name());
        }
    }

    @Test
    void twoProcessorsWithoutACoreShareTheCoresLeft(@TempDir Path tmp) throws Exception {
        // a pinned to core 1, b on a processor without a core, c on none ('default'): b and c on the same CPUs
        Architecture arch = model(tmp, THREE, processor("cpu1", "core=\"1\"", "a") + processor("free", "", "b"));
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            assertNull(PlatformCheck.notApart(arch, module(arch, "a"), target, 3), target.name());
            for (String m : new String[] {"b", "c"}) {
                assertEquals("it has no core of its own and shares the CPUs no processor claims with the modules of processors [default, free],"
                        + " which have none either", PlatformCheck.notApart(arch, module(arch, m), target, 3), target + " " + m);
            }
        }
    }

    @Test
    void theDeadlineThreadsOfAnEdfProcessorRunOnEveryCore(@TempDir Path tmp) throws Exception {
        // as ros2-edf: 'edf' without a core (a, b), 'pinnedEdf' on core 1 (c)
        String modules = JobTimingTest.module("a", 5, 2, "EDF") + JobTimingTest.module("b", 7, 4, "EDF") + JobTimingTest.module("c", 10, 2, "EDF");
        Architecture arch = model(tmp, modules, processor("edf", "schedPolicy=\"EDF\"", "a", "b")
                + processor("pinnedEdf", "schedPolicy=\"EDF\" core=\"1\"", "c"));
        // C++ leaves the releases of an EDF processor with a core on every core, ahead of the other processor's threads
        assertEquals("the deadline threads of EDF processor pinnedEdf run on every core", PlatformCheck.notApart(arch, module(arch, "a"), CPP, 2));
        // ROS 2 pins its process with taskset: refused SCHED_DEADLINE, it stays on core 1
        assertNull(PlatformCheck.notApart(arch, module(arch, "a"), ROS2, 2));
        // on both targets 'edf' is kept to the core pinnedEdf leaves (refused SCHED_DEADLINE there): pinnedEdf keeps its core
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            assertNull(PlatformCheck.notApart(arch, module(arch, "c"), target, 2), target.name());
        }
        // a fixed-priority processor beside an EDF one without a core keeps its core on both targets, the EDF one the core left
        Architecture mixed = model(tmp, modules, processor("edf", "schedPolicy=\"EDF\"", "a", "b") + processor("rm", "core=\"1\"", "c"));
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            assertNull(PlatformCheck.notApart(mixed, module(mixed, "c"), target, 2), target.name());
            assertNull(PlatformCheck.notApart(mixed, module(mixed, "a"), target, 2), target.name());
        }
        // no processor claims a core: the EDF processor without one runs its deadline threads on every core, the other
        // processor without a core's too (which shares them anyway)
        Architecture free = model(tmp, modules, processor("edf", "schedPolicy=\"EDF\"", "a", "b") + processor("rm", "", "c"));
        for (PlatformCheck.Placement target : PlatformCheck.Placement.values()) {
            assertEquals("the deadline threads of EDF processor edf run on every core", PlatformCheck.notApart(free, module(free, "c"), target, 2),
                    target.name());
        }
    }
}
