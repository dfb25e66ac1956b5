/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.ide.server.hover.HoverService;
import org.eclipse.xtext.naming.QualifiedName;
import org.rsaml.analysis.ArchitectureTiming;
import org.rsaml.analysis.ProcessorTiming;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.TaskSource;
import org.rsaml.model.NamedElement;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.resource.LocatingResource;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlTimes;
import org.rsaml.text.naming.RsamlTextQualifiedNameProvider;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.RsamlModelValidator;

/**
 * What hovering over an element shows: its kind and full name, its description, and for an element
 * that executes its timing facts as the diagrams label them ({@link RsamlLabels#timingFacts}: period T, deadline D,
 * wcet C, each with its unit), and, where the timing analysis
 * (as {@code rsaml analyze} runs it) covers it, its worst-case response time and slack.
 */
public class RsamlTextHoverService extends HoverService {

    @Override
    public String getContents(EObject element) {
        if (!(element instanceof NamedElement named)) {
            return null;
        }
        List<String> parts = new ArrayList<>();
        QualifiedName name = RsamlTextQualifiedNameProvider.qualifiedName(element);
        parts.add("**" + element.eClass().getName() + "** `" + (name == null ? String.valueOf(named.getName()) : name.toString()) + "`");
        if (named.getDescription() != null) {
            parts.add(named.getDescription());
        }
        if (element instanceof RealTimeElement e) {
            parts.add(RsamlLabels.timingFacts(e));
            parts.add(analysed(element));
        }
        return String.join("\n\n", parts);
    }

    /** The element's response time and slack from the timing analysis, or why there are none. */
    private static String analysed(EObject element) {
        if (!(element.eResource() instanceof LocatingResource resource) || !resource.getErrors().isEmpty()) {
            return "Timing: not analysed while the file has errors.";
        }
        Path path = resource.getURI().isFile() ? Path.of(resource.getURI().toFileString()) : null;
        ArchitectureTiming timing;
        try {
            timing = RsamlModelValidator.analyseTiming(LoadedModel.of(resource, String.valueOf(resource.getURI().lastSegment()), path));
        } catch (ModelLoadException e) {
            return "Timing: not analysed: " + e.getMessage();
        } catch (RuntimeException e) {
            return "Timing: not analysed (" + e.getClass().getSimpleName() + ").";
        }
        for (ProcessorTiming processor : timing.processors()) {
            for (TaskSource source : processor.sources()) {
                if (source.element() != element) {
                    continue;
                }
                for (TaskResult result : processor.result().tasks()) {
                    if (result.task().equals(source.task())) {
                        if (result.responseTime().isEmpty()) {
                            return "Timing on " + processor.name() + ": " + result.explanation();
                        }
                        return "Timing on " + processor.name() + ": worst-case response time "
                                + RsamlTimes.milliseconds(result.responseTime().getAsLong()) + ", slack " + RsamlTimes.milliseconds(result.slack().getAsLong())
                                + " (" + result.verdict().toString().toLowerCase(java.util.Locale.ROOT).replace('_', ' ') + ")";
                    }
                }
            }
        }
        return "Timing: no task of the analysis is released for this element.";
    }
}
