/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.Reaction;
import org.rsaml.analysis.plan.Release;
import org.rsaml.analysis.plan.UnplannableException;
import org.rsaml.model.Architecture;
import org.rsaml.model.RsamlPackage;
import org.rsaml.tests.support.models.RandomModels;
import org.rsaml.tests.support.models.RandomModels.Shape;
import org.rsaml.tests.support.models.RandomModels.Values;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;

/**
 * The plan the timing analysis reads of an architecture without latency requirements
 * ({@link ExecutionPlan#releasesOf}: no ports, flows or links) is the whole plan's ({@link ExecutionPlan#of}) as far as
 * the analysis reads it, its modules, releases, reactions and ranks, and is refused where the whole plan is, with the
 * same words, and it refuses to tell the connections it does not hold: on every example and fixture, mutated examples
 * and seeded random models.
 */
class ReleasesPlanTest {

    private static final long SEED = 20261128L;

    @TempDir
    Path dir;

    @Test
    void theReleasesPlanIsTheWholePlansReleasesOnExamplesMutantsAndRandomModels() throws Exception {
        List<byte[]> examples = new ArrayList<>();
        List<Path> files = CompiledInvariantsTest.models();
        int[] counts = new int[3]; // plans compared, refusals compared, releases compared
        for (Path file : files) {
            examples.add(Files.readAllBytes(file));
            compare(ModelLoader.load(file, file.getFileName().toString()), file.getFileName().toString(), counts);
        }
        Random random = new Random(SEED);
        for (int i = 0; i < 300; i++) {
            Path file = dir.resolve("mutant-" + i + ".rsaml");
            Files.write(file, MutatedFilesTest.mutate(examples.get(random.nextInt(examples.size())), random.nextInt(12), random));
            try {
                compare(ModelLoader.load(file, file.getFileName().toString()), "mutant " + i, counts);
            } catch (ModelLoadException e) {
                // not a model: nothing to plan
            }
        }
        for (int i = 0; i < 300; i++) {
            EObject root = new RandomModels(RsamlPackage.eINSTANCE, random, Values.EDGES, Shape.ANY).create(RsamlPackage.Literals.ARCHITECTURE);
            compare((Architecture) root, "random model " + i, counts);
        }
        assertTrue(counts[0] > 200 && counts[1] > 100 && counts[2] > 200,
                "plans, refusals and releases compared: " + counts[0] + ", " + counts[1] + ", " + counts[2]);
    }

    private static void compare(LoadedModel model, String where, int[] counts) {
        compare(model.architecture(), where, counts);
    }

    private static void compare(Architecture architecture, String where, int[] counts) {
        if (architecture == null) {
            return;
        }
        String whole;
        String releases;
        try {
            whole = describe(ExecutionPlan.of(architecture));
        } catch (UnplannableException e) {
            whole = "refused: " + e.getMessage();
        }
        try {
            ExecutionPlan plan = ExecutionPlan.releasesOf(architecture);
            releases = describe(plan);
            // what it does not hold it refuses to tell, rather than answer "no connections"
            assertThrows(IllegalStateException.class, plan::flows, where);
            assertThrows(IllegalStateException.class, plan::links, where);
            assertThrows(IllegalStateException.class, plan::reactiveCycles, where);
            for (PlannedModule m : plan.modules()) {
                assertThrows(IllegalStateException.class, m::inputs, where);
            }
        } catch (UnplannableException e) {
            releases = "refused: " + e.getMessage();
        }
        assertEquals(whole, releases, where);
        counts[whole.startsWith("refused: ") ? 1 : 0]++;
        counts[2] += whole.split("\n release ").length - 1;
    }

    /** What the timing analysis reads of a plan: its modules, each one's releases and reaction. */
    private static String describe(ExecutionPlan plan) {
        StringBuilder b = new StringBuilder();
        for (PlannedModule m : plan.modules()) {
            b.append(m.qualifiedName()).append(" periodic ").append(m.periodic()).append(" reactive ").append(m.reactive())
                    .append(" interval ").append(m.minIntervalNs()).append(" core ").append(m.core()).append(" processor ")
                    .append(m.processor() == null ? "none" : m.processor().getName()).append('\n');
            for (Release r : m.releases()) {
                b.append(" release ").append(r.label()).append(' ').append(r.kind()).append(" period ").append(r.periodNs())
                        .append(" offset ").append(r.offsetNs()).append(" deadline ").append(r.deadlineNs()).append(" cost ")
                        .append(r.costNs()).append(" rank ").append(r.rank()).append(' ').append(r.policy()).append(" edf ")
                        .append(r.edf()).append('\n');
            }
            Reaction reaction = m.reaction();
            if (reaction != null) {
                String cost;
                try {
                    cost = Long.toString(reaction.costNs());
                } catch (ArithmeticException e) {
                    cost = "too large";
                }
                b.append(" reaction ").append(reaction.label()).append(" deadline ").append(reaction.deadlineNs()).append(" cost ")
                        .append(cost).append(" functions ").append(reaction.functions().size()).append('\n');
            }
        }
        return b.toString();
    }
}
