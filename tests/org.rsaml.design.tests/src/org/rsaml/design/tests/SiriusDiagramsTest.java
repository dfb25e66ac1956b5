/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.ILogListener;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.jobs.IJobChangeEvent;
import org.eclipse.core.runtime.jobs.IJobChangeListener;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.core.runtime.jobs.JobChangeAdapter;
import org.eclipse.draw2d.IFigure;
import org.eclipse.draw2d.Label;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.gmf.runtime.diagram.ui.editparts.IGraphicalEditPart;
import org.eclipse.gmf.runtime.diagram.ui.parts.IDiagramWorkbenchPart;
import org.eclipse.sirius.business.api.session.Session;
import org.eclipse.sirius.common.tools.api.resource.ImageFileFormat;
import org.eclipse.sirius.diagram.DDiagram;
import org.eclipse.sirius.diagram.DDiagramElement;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDDiagramEditPart;
import org.eclipse.sirius.diagram.ui.edit.api.part.IDiagramElementEditPart;
import org.eclipse.sirius.diagram.ui.part.ValidateAction;
import org.eclipse.sirius.diagram.ui.tools.api.decoration.AbstractSiriusDecorationDescriptorProvider;
import org.eclipse.sirius.diagram.ui.tools.api.decoration.DecorationDescriptor;
import org.eclipse.sirius.diagram.ui.tools.api.decoration.SiriusDecorationDescriptorProvider;
import org.eclipse.sirius.diagram.ui.tools.api.decoration.SiriusDecorationProviderRegistry;
import org.eclipse.sirius.ui.business.api.dialect.DialectUIManager;
import org.eclipse.sirius.ui.business.api.dialect.ExportFormat;
import org.eclipse.sirius.ui.business.api.dialect.ExportFormat.ExportDocumentFormat;
import org.eclipse.sirius.viewpoint.DSemanticDecorator;
import org.eclipse.sirius.viewpoint.Decoration;
import org.eclipse.sirius.viewpoint.description.DecorationDescription;
import org.eclipse.ui.IEditorPart;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.design.services.RsamlServices;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The RsaML diagrams as an architect meets them in Eclipse: a modeling project holding the examples, the
 * RsaML viewpoint enabled, an architecture and a mission diagram of each example created with Sirius,
 * opened in Sirius's editor (which lays them out), decorated with exactly the findings the model states
 * in its {@code <!-- expect: -->} comments, marked by Sirius's <i>Validate</i> with exactly {@code rsaml validate}'s
 * findings without a second decoration for them (what is drawn on each element stays its findings, once each), readable (no label over another label or a node, checked on the laid-out figures' geometry:
 * {@link DiagramGeometry}), and exported as images under {@code target/diagrams}. The examples drawn are
 * {@code rsaml.diagrams.examples} ({@code all}, the default, draws every one; a comma-separated list draws those).
 */
class SiriusDiagramsTest {

    /** The type of the markers Sirius's Validate puts on the session's representations file. */
    private static final String SIRIUS_MARKER = "org.eclipse.sirius.diagram.ui.diagnostic";

    /** The README's picture of an architecture diagram, which this test exports again. */
    private static final String README_IMAGE = "docs/images/exp1-hybrid-sirius-architecture.png";

    private static SiriusProject project;

    static Stream<String> examples() throws Exception {
        String chosen = System.getProperty("rsaml.diagrams.examples", "all");
        if (chosen.equals("all")) {
            try (Stream<Path> files = Files.list(TestRepository.root().resolve("examples"))) {
                return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted().toList().stream();
            }
        }
        return Arrays.stream(chosen.split(",")).map(String::trim).filter(s -> !s.isEmpty());
    }

    private static Path output() throws Exception {
        Path dir = Path.of(System.getProperty("rsaml.diagrams.output", "target/diagrams"));
        Files.createDirectories(dir);
        return dir;
    }

    /** What the workbench does (jobs that ran, problems logged); a failed check tells what it did while its example was drawn. */
    private static final List<String> HAPPENINGS = java.util.Collections.synchronizedList(new ArrayList<>());

    private static final ILogListener LOGGED = (status, plugin) -> {
        if (status.getSeverity() >= IStatus.WARNING) {
            HAPPENINGS.add("logged by " + status.getPlugin() + ": " + status.getMessage()
                    + (status.getException() == null ? "" : " (" + status.getException() + ")"));
        }
    };

