/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

import org.eclipse.emf.common.util.TreeIterator;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.diagram.internal.ArchitectureLayout;
import org.rsaml.diagram.internal.DeepStack;
import org.rsaml.diagram.internal.Drawing;
import org.rsaml.diagram.internal.HtmlWriter;
import org.rsaml.diagram.internal.MissionLayout;
import org.rsaml.diagram.internal.SvgWriter;
import org.rsaml.diagram.internal.TimingOverlay;
import org.rsaml.model.Architecture;
import org.rsaml.model.support.AtomicFiles;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/**
 * Draws RsaML models headless: the architecture or mission view laid out by ELK, as SVG or as one
 * self-contained HTML page with the findings of validation. The same model always gives the same
 * bytes.
 *
 * <pre>
 * Path written = new RsamlDiagrams(DiagramView.ARCHITECTURE)
 *         .write(Path.of("robot.rsaml"), "robot.rsaml", DiagramFormat.HTML, Path.of("target/diagrams"));
 * </pre>
 */
public final class RsamlDiagrams {

    private final DiagramView view;
    private final List<DiagramOverlay> overlays = new ArrayList<>();
    private TimingMode timing = TimingMode.AUTO;

    public RsamlDiagrams(DiagramView view) {
        this.view = view;
    }

    /**
     * Whether the architecture view shows the timing analysis (processors' utilisation, tasks'
     * response times, latency requirements' worst paths); {@link TimingMode#AUTO} by default.
     */
    public RsamlDiagrams timing(TimingMode mode) {
        this.timing = mode;
        return this;
    }

    /** Adds an overlay (e.g. timing analysis results) drawn over the diagram. */
    public RsamlDiagrams overlay(DiagramOverlay overlay) {
        overlays.add(overlay);
        return this;
    }

    /**
     * The SVG document of an architecture, its elements decorated with the findings.
     *
     * @throws StackOverflowError when even the stack {@link DeepStack} sized for the model is too small
     */
    public String svg(Architecture architecture, List<Finding> findings) {
        return text(architecture, elements(architecture), null, findings, DiagramFormat.SVG);
    }

    /**
     * The HTML page of a model read from {@code file} (the name shown on the page), with its findings.
     *
     * @throws StackOverflowError when even the stack {@link DeepStack} sized for the model is too small
     */
    public String html(Architecture architecture, String file, List<Finding> findings) {
        return text(architecture, elements(architecture), file, findings, DiagramFormat.HTML);
    }

    /**
     * The diagram's text, laid out and written on a thread whose stack grows with the model (ELK's layout recurses
     * along chains of modules), so that a long chain does not overflow the caller's stack.
     */
    private String text(Architecture architecture, long elements, String file, List<Finding> findings, DiagramFormat format) {
        return DeepStack.call("rsaml-diagram", DeepStack.bytesFor(elements),
                () -> format == DiagramFormat.HTML ? HtmlWriter.write(draw(architecture, findings), file, findings)
                        : SvgWriter.write(draw(architecture, findings), true));
    }

    private static long elements(Architecture architecture) {
        long count = 0;
        for (TreeIterator<EObject> all = architecture.eAllContents(); all.hasNext(); all.next()) {
            count++;
        }
        return count;
    }

    private Drawing draw(Architecture architecture, List<Finding> findings) {
        DiagramOverlay.Notes notes = notes(architecture);
        return view == DiagramView.MISSION ? MissionLayout.draw(architecture, findings, notes)
                : ArchitectureLayout.draw(architecture, findings, notes);
    }

    private DiagramOverlay.Notes notes(Architecture architecture) {
        List<DiagramOverlay> all = new ArrayList<>();
        if (view == DiagramView.ARCHITECTURE && timing.appliesTo(architecture)) {
            all.add(new TimingOverlay());
        }
        all.addAll(overlays);
        if (all.isEmpty()) {
            return DiagramOverlay.Notes.NONE;
        }
        Map<String, List<DiagramOverlay.Line>> lines = new LinkedHashMap<>();
        Map<String, Set<String>> classes = new LinkedHashMap<>();
        Map<String, Map<String, String>> data = new LinkedHashMap<>();
        List<DiagramOverlay.Item> items = new ArrayList<>();
        for (DiagramOverlay overlay : all) {
            DiagramOverlay.Notes notes = overlay.notes(architecture);
            notes.lines().forEach((k, v) -> lines.computeIfAbsent(k, x -> new ArrayList<>()).addAll(v));
            notes.classes().forEach((k, v) -> classes.computeIfAbsent(k, x -> new TreeSet<>()).addAll(v));
            notes.data().forEach((k, v) -> data.computeIfAbsent(k, x -> new TreeMap<>()).putAll(v));
            items.addAll(notes.items());
        }
        return new DiagramOverlay.Notes(lines, classes, data, items);
    }

    /** The file a model's diagram is written to: {@code exp1-hybrid-architecture.svg} for {@code exp1-hybrid.rsaml}. */
    public String fileName(Path model, DiagramFormat format) {
        String name = model.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return (dot > 0 ? name.substring(0, dot) : name) + "-" + view.id() + "." + format.id();
    }

    /**
     * Reads and validates a model and writes its diagram into {@code directory} (created if needed)
     * under {@link #fileName}; the file is written whole or not at all.
     *
     * @param displayName the model as the user named it, shown in the page and in messages
     * @return the file written
     * @throws ModelLoadException when the model cannot be read
     * @throws DiagramException   when the diagram cannot be laid out (a model too deep even for the stack
     *                            {@link DeepStack} sized for it) or written
     */
    public Path write(Path model, String displayName, DiagramFormat format, Path directory) throws ModelLoadException, DiagramException {
        LoadedModel loaded = ModelLoader.load(model, displayName);
        List<Finding> findings = RsamlModelValidator.validate(loaded);
        String text;
        long elements = elements(loaded.architecture());
        try {
            text = text(loaded.architecture(), elements, displayName, findings, format);
        } catch (StackOverflowError e) {
            long mib = DeepStack.bytesFor(elements) >> 20;
            throw new DiagramException("too deep to lay out: the layout of its " + elements + " elements recursed past the "
                    + mib + " MiB stack it was given (long chains of connected modules recurse deepest); draw it with a larger"
                    + " stack, e.g. RSAML_JAVA_OPTS=-D" + DeepStack.PROPERTY + "=" + Math.max(4 * mib, 64)
                    + " (for the Maven goal, in MAVEN_OPTS), or split the chain", e);
        }
        Path target = directory.resolve(fileName(model, format));
        write(target, text);
        return target;
    }

    /** Writes {@code text} to {@code target} whole or not at all ({@link AtomicFiles}). */
    public static void write(Path target, String text) throws DiagramException {
        try {
            AtomicFiles.writeString(target, text);
        } catch (IOException e) {
            throw new DiagramException(target + ": cannot write the diagram: " + AtomicFiles.reason(e, target), e);
        }
    }
}
