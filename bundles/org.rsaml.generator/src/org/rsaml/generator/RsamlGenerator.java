/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.generator.internal.OutputWriter;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.UnplannableException;
import org.rsaml.generator.spi.GeneratedProject;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Severity;

/**
 * Generates the code skeleton of an RsaML architecture: the entry point of the command line and
 * the Maven plugin. Headless; works in a plain JVM and in OSGi.
 *
 * <pre>{@code
 * GenerationResult r = new RsamlGenerator().generate(Path.of("examples/exp3-task-interpreter.rsaml"),
 *         Target.CPP, Path.of("out/exp3"), false);
 * r.written().forEach(System.out::println);
 * }</pre>
 *
 * <p><b>Validation first.</b> The model is loaded with {@link ModelLoader} and validated with
 * {@link RsamlModelValidator}; a model with error findings is refused with a
 * {@link GenerationRefusedException} that carries the findings, unless {@code force} is set.
 *
 * <p><b>Generation gap.</b> Files under {@code gen/} (and the build files) are regenerated on every
 * run; the module classes under {@code src/} belong to the architect: created once, never
 * overwritten. When the model changes (a port is added, a function renamed), the architect's code
 * survives and still builds; {@link GenerationResult#warnings()} names methods of theirs that the
 * model no longer calls and new methods they may implement.
 *
 * <p><b>Deterministic and atomic.</b> The same model gives byte-identical files (stable order, no
 * timestamps, no absolute paths). Files whose content is unchanged are not touched. The files are
 * written into a temporary directory beside the output and moved into place; on any failure the
 * output directory is left as it was, and a {@link GenerationException} names the file concerned.
 *
 * <p><b>Names.</b> File names and identifiers come from model names made safe: no path separators
 * or traversal, no C++ or Python reserved words, and names that collide after sanitising get
 * {@code _2}, {@code _3}, ... in model order.
 */
public final class RsamlGenerator {

    /**
     * Loads, validates and generates.
     *
     * @param model     the {@code .rsaml} file
     * @param target    what to generate
     * @param outputDir the project directory to create or update
     * @param force     generate even when the model has error findings
     * @throws GenerationRefusedException the model has errors and {@code force} is not set
     * @throws GenerationException        the model cannot be read, or the output cannot be written
     */
    public GenerationResult generate(Path model, Target target, Path outputDir, boolean force) throws GenerationException {
        return generate(model, model.toString(), target, outputDir, force);
    }

    /** As {@link #generate(Path, Target, Path, boolean)}, naming the model {@code displayName} in messages. */
    public GenerationResult generate(Path model, String displayName, Target target, Path outputDir, boolean force)
            throws GenerationException {
        LoadedModel loaded;
        try {
            loaded = ModelLoader.load(model, displayName);
        } catch (ModelLoadException e) {
            throw new GenerationException(e.file(), e.line(), e.column(), e.getMessage(), e);
        }
        return generate(loaded, target, outputDir, force);
    }

    /** Validates an already loaded model and generates from it. */
    public GenerationResult generate(LoadedModel model, Target target, Path outputDir, boolean force) throws GenerationException {
        List<Finding> findings = RsamlModelValidator.validate(model);
        if (!force && findings.stream().anyMatch(f -> f.severity() == Severity.ERROR)) {
            throw new GenerationRefusedException(model.file(), findings);
        }
        return write(model, findings, target, outputDir);
    }

    private GenerationResult write(LoadedModel model, List<Finding> findings, Target target, Path outputDir) throws GenerationException {
        if (target == null || outputDir == null) {
            throw new GenerationException(model.file(), "no " + (target == null ? "target" : "output directory") + " given");
        }
        ExecutionPlan plan;
        try {
            plan = ExecutionPlan.of(model.architecture());
        } catch (UnplannableException e) {
            int[] at = e.element() == null ? new int[] { 0, 0 } : model.locate(e.element());
            throw new GenerationException(model.file(), at[0], at[1], "no code generated: " + e.getMessage(), e);
        }
        GeneratedProject project = target.generator().generate(plan, OutputWriter.context(outputDir, target.id()));
        List<String> warnings = new ArrayList<>(plan.warnings());
        warnings.addAll(project.warnings());
        OutputWriter.Outcome outcome = OutputWriter.write(outputDir, project.files(), target.id(), project.keep());
        warnings.addAll(outcome.warnings());
        Path dir = outputDir.toAbsolutePath().normalize();
        return new GenerationResult(target, dir, paths(outcome.written()), paths(outcome.unchanged()), paths(outcome.preserved()),
                paths(outcome.deleted()), findings, warnings);
    }

    private static List<Path> paths(List<String> relative) {
        return relative.stream().map(Path::of).toList();
    }
}