    private static final IJobChangeListener JOBS = new JobChangeAdapter() {
        @Override
        public void done(IJobChangeEvent event) {
            if (!event.getJob().isSystem()) {
                HAPPENINGS.add("job done: " + event.getJob().getName());
            }
        }
    };

    @BeforeAll
    static void modelingProjectWithTheRsamlViewpoint() throws Exception {
        Platform.addLogListener(LOGGED);
        Job.getJobManager().addJobChangeListener(JOBS);
        project = SiriusProject.create("rsaml-diagrams", examples().toList());
        HAPPENINGS.add("the modeling project is set up");
    }

    @AfterAll
    static void closeTheProject() throws Exception {
        Platform.removeLogListener(LOGGED);
        Job.getJobManager().removeJobChangeListener(JOBS);
        if (project != null) {
            project.delete();
        }
    }

    /** "error hybrid/control/resourceChecker: RSA-08: ..." for each finding a decoration shows, once per element drawn. */
    private static List<String> decorations(DDiagram diagram) {
        List<String> shown = new ArrayList<>();
        for (DDiagramElement element : diagram.getDiagramElements()) {
            List<Decoration> all = new ArrayList<>(element.getDecorations());
            all.addAll(element.getTransientDecorations());
            for (Decoration decoration : all) {
                DecorationDescription description = (DecorationDescription) decoration.getDescription();
                String severity = description.getName().endsWith("Errors") ? "error" : "warning";
                String tooltip = project.evaluate(element.getTarget(), description.getTooltipExpression());
                for (String line : tooltip.split("\n")) {
                    shown.add(severity + " " + RsamlLabels.qualifiedName(element.getTarget()) + ": " + line);
                }
            }
        }
        return shown;
    }

    /**
     * "hybrid/control/resourceChecker: RSA-08: ..." for each line of every decoration Sirius draws on the open diagram's
     * elements, whoever provides it (RsaML's viewpoint, the decoration of Validate's markers, ...), as Sirius's decorator
     * computes them for each edit part it decorates.
     */
    private static List<String> decorationsDrawn(IDiagramWorkbenchPart part) {
        Decorable decorable = new Decorable();
        List<String> shown = new ArrayList<>();
        for (Object o : new LinkedHashSet<>(part.getDiagramGraphicalViewer().getEditPartRegistry().values())) {
            if (!(o instanceof IDiagramElementEditPart editPart) || !decorable.decorates(editPart)) {
                continue;
            }
            DDiagramElement element = editPart.resolveDiagramElement();
            String on = RsamlLabels.qualifiedName(element.getTarget());
            for (SiriusDecorationDescriptorProvider provider : List.copyOf(SiriusDecorationProviderRegistry.INSTANCE.getDecorationDescriptorProviders())) {
                if (provider.provides(editPart)) {
                    for (DecorationDescriptor descriptor : provider.getDecorationDescriptors(editPart, project.session)) {
                        for (String line : lines(element, descriptor)) {
                            shown.add(on + ": " + line);
                        }
                    }
                }
            }
        }
        shown.sort(null);
        return shown;
    }

    /** The lines of a decoration's tooltip: the viewpoint's tooltip expression on the element's target, or the figure's labels. */
    private static List<String> lines(DDiagramElement element, DecorationDescriptor descriptor) {
        List<Decoration> all = new ArrayList<>(element.getDecorations());
        all.addAll(element.getTransientDecorations());
        for (Decoration decoration : all) {
            DecorationDescription description = (DecorationDescription) decoration.getDescription();
            if (description.getName().equals(descriptor.getName())) {
                return List.of(project.evaluate(element.getTarget(), description.getTooltipExpression()).split("\n"));
            }
        }
        List<String> lines = new ArrayList<>();
        if (descriptor.getTooltipAsFigure() != null) {
            labels(descriptor.getTooltipAsFigure(), lines);
        } else if (descriptor.getTooltipAsString() != null) {
            lines.addAll(List.of(descriptor.getTooltipAsString().split("\n")));
        }
        return lines.isEmpty() ? List.of("(decoration " + descriptor.getName() + ")") : lines;
    }

    private static void labels(IFigure figure, List<String> lines) {
        if (figure instanceof Label label && !label.getText().isEmpty()) {
            lines.add(label.getText());
        }
        for (Object child : figure.getChildren()) {
            labels((IFigure) child, lines);
        }
    }

