/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedLayer;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.generator.GenerationException;
import org.rsaml.generator.internal.NameScope;
import org.rsaml.generator.internal.cxx.CxxNames;
import org.rsaml.generator.spi.OutputContext;
import org.rsaml.model.PackageLayout;
import org.rsaml.model.Processor;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlPackages;

/**
 * The ROS 2 packages of one generation and which node goes into which (Architecture.packages). With
 * {@code single} (the default) one package, named after the architecture, holds every node, the
 * scheduling runtime, the component container, the lifecycle manager, the launch files and the
 * parameters file. With {@code perLayer} or {@code perProcessor} the nodes of each layer (or
 * processor: {@code default} for the modules no processor names) are a package of their own,
 * {@code <architecture>_<part>} ({@link RsamlPackages}, whose rule RSA-29 refuses unusable names);
 * the scheduling runtime with the container and the lifecycle manager is {@code <architecture>_runtime},
 * which the node packages build on; the package named after the architecture keeps the launch files
 * and the parameters file and depends on the others at run time. The message types the model names
 * are in the interfaces package in every layout.
 */
public final class Ros2Packages {

    /** A package of nodes: its name, what it holds (for its description) and its modules, in model order. */
    public static final class NodePackage {
        public final String name;
        /** {@code layer 'navigation'}, {@code processor 'core0'}, the modules no processor names; null with {@code single}. */
        public final String holds;
        public final List<PlannedModule> modules = new ArrayList<>();

        NodePackage(String name, String holds) {
            this.name = name;
            this.holds = holds;
        }
    }

    private final PackageLayout layout;
    private final String system;
    private final String runtime;
    private final List<NodePackage> nodePackages = new ArrayList<>();
    private final Map<PlannedModule, NodePackage> byModule = new IdentityHashMap<>();

    public Ros2Packages(ExecutionPlan plan, CxxNames names) {
        this(plan, names, plan.architecture().getPackages());
    }

    Ros2Packages(ExecutionPlan plan, CxxNames names, PackageLayout layout) {
        this.layout = layout;
        this.system = names.project();
        String prefix = system.replaceFirst("_+$", "") + "_";
        NameScope scope = new NameScope(false, system, prefix + RsamlPackages.INTERFACES, prefix + RsamlPackages.RUNTIME);
        Map<Object, NodePackage> packages = new LinkedHashMap<>();
        switch (layout) {
            case PER_LAYER -> {
                for (PlannedLayer l : plan.layers()) {
                    if (!l.modules().isEmpty()) {
                        packages.put(l, new NodePackage(scope.allocate(prefix + part(l.layer().getName(), names.layerId(l))),
                                "layer '" + RsamlLabels.name(l.layer()) + "'"));
                    }
                }
                plan.modules().forEach(m -> add(packages.get(m.layer()), m));
            }
            case PER_PROCESSOR -> {
                for (Processor p : plan.architecture().getProcessors()) {
                    if (plan.modules().stream().anyMatch(m -> m.processor() == p)) {
                        packages.put(p, new NodePackage(scope.allocate(prefix + part(p.getName(), "processor")),
                                "processor '" + RsamlLabels.name(p) + "'"));
                    }
                }
                for (PlannedModule m : plan.modules()) {
                    Object key = m.processor() == null ? RsamlPackages.DEFAULT : m.processor();
                    add(packages.computeIfAbsent(key, k -> new NodePackage(scope.allocate(prefix + RsamlPackages.DEFAULT),
                            "the modules no processor names")), m);
                }
            }
            default -> {
                NodePackage all = new NodePackage(system, null);
                packages.put(all, all);
                plan.modules().forEach(m -> add(all, m));
            }
        }
        nodePackages.addAll(packages.values());
        this.runtime = layout == PackageLayout.SINGLE ? system : prefix + RsamlPackages.RUNTIME;
    }

    /** The part a layer or processor gives a package name; with --force and an RSA-29 error, a sanitised stand-in. */
    private static String part(String name, String otherwise) {
        String part = RsamlPackages.part(name);
        return part.isEmpty() ? otherwise : part;
    }

    private void add(NodePackage p, PlannedModule m) {
        p.modules.add(m);
        byModule.put(m, p);
    }

    /** Whether one package holds everything (packages single). */
    public boolean single() {
        return layout == PackageLayout.SINGLE;
    }

    /** The package of the launch files and the parameters file, named after the architecture (with single, of everything). */
    public String system() {
        return system;
    }

    /** The package of the scheduling runtime, the component container and the lifecycle manager. */
    public String runtime() {
        return runtime;
    }

    /** The packages of nodes, in model order. */
    public List<NodePackage> nodePackages() {
        return nodePackages;
    }

    /** The package of a module's node. */
    public NodePackage of(PlannedModule m) {
        return byModule.get(m);
    }

    /** The architect's files of a module (its class, header and source), relative to the output. */
    public static List<String> userFiles(String pkg, CxxNames names, PlannedModule m) {
        String dir = pkg + "/src/" + names.layerId(m) + "/" + names.className(m);
        return List.of(dir + ".hpp", dir + ".cpp");
    }

    /**
     * Refuses a layout that would leave the architect's code behind: when a module's class of the
     * architect's is not where this layout puts it but where another layout put it (the output was
     * generated with another packages), nothing is written and the exception lists what to move.
     */
    public void checkUserCodeIsHere(ExecutionPlan plan, CxxNames names, OutputContext output) throws GenerationException {
        List<String> moves = new ArrayList<>();
        String from = null;
        for (PackageLayout other : PackageLayout.VALUES) {
            if (other == layout) {
                continue;
            }
            Ros2Packages then = new Ros2Packages(plan, names, other);
            for (PlannedModule m : plan.modules()) {
                List<String> now = userFiles(of(m).name, names, m);
                List<String> before = userFiles(then.of(m).name, names, m);
                for (int i = 0; i < now.size(); i++) {
                    if (!now.get(i).equals(before.get(i)) && output.userFile(now.get(i)).isEmpty() && output.userFile(before.get(i)).isPresent()) {
                        moves.add(before.get(i) + " -> " + now.get(i));
                        from = Optional.ofNullable(from).orElse(other.getLiteral());
                    }
                }
            }
        }
        if (moves.isEmpty()) {
            return;
        }
        throw new GenerationException(moves.get(0).replaceFirst(" -> .*", ""), "nothing generated: the model asks for packages "
                + layout.getLiteral() + ", but your code in this output is where packages " + from + " put it; generating would leave it"
                + " behind. Move each file of yours to its new package (paths in the output directory): " + String.join(", ", moves)
                + " (and what your user.cmake and package.user.xml of the old package add for these nodes to those of the new one),"
                + " then generate again; or set packages back to " + from + ".");
    }
}
