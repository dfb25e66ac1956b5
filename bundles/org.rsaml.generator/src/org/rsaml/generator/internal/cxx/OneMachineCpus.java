/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cxx;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;

import org.rsaml.model.Architecture;
import org.rsaml.model.Processor;
import org.rsaml.model.support.RsamlLabels;

/**
 * The CPU of one machine that runs every host's modules (the C++ program; a ROS 2 launch without
 * {@code host:=}) for each processor's core (docs/timing.md, "Other machines"). The analysis counts
 * the processors of different hosts apart (core 0 of a board is not core 0 of the main host), so
 * on one machine they must not share a CPU either: the first host (the main one, else the first by
 * name) keeps its cores' numbers, and every core of another host, host by host (by name) and core by
 * core, takes its own number when no host's core has taken it, else the lowest number none has
 * taken. A machine without that CPU runs the processor's threads where the operating system puts
 * them, and the program says so.
 */
public final class OneMachineCpus {
    private OneMachineCpus() {
    }

    /** The CPU of each processor with a core and modules. */
    public static Map<Processor, Integer> of(Architecture arch) {
        TreeMap<String, TreeSet<Integer>> byHost = new TreeMap<>(); // "" (the main host) first
        for (Processor p : arch.getProcessors()) {
            if (p.getCore() >= 0 && !p.getModules().isEmpty()) {
                byHost.computeIfAbsent(RsamlLabels.host(p), h -> new TreeSet<>()).add(p.getCore());
            }
        }
        Map<String, Integer> cpuOf = new HashMap<>();
        Set<Integer> taken = new HashSet<>();
        boolean first = true;
        for (Map.Entry<String, TreeSet<Integer>> host : byHost.entrySet()) {
            for (int core : host.getValue()) {
                int cpu = core;
                if (!first && taken.contains(core)) {
                    cpu = 0;
                    while (taken.contains(cpu)) {
                        cpu++;
                    }
                }
                taken.add(cpu);
                cpuOf.put(host.getKey() + "\0" + core, cpu);
            }
            first = false;
        }
        Map<Processor, Integer> cpus = new HashMap<>();
        for (Processor p : arch.getProcessors()) {
            Integer cpu = cpuOf.get(RsamlLabels.host(p) + "\0" + p.getCore());
            if (cpu != null) {
                cpus.put(p, cpu);
            }
        }
        return cpus;
    }

    /**
     * The CPUs the processors with a core (and modules) claim, by where the system is started: {@code ""}, one machine
     * runs every host (the C++ program, a ROS 2 launch without {@code host:=}): the CPUs {@link #of} gives; a host's name
     * ({@link RsamlLabels#MAIN_HOST} for the processors without one), only that host's processors run: their cores. The threads of the
     * modules without a core are kept off them, on the CPUs left, when some CPU is claimed (docs/timing.md, "One CPU per
     * processor"): the C++ runtime (System::claim_cores, from each module's CPU, which {@link #cpu} gives) and the ROS 2
     * launch (the taskset of the processes of the processors without a core) alike.
     */
    public static Map<String, SortedSet<Integer>> claimed(Architecture arch) {
        Map<String, SortedSet<Integer>> claimed = new TreeMap<>();
        claimed.put("", new TreeSet<>(of(arch).values()));
        for (Processor p : arch.getProcessors()) {
            SortedSet<Integer> cores = claimed.computeIfAbsent(RsamlLabels.hostName(p), h -> new TreeSet<>());
            if (p.getCore() >= 0 && !p.getModules().isEmpty()) {
                cores.add(p.getCore());
            }
        }
        return claimed;
    }

    /** The CPU of processor p's core on one machine, or -1 when it has no core (or no modules). */
    public static int cpu(Processor p) {
        if (p == null || p.getCore() < 0 || !(p.eContainer() instanceof Architecture arch)) {
            return -1;
        }
        return of(arch).getOrDefault(p, -1);
    }
}