    /** Which edit parts Sirius's decorator decorates: not labels, not a compartment showing its parent's element again. */
    private static final class Decorable extends AbstractSiriusDecorationDescriptorProvider {
        boolean decorates(IDiagramElementEditPart editPart) {
            if (!shouldBeDecorated(editPart) || editPart.resolveDiagramElement() == null) {
                return false;
            }
            return editPart.getParent() instanceof IDDiagramEditPart || !(editPart.getParent() instanceof IGraphicalEditPart parent)
                    || !(parent.resolveSemanticElement() instanceof DSemanticDecorator parentElement)
                    || parentElement.getTarget() != editPart.resolveDiagramElement().getTarget();
        }

        @Override
        protected List<DecorationDescriptor> createDecorationDescriptors(IDiagramElementEditPart diagramEditPart, Session session) {
            return List.of();
        }
    }

    /**
     * The qualified name of the element whose decoration shows findings on {@code qualifiedName}: the element
     * itself, or the nearest drawn element containing it (a function shows its actions' findings).
     */
    private static String shownOn(Architecture architecture, String qualifiedName) {
        List<EObject> all = new ArrayList<>(List.of(architecture));
        architecture.eAllContents().forEachRemaining(all::add);
        return all.stream().filter(e -> RsamlLabels.qualifiedName(e).equals(qualifiedName)).findFirst()
                .map(e -> RsamlLabels.qualifiedName(RsamlServices.shownOn(e))).orElse(qualifiedName);
    }

    private static String line(Architecture architecture, ExpectedFinding f) {
        return f.severity() + " " + shownOn(architecture, f.qualifiedName()) + ": " + (f.message() == null ? f.ruleId() : f.ruleId() + ": " + f.message());
    }

    private static String line(Architecture architecture, Finding f) {
        return f.severity().name().toLowerCase() + " " + shownOn(architecture, f.qualifiedName()) + ": " + f.ruleId() + ": " + f.message();
    }

    /** Only the rule id when the model states no wording for the finding. */
    private static Set<String> comparable(Architecture architecture, List<String> shown, List<ExpectedFinding> stated) {
        Set<String> result = new TreeSet<>();
        for (String s : shown) {
            String shortened = s;
            for (ExpectedFinding f : stated) {
                String prefix = f.severity() + " " + shownOn(architecture, f.qualifiedName()) + ": " + f.ruleId();
                if (f.message() == null && s.startsWith(prefix + ":")) {
                    shortened = prefix;
                }
            }
            result.add(shortened);
        }
        return result;
    }

    /**
     * What drawing an example's two diagrams showed: the decorations of both and the geometry of each, and what the
     * workbench did meanwhile (from "drawing EXAMPLE" on; not what it did for the examples drawn before).
     */
    private record Drawn(List<String> decorations, List<DiagramGeometry> geometries, List<String> happenings) {
    }

    private static final Map<String, Drawn> DRAWN = new HashMap<>();

