/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

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
    private final List<String> renamed = new ArrayList<>();

    public Ros2Packages(ExecutionPlan plan, CxxNames names) {
        this(plan, names, plan.architecture().getPackages());
    }

    Ros2Packages(ExecutionPlan plan, CxxNames names, PackageLayout layout) {
        this.layout = layout;
        this.system = names.project();
        String prefix = system.replaceFirst("_+$", "") + "_";
        NameScope scope = new NameScope(false, system, prefix + RsamlPackages.INTERFACES, prefix + RsamlPackages.RUNTIME);
        RsamlPackages.ROS2_OWN.forEach(scope::allocate); // a package per layer or processor never hides one of ROS 2's
        Map<Object, NodePackage> packages = new LinkedHashMap<>();
        switch (layout) {
            case PER_LAYER -> {
                for (PlannedLayer l : plan.layers()) {
                    if (!l.modules().isEmpty()) {
                        String holds = "layer '" + RsamlLabels.name(l.layer()) + "'";
                        packages.put(l, new NodePackage(allocate(scope, prefix + part(l.layer().getName(), names.layerId(l)), holds), holds));
                    }
                }
                plan.modules().forEach(m -> add(packages.get(m.layer()), m));
            }
            case PER_PROCESSOR -> {
                for (Processor p : plan.architecture().getProcessors()) {
                    if (plan.modules().stream().anyMatch(m -> m.processor() == p)) {
                        String holds = "processor '" + RsamlLabels.name(p) + "'";
                        packages.put(p, new NodePackage(allocate(scope, prefix + part(p.getName(), "processor"), holds), holds));
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

    /**
     * The package name {@code wanted} in {@code scope}, or the next free one; when that is because
     * {@code wanted} is one of ROS 2's own packages, a warning naming the element the package {@code holds}.
     */
    private String allocate(NameScope scope, String wanted, String holds) {
        String name = scope.allocate(wanted);
        if (!name.equals(wanted) && RsamlPackages.ROS2_OWN.contains(wanted)) {
            renamed.add(RsamlPackages.renamedFromOwn(holds, name, wanted, List.of(wanted), "the package of its nodes is"));
        }
        return name;
    }

    /**
     * The warnings of this layout: a package of a layer's or processor's nodes named otherwise than
     * {@code <architecture>_<part>} because that is one of ROS 2's own packages, as the architecture's
     * own package is said ({@link CxxNames#stableProject}).
     */
    public List<String> warnings() {
        return renamed;
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

    /** The setting under which the output's manifest keeps the layout it was generated with. */
    public static final String KEPT_LAYOUT = "packages";

    /** The architect's files every package of nodes, the runtime package and the launch files' package have, beside package.xml. */
    private static final List<String> PACKAGE_FILES = List.of("user.cmake", Ros2Manifest.FILE);

    /**
     * A package of a layout: its name, the modules whose nodes it builds, and whether it builds the
     * scheduling runtime.
     */
    private record Part(String name, List<PlannedModule> modules, boolean runtime) {
    }

    /** Every package of this layout that has a user.cmake and a package.user.xml, but the interfaces package (the same in every layout). */
    private List<Part> parts() {
        if (single()) {
            return List.of(new Part(system, nodePackages.get(0).modules, true));
        }
        List<Part> parts = new ArrayList<>(List.of(new Part(system, List.of(), false), new Part(runtime, List.of(), true)));
        nodePackages.forEach(np -> parts.add(new Part(np.name, np.modules, false)));
        return parts;
    }

    /**
     * The layout this output was generated with: the one its manifest keeps; for an output generated
     * before the manifest kept it, the other layout where the architect's classes are (and this one's
     * are not); null when it cannot have been another.
     */
    private PackageLayout previous(ExecutionPlan plan, CxxNames names, OutputContext output) {
        PackageLayout kept = PackageLayout.get(output.kept().getOrDefault(KEPT_LAYOUT, ""));
        if (kept != null) {
            return kept;
        }
        for (PackageLayout other : PackageLayout.VALUES) {
            Ros2Packages then = other == layout ? this : new Ros2Packages(plan, names, other);
            for (PlannedModule m : plan.modules()) {
                List<String> now = userFiles(of(m).name, names, m);
                List<String> before = userFiles(then.of(m).name, names, m);
                for (int i = 0; i < now.size(); i++) {
                    if (!now.get(i).equals(before.get(i)) && output.userFile(now.get(i)).isEmpty() && output.userFile(before.get(i)).isPresent()) {
                        return other;
                    }
                }
            }
        }
        return null;
    }

    /** Whether a user.cmake holds more than comments (RsaML creates it with comments only). */
    static boolean cmakeHasAdditions(String text) {
        return text.lines().map(String::strip).anyMatch(l -> !l.isEmpty() && !l.startsWith("#"));
    }

    /**
     * Keeps the architect's code where it is built when the layout changes (the output was generated
     * with another {@code packages}). Refuses, with nothing written and the list of what to do, when
     * a file of theirs would be left in a package this layout no longer has or no longer builds that
     * module in: each module's class (to move), and each old package's user.cmake and
     * package.user.xml that adds something of theirs (to merge into the files of the packages that now
     * build its nodes, then delete). The parameters file, the message files and the README are in the
     * same place in every layout. Returns warnings: a user.cmake or package.user.xml that stays but
     * whose package no longer builds nodes it added to (single to perLayer: the launch files' package
     * keeps its name), and the old packages' files that add nothing and are no longer used.
     */
    public List<String> checkUserCodeIsHere(ExecutionPlan plan, CxxNames names, OutputContext output) throws GenerationException {
        PackageLayout before = previous(plan, names, output);
        if (before == null || before == layout) {
            return List.of();
        }
        Ros2Packages then = new Ros2Packages(plan, names, before);
        List<String> moves = new ArrayList<>();
        for (PlannedModule m : plan.modules()) {
            List<String> now = userFiles(of(m).name, names, m);
            List<String> old = userFiles(then.of(m).name, names, m);
            for (int i = 0; i < now.size(); i++) {
                if (!now.get(i).equals(old.get(i)) && output.userFile(now.get(i)).isEmpty() && output.userFile(old.get(i)).isPresent()) {
                    moves.add(old.get(i) + " -> " + now.get(i));
                }
            }
        }
        Map<String, Part> nowParts = new LinkedHashMap<>();
        parts().forEach(p -> nowParts.put(p.name(), p));
        List<String> merges = new ArrayList<>();
        List<String> stays = new ArrayList<>();
        List<String> unused = new ArrayList<>();
        for (Part old : then.parts()) {
            Part same = nowParts.get(old.name());
            // The packages that now build what this one built and the package at its path does not.
            Set<String> into = new LinkedHashSet<>();
            for (PlannedModule m : old.modules()) {
                if (same == null || !same.modules().contains(m)) {
                    into.add(of(m).name);
                }
            }
            if (old.runtime() && (same == null || !same.runtime())) {
                into.add(runtime);
            }
            for (String file : PACKAGE_FILES) {
                String path = old.name() + "/" + file;
                Optional<String> text = output.userFile(path);
                if (text.isEmpty()) {
                    continue;
                }
                boolean additions = file.equals(Ros2Manifest.FILE) ? Ros2Manifest.hasAdditions(path, text.get()) : cmakeHasAdditions(text.get());
                List<String> targets = into.stream().map(p -> p + "/" + file).toList();
                if (same == null && additions) {
                    merges.add(path + " into " + String.join(" and ", targets));
                } else if (same == null) {
                    unused.add(path);
                } else if (additions && !targets.isEmpty()) {
                    stays.add("what " + path + " adds for " + (old.modules().isEmpty() ? "the scheduling runtime" : "the nodes")
                            + " now built elsewhere goes into " + String.join(" and ", targets));
                }
            }
        }
        String change = "packages " + before.getLiteral() + " (this output) to " + layout.getLiteral() + " (the model)";
        if (!moves.isEmpty() || !merges.isEmpty()) {
            List<String> todo = new ArrayList<>();
            if (!moves.isEmpty()) {
                todo.add("Move each of these files of yours to its new package (paths in the output directory): " + String.join(", ", moves) + ".");
            }
            if (!merges.isEmpty()) {
                todo.add("These files of yours are in packages the new layout does not have; merge what each adds into the files of the"
                        + " packages that now build its nodes, then delete it: " + String.join("; ", merges) + ".");
            }
            if (!stays.isEmpty()) {
                todo.add("Also, " + String.join("; ", stays) + ".");
            }
            String first = moves.isEmpty() ? merges.get(0).replaceFirst(" into .*", "") : moves.get(0).replaceFirst(" -> .*", "");
            throw new GenerationException(first, "nothing generated: the layout changes from " + change + ", and generating would leave"
                    + " your code behind where nothing builds it. " + String.join(" ", todo) + " Then generate again; or set packages back to "
                    + before.getLiteral() + ".");
        }
        List<String> warnings = new ArrayList<>();
        if (!stays.isEmpty()) {
            warnings.add("the layout changed from " + change + ": " + String.join("; ", stays)
                    + " (the package it is in no longer builds those)");
        }
        if (!unused.isEmpty()) {
            warnings.add("the layout changed from " + change + ": " + String.join(", ", unused) + " are left over in packages the new"
                    + " layout does not have, unchanged since RsaML created them and no longer used; delete them");
        }
        return warnings;
    }
}