    /** Draws the architecture and mission diagrams of {@code example} once, exports them, and keeps what they showed. */
    private static Drawn drawn(String example) throws Exception {
        Drawn done = DRAWN.get(example);
        if (done != null) {
            return done;
        }
        Architecture architecture = project.architecture(example);
        String base = example.replace(".rsaml", "");
        int from = HAPPENINGS.size();
        HAPPENINGS.add("drawing " + example);
        List<String> shown = new ArrayList<>();
        List<DiagramGeometry> geometries = new ArrayList<>();
        for (String kind : List.of("Architecture", "Missions")) {
            DDiagram diagram = project.create(kind, architecture, base + " " + kind);
            IEditorPart editor = DialectUIManager.INSTANCE.openEditor(project.session, diagram, SiriusProject.MONITOR);
            assertNotNull(editor, "Sirius opens the " + kind + " diagram of " + example);
            SiriusProject.awaitRepresentationsFileJobs();
            try {
                List<String> onDiagram = decorations(diagram);
                assertEquals(new LinkedHashSet<>(onDiagram).size(), onDiagram.size(), "each finding decorates its element once: " + onDiagram);
                shown.addAll(onDiagram);
                if (kind.equals("Architecture")) {
                    IDiagramWorkbenchPart part = (IDiagramWorkbenchPart) editor;
                    List<String> once = onDiagram.stream().map(s -> s.substring(s.indexOf(' ') + 1)).sorted().toList();
                    assertEquals(once, decorationsDrawn(part), "the decorations drawn on the elements of " + example + "'s architecture diagram are its findings, once each");
                    validateMarksWhatRsamlValidateFinds(architecture, part);
                    assertEquals(once, decorationsDrawn(part), "after Diagram > Validate the decorations drawn on each element of " + example
                            + "'s architecture diagram are still its findings, once each (Validate's markers add no second decoration)");
                }
                geometries.add(DiagramGeometry.of(base + " " + kind, editor));
                Path image = output().resolve(base + "-" + kind.toLowerCase() + ".png");
                DialectUIManager.INSTANCE.export(diagram, project.session, new org.eclipse.core.runtime.Path(image.toString()),
                        new ExportFormat(ExportDocumentFormat.NONE, ImageFileFormat.PNG), SiriusProject.MONITOR);
                assertTrue(Files.size(image) > 0, "the " + kind + " diagram of " + example + " is exported to " + image);
            } finally {
                DialectUIManager.INSTANCE.closeEditor(editor, false);
                SiriusProject.flushEvents();
                project.delete(diagram);
            }
        }
        List<String> happenings;
        synchronized (HAPPENINGS) {
            happenings = List.copyOf(HAPPENINGS.subList(from, HAPPENINGS.size()));
        }
        done = new Drawn(shown, geometries, happenings);
        DRAWN.put(example, done);
        return done;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("examples")
    void architectureAndMissionDiagramsAreDecoratedWithTheModelsFindingsAndExported(String example) throws Exception {
        Architecture architecture = project.architecture(example);
        List<ExpectedFinding> stated = ExpectedFinding.of(TestRepository.example(example)).stream()
                .filter(f -> !f.severity().equals("info")).toList();
        List<String> shown = drawn(example).decorations();
        assertEquals(comparable(architecture, stated.stream().map(f -> line(architecture, f)).toList(), stated), comparable(architecture, shown, stated),
                "the decorations of " + example + "'s diagrams are the findings its expect comments state, each once");
    }

    /**
     * The diagrams read well as laid out: no text is drawn over another (a port's name over its module's title or
     * over another port's name), no text is cut short, no text and a node other than its own element or one that
     * contains it lie over each other (an edge's label on a module, a port's name on another module, a module on its
     * layer's title). Checked on the geometry of the figures the image is exported from.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("examples")
    void noLabelIsDrawnOverAnotherLabelOrANode(String example) throws Exception {
        List<String> overlaps = new ArrayList<>();
        for (DiagramGeometry geometry : drawn(example).geometries()) {
            // An architecture diagram draws its layers and modules; a diagram with nodes has texts (an architecture
            // without missions draws an empty mission diagram). Nothing read is nothing checked.
            assertTrue(!geometry.diagram.endsWith(" Architecture") || !geometry.nodes.isEmpty(), "the nodes of the diagram " + geometry.diagram + " are found");
            assertTrue(geometry.nodes.isEmpty() || !geometry.labels.isEmpty(), "the labels of the diagram " + geometry.diagram + " are found");
            geometry.overlaps().forEach(o -> overlaps.add("in " + geometry.diagram + ": " + o));
        }
        assertEquals("", String.join("\n", overlaps), overlaps.size() + " overlaps make the diagrams of " + example
                + " hard to read; the workbench meanwhile: " + drawn(example).happenings());
    }

    /**
     * Decorations follow the model without a manual validation: a change that breaks a rule decorates the
     * elements concerned as soon as the change is made, and the change that repairs it removes the decorations.
     */
    @Test
    void decorationsFollowModelChangesInAnOpenDiagram() throws Exception {
        String example = examples().toList().get(0);
        Architecture architecture = project.architecture(example);
        DDiagram diagram = project.create("Architecture", architecture, "changes " + example);
        IEditorPart editor = DialectUIManager.INSTANCE.openEditor(project.session, diagram, SiriusProject.MONITOR);
        try {
            Set<String> before = new TreeSet<>(decorations(diagram));
            Layer layer = architecture.getLayers().stream().filter(l -> !l.getModules().isEmpty()).findFirst().orElseThrow();
            double budget = layer.getMaxExecTime();
            project.run("tighten " + layer.getName(), () -> layer.setMaxExecTime(0.001));
            try {
                Set<String> expected = new TreeSet<>();
                RsamlModelValidator.validate(architecture).stream().filter(f -> f.severity() != org.rsaml.validation.Severity.INFO)
                        .map(f -> line(architecture, f)).forEach(expected::add);
                Set<String> after = new TreeSet<>(decorations(diagram));
                assertEquals(expected, after, "after the change the diagram shows what rsaml validate finds now");
                for (Module module : layer.getModules()) {
                    assertTrue(after.stream().anyMatch(s -> s.startsWith("error " + RsamlLabels.qualifiedName(module) + ": ")),
                            module.getName() + " now takes longer than its layer allows, and says so");
                }
            } finally {
                project.run("restore " + layer.getName(), () -> layer.setMaxExecTime(budget));
            }
            assertEquals(before, new TreeSet<>(decorations(diagram)), "restoring the layer's budget removes the decorations");
        } finally {
            DialectUIManager.INSTANCE.closeEditor(editor, false);
            SiriusProject.flushEvents();
            project.delete(diagram);
        }
    }

    /**
     * One verdict: Sirius's own <i>Diagram &gt; Validate</i> on the open diagram marks exactly what {@code rsaml validate}
     * finds, each finding once, with its severity and the text of the builder's markers and the decorations ({@code RSA-08: ...}).
     */
    private static void validateMarksWhatRsamlValidateFinds(Architecture architecture, IDiagramWorkbenchPart part) throws Exception {
        List<String> expected = new ArrayList<>(RsamlModelValidator.validate(architecture).stream()
                .map(f -> f.severity().name().toLowerCase() + " " + f.text()).toList());
        expected.sort(null);
        // What Diagram > Validate runs on the open diagram.
        ValidateAction.runValidation(part.getDiagramEditPart(), part.getDiagram());
        SiriusProject.flushEvents();
        IFile aird = ResourcesPlugin.getWorkspace().getRoot()
                .getFile(new org.eclipse.core.runtime.Path(project.session.getSessionResource().getURI().toPlatformString(true)));
        List<String> marked = new ArrayList<>();
        for (IMarker marker : aird.findMarkers(SIRIUS_MARKER, true, IResource.DEPTH_ZERO)) {
            int severity = marker.getAttribute(IMarker.SEVERITY, -1);
            marked.add((severity == IMarker.SEVERITY_ERROR ? "error" : severity == IMarker.SEVERITY_WARNING ? "warning" : "info") + " "
                    + marker.getAttribute(IMarker.MESSAGE, ""));
        }
        marked.sort(null);
        assertEquals(expected, marked, "Validate's markers on " + aird.getName() + " for " + architecture.getName()
                + " are rsaml validate's findings, once each, in its words");
    }

    /** The README's picture of a Sirius architecture diagram is the one this test exports today. */
    @Test
    void theReadmesArchitectureDiagramImageIsCurrent() throws Exception {
        assertTrue(examples().anyMatch("exp1-hybrid.rsaml"::equals), "exp1-hybrid.rsaml is among the examples drawn");
        Path exported = output().resolve("exp1-hybrid-architecture.png");
        drawn("exp1-hybrid.rsaml");
        Path committed = TestRepository.root().resolve(README_IMAGE);
        String fix = README_IMAGE + " is out of date: copy " + exported + " over it";
        assertTrue(Files.exists(committed), fix);
        BufferedImage now = ImageIO.read(exported.toFile());
        BufferedImage then = ImageIO.read(committed.toFile());
        assertEquals(now.getWidth() + "x" + now.getHeight(), then.getWidth() + "x" + then.getHeight(), fix);
        long differing = differing(now, then);
        // Rendering on another run may differ in a few anti-aliased pixels; any change to what is drawn changes thousands.
        assertTrue(differing * 1000 <= (long) now.getWidth() * now.getHeight(), differing + " pixels differ: " + fix
                + " (the workbench meanwhile: " + drawn("exp1-hybrid.rsaml").happenings() + ")");
        assertTrue(Files.readString(TestRepository.root().resolve("README.md")).contains(README_IMAGE), "the README shows " + README_IMAGE);
    }

    private static long differing(BufferedImage a, BufferedImage b) {
        long count = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    count++;
                }
            }
        }
        return count;
    }
}
