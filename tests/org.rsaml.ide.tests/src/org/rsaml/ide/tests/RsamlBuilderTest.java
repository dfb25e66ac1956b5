/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.ide.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.resources.IWorkspaceDescription;
import org.eclipse.core.resources.IncrementalProjectBuilder;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IPath;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.emf.ecore.resource.impl.ResourceSetImpl;
import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInfo;
import org.rsaml.ide.RsamlMarkers;
import org.rsaml.ide.RsamlProjects;
import org.rsaml.model.Architecture;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlModelValidator;

/** What a user sees in the Problems view once a project has the RsaML nature, in a real workspace. */
class RsamlBuilderTest {

    private static final IWorkspace WORKSPACE = ResourcesPlugin.getWorkspace();

    /**
     * Experiment 2's five defects and its timing warning as (rule, line, severity), sorted by rule, from the expectations the
     * model states.
     */
    private static final List<String> EXPERIMENT_TWO = experimentTwo();
    /** The module of exp2's budget defect, which the test fixes. */
    private static final String BUDGET = "hybridMobileRobotWithDefects/control/resourceChecker";

    private IProject project;

    @BeforeAll
    static void buildOnlyWhenAsked() throws CoreException {
        IWorkspaceDescription description = WORKSPACE.getDescription();
        description.setAutoBuilding(false);
        WORKSPACE.setDescription(description);
    }

    @AfterAll
    static void saveWorkspace() throws CoreException {
        WORKSPACE.save(true, null);
    }

    @BeforeEach
    void createProject(TestInfo test) throws CoreException {
        project = WORKSPACE.getRoot().getProject(test.getTestMethod().orElseThrow().getName());
        project.create(null);
        project.open(null);
    }

    @AfterEach
    void deleteProject() throws CoreException {
        project.delete(true, true, null);
    }

    @Test
    void experimentTwoShowsItsFiveDefectsAndAFixedDefectDisappears() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile file = copy(TestRepository.example("exp2-defects.rsaml"), "models/exp2-defects.rsaml");
        IFile other = copy(TestRepository.example("exp2-defects.rsaml"), "other/exp2-copy.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);

        assertEquals(EXPERIMENT_TWO, summaries(file), "the markers are the findings the model's expect comments state");
        ExpectedFinding expected = ExpectedFinding.on(TestRepository.example("exp2-defects.rsaml"), BUDGET);
        IMarker budget = marker(file, expected.ruleId());
        assertEquals(expected.diagnosticMessage(), budget.getAttribute(IMarker.MESSAGE), "the marker's message is the finding's");
        assertEquals(expected.qualifiedName(), budget.getAttribute(RsamlMarkers.QUALIFIED_NAME), "the marker names its element");
        assertEquals(IMarker.SEVERITY_ERROR, budget.getAttribute(IMarker.SEVERITY, -1), "the budget's finding is an error");
        assertTrue(budget.isSubtypeOf(IMarker.PROBLEM) && budget.isSubtypeOf(IMarker.TEXT), "a problem marker with a line");

        // Each marker leads to its element, as an EMF editor would resolve it.
        LoadedModel model = ModelLoader.load(file.getLocation().toPath(), "exp2");
        for (IMarker marker : markers(file)) {
            String fragment = (String) marker.getAttribute(RsamlMarkers.URI_FRAGMENT);
            assertTrue(fragment != null && !fragment.isEmpty(), "no uriFragment on " + marker.getAttributes());
            assertEquals("platform:/resource/" + project.getName() + "/models/exp2-defects.rsaml#" + fragment,
                    marker.getAttribute(RsamlMarkers.URI), "the marker opens the model file in the workspace at its element");
            EObject element = model.resource().getEObject(fragment);
            assertEquals(marker.getAttribute(RsamlMarkers.QUALIFIED_NAME), RsamlLabels.qualifiedName(element), fragment);
        }

        // Fix defect 4: resourceChecker within its layer's 2.0 ms budget.
        List<Long> otherIds = ids(other);
        String text = Files.readString(file.getLocation().toPath());
        String fixed = Arrays.stream(text.split("\n", -1))
                .map(l -> l.contains("name=\"resourceChecker\"") ? l.replace("execDuration=\"2.5\"", "execDuration=\"1.8\"") : l)
                .collect(Collectors.joining("\n"));
        assertNotEquals(text, fixed, "the test found resourceChecker's execDuration to fix");
        file.setContents(new ByteArrayInputStream(fixed.getBytes(StandardCharsets.UTF_8)), IResource.FORCE, null);
        project.build(IncrementalProjectBuilder.INCREMENTAL_BUILD, null);

        String fixedSummary = expected.ruleId() + " line " + expected.line() + " " + expected.severity();
        assertEquals(EXPERIMENT_TWO.stream().filter(f -> !f.equals(fixedSummary)).toList(), summaries(file),
                "the fixed defect's marker is gone, the others stay");
        assertEquals(EXPERIMENT_TWO, summaries(other), "the other file's markers stay");
        assertEquals(otherIds, ids(other), "an unchanged file is not validated again");
    }

    @Test
    void aMalformedFileGetsOneErrorAtTheFaultyLineUntilItIsRepaired() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile file = copy(TestRepository.resource("org.rsaml.ide.tests", "models/malformed-unclosed-layer.rsaml"), "broken.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);

        assertEquals(List.of("RSA-00 line 7 error"), summaries(file), "one error marker at the line of the unclosed layer");
        String message = (String) markers(file).get(0).getAttribute(IMarker.MESSAGE);
        assertTrue(message.startsWith("RSA-00: malformed XML: ") && message.contains("layers"), message);

        file.setContents(Files.newInputStream(TestRepository.example("exp3-task-interpreter.rsaml")), IResource.FORCE, null);
        project.build(IncrementalProjectBuilder.INCREMENTAL_BUILD, null);
        assertEquals(List.of(), summaries(file), "the repaired file's marker is gone");
    }

    @Test
    void aFileWithSeveralMistakesGetsAnErrorForEach() throws Exception {
        RsamlProjects.addNature(project, null);
        Path model = TestRepository.root().resolve("tests/org.rsaml.cli.tests/resources/inputs/many-errors.rsaml");
        IFile file = copy(model, "many-errors.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);

        // One marker per line with a mistake (each line that declares a module), not one for the first alone.
        List<String> lines = Files.readAllLines(model);
        List<String> expected = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).contains("<modules name=\"m")) {
                expected.add("RSA-00 line " + (i + 1) + " error");
            }
        }
        assertEquals(12, expected.size(), "many-errors.rsaml declares twelve faulty modules");
        assertEquals(expected, summaries(file).stream().sorted(Comparator.comparingInt(s -> Integer.parseInt(s.split(" ")[2]))).toList(),
                "one error marker on each line that declares a faulty module");
    }

    /**
     * The tree editor's Validate replaces the file's markers of its type (the builder's) with one per
     * finding, written by {@link RsamlMarkers#create}: after a build and a Validate, and after a
     * Validate and a build, the Problems view lists each finding once, with the same text.
     */
    @Test
    void theEditorsValidateAndTheBuilderListEachFindingOnce() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile file = copy(TestRepository.example("exp2-defects.rsaml"), "exp2.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        List<String> built = described(file);
        assertEquals(EXPERIMENT_TWO.size(), built.size(), () -> "one marker per finding the model states: " + built);

        // What EMF's marker helper does for the editor's Validate, with the editor's marker type.
        LoadedModel model = ModelLoader.load(file.getLocation().toPath(), "exp2");
        file.deleteMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO);
        for (Diagnostic finding : RsamlModelValidator.diagnose(model.architecture()).getChildren()) {
            RsamlMarkers.create(file, finding);
        }
        assertEquals(built, described(file), "Validate must mark what the builder marks, on the same lines");

        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(built, described(file), "a build after Validate marks what Validate marked");
        assertEquals(EXPERIMENT_TWO.size(), markers(project).size(), "each finding is listed once in the Problems view");
    }

    /**
     * After an edit saved through EMF (a module inserted above the findings, as the tree editor saves),
     * Validate's markers have the lines of the saved file, the lines the builder then gives.
     */
    @Test
    void afterASaveValidateAndTheBuilderGiveTheSameLines() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile file = copy(TestRepository.example("exp2-defects.rsaml"), "exp2.rsaml");
        ResourceSet set = new ResourceSetImpl();
        RsamlResource resource = (RsamlResource) set.getResource(
                URI.createPlatformResourceURI(file.getFullPath().toString(), true), true);
        Architecture architecture = (Architecture) resource.getContents().get(0);
        Module inserted = RsamlFactory.eINSTANCE.createModule();
        inserted.setName("inserted");
        architecture.getLayers().get(0).getModules().add(0, inserted);
        resource.save(null);
        resource.refreshLocations();

        file.deleteMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO);
        for (Diagnostic finding : RsamlModelValidator.diagnose(architecture).getChildren()) {
            RsamlMarkers.create(file, finding);
        }
        List<String> validated = described(file);
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(validated, described(file), "Validate after a save must mark the lines the builder marks");
        List<Integer> lines = markers(file).stream().map(m -> m.getAttribute(IMarker.LINE_NUMBER, -1)).toList();
        List<Integer> before = ExpectedFinding.of(TestRepository.example("exp2-defects.rsaml")).stream()
                .sorted(Comparator.comparing(ExpectedFinding::ruleId)).map(ExpectedFinding::line).toList();
        assertNotEquals(before, lines, "the inserted module moved the findings' lines");
    }

    /**
     * Creating a model in a project or opening one there (the tree editor calls this) turns RsaML
     * validation on; a project where the user turned it off stays off until turned on again.
     */
    @Test
    void creatingOrOpeningAModelTurnsValidationOnUnlessTurnedOff() throws Exception {
        IFile text = copy(TestRepository.example("exp2-defects.rsaml"), "notes.txt");
        assertFalse(RsamlProjects.enableFor(text, null), "a file that is not a model changes nothing");
        assertFalse(RsamlProjects.hasNature(project), "a text file does not turn validation on");

        IFile model = copy(TestRepository.example("exp2-defects.rsaml"), "exp2.rsaml");
        assertTrue(RsamlProjects.enableFor(model, null), "the first model turns validation on");
        assertTrue(RsamlProjects.hasNature(project), "the project has RsaML validation on");
        assertEquals(List.of(RsamlProjects.BUILDER_ID), builders(), "the project builds with RsaML's builder alone");
        assertFalse(RsamlProjects.enableFor(model, null), "a second time changes nothing");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(EXPERIMENT_TWO, summaries(model), "the build marks the findings the model states");

        RsamlProjects.removeNature(project, null);
        assertTrue(RsamlProjects.isOptedOut(project), "turning validation off is remembered");
        assertFalse(RsamlProjects.enableFor(model, null), "opening a model must not undo the user's choice");
        assertFalse(RsamlProjects.hasNature(project), "validation stays off");
        assertEquals(List.of(), summaries(project), "turning validation off removes its markers");

        RsamlProjects.addNature(project, null);
        assertFalse(RsamlProjects.isOptedOut(project), "turning it on again forgets the choice");
        assertTrue(RsamlProjects.hasNature(project), "validation is on again");
    }

    /** Rule, severity, line, element, fragment and message of each marker of the resource, sorted. */
    private static List<String> described(IResource resource) throws CoreException {
        return markers(resource).stream().map(m -> m.getAttribute(RsamlMarkers.RULE_ID, "?") + " "
                + m.getAttribute(IMarker.SEVERITY, -1) + " line " + m.getAttribute(IMarker.LINE_NUMBER, -1) + " "
                + m.getAttribute(RsamlMarkers.QUALIFIED_NAME, "?") + " "
                + m.getAttribute(RsamlMarkers.URI_FRAGMENT, "?") + " " + m.getAttribute(IMarker.MESSAGE, "?"))
                .sorted().collect(Collectors.toList());
    }

    @Test
    void deletedAndRenamedModelsLoseTheirMarkers() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile deleted = copy(TestRepository.example("exp2-defects.rsaml"), "a.rsaml");
        IFile renamed = copy(TestRepository.example("exp2-defects.rsaml"), "b.rsaml");
        IFile kept = copy(TestRepository.example("exp2-defects.rsaml"), "c.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(3 * EXPERIMENT_TWO.size(), markers(project).size(), "each of the three copies has its findings marked");

        deleted.delete(true, null);
        renamed.move(IPath.fromOSString("b.txt"), true, null);
        project.build(IncrementalProjectBuilder.INCREMENTAL_BUILD, null);

        assertEquals(List.of(), summaries(project.getFile("b.txt")), "a model renamed to .txt loses its markers");
        assertEquals(EXPERIMENT_TWO, summaries(kept), "the untouched model keeps its markers");
        assertEquals(EXPERIMENT_TWO.size(), markers(project).size(), "the deleted model's markers are gone");

        project.getFile("b.txt").move(IPath.fromOSString("d.rsaml"), true, null);
        project.build(IncrementalProjectBuilder.INCREMENTAL_BUILD, null);
        assertEquals(EXPERIMENT_TWO, summaries(project.getFile("d.rsaml")), "a file renamed to .rsaml is validated again");
    }

    @Test
    void aCleanExampleGetsNoMarker() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile clean = copy(TestRepository.example("exp3-task-interpreter.rsaml"), "exp3-task-interpreter.rsaml");
        IFile defective = copy(TestRepository.example("exp2-defects.rsaml"), "exp2-defects.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);

        assertEquals(List.of(), summaries(clean), "a model without defects gets no marker");
        assertEquals(EXPERIMENT_TWO, summaries(defective), "the builder ran");
    }

    @Test
    void otherFilesAndDerivedCopiesAreIgnored() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile model = copy(TestRepository.example("exp2-defects.rsaml"), "exp2-defects.rsaml");
        IFile xml = copy(TestRepository.example("exp2-defects.rsaml"), "exp2-defects.xml");
        IFile text = copy(TestRepository.resource("org.rsaml.ide.tests", "models/malformed-unclosed-layer.rsaml"), "notes.txt");
        IFolder bin = project.getFolder("bin");
        bin.create(true, true, null);
        bin.setDerived(true, null);
        IFile derived = copy(TestRepository.example("exp2-defects.rsaml"), "bin/exp2-defects.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);

        assertEquals(EXPERIMENT_TWO, summaries(model), "the builder ran");
        assertEquals(List.of(), summaries(xml), "a .xml file is not validated as a model");
        assertEquals(List.of(), summaries(text), "a .txt file is not validated as a model");
        assertEquals(List.of(), summaries(derived), "a derived copy (build output) is not validated");

        derived.setContents(Files.newInputStream(TestRepository.resource("org.rsaml.ide.tests", "models/malformed-unclosed-layer.rsaml")), IResource.FORCE, null);
        project.build(IncrementalProjectBuilder.INCREMENTAL_BUILD, null);
        assertEquals(List.of(), summaries(derived), "a changed derived copy is still not validated");
    }

    @Test
    void aTextualModelIsValidatedLikeAnXmiOneWithItsTextLine() throws Exception {
        RsamlProjects.addNature(project, null);
        Path source = TestRepository.resource("org.rsaml.ide.tests", "models/mismatched-scan.rsa");
        IFile file = copy(source, "models/mismatched-scan.rsa");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);

        // The costmap's port expects PointCloud2 where the driver sends LaserScan: the connection on line 23.
        assertEquals(List.of("RSA-02 line 23 error"), summaries(file), "the .rsa file is validated, located at its text line");
        String expected = RsamlModelValidator.validate(source, "mismatched-scan.rsa").get(0).message();
        assertEquals("RSA-02: " + expected, marker(file, "RSA-02").getAttribute(IMarker.MESSAGE),
                "the same message as the command line's");

        // Fixing the text clears the marker on the next incremental build.
        String fixed = Files.readString(source).replace("\"PointCloud2\"", "\"LaserScan\"");
        file.setContents(new ByteArrayInputStream(fixed.getBytes(StandardCharsets.UTF_8)), IResource.FORCE, null);
        project.build(IncrementalProjectBuilder.INCREMENTAL_BUILD, null);
        assertEquals(List.of(), summaries(file), "the fixed text model has no finding");

        // A syntax error is a load error on its line, not a stack trace.
        file.setContents(new ByteArrayInputStream("architecture a {\n  layer l {\n    level high\n  }\n}\n"
                .getBytes(StandardCharsets.UTF_8)), IResource.FORCE, null);
        project.build(IncrementalProjectBuilder.INCREMENTAL_BUILD, null);
        List<String> loadErrors = summaries(file);
        assertFalse(loadErrors.isEmpty(), "the syntax error is marked");
        assertTrue(loadErrors.stream().allMatch((RsamlMarkers.LOAD_ERROR_RULE_ID + " line 3 error")::equals),
                "every load error is on the line of 'level high': " + loadErrors);
        assertTrue(markers(file).stream().anyMatch(m -> m.getAttribute(IMarker.MESSAGE, "").contains("'high'")),
                "a marker names the offending text: " + loadErrors);
    }

    @Test
    void onlyProjectsWithTheNatureAreValidated() throws Exception {
        IFile file = copy(TestRepository.example("exp2-defects.rsaml"), "exp2-defects.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertFalse(RsamlProjects.hasNature(project), "a new project has no RsaML validation");
        assertEquals(List.of(), summaries(project), "a project without the nature gets no marker");

        RsamlProjects.addNature(project, null);
        assertTrue(RsamlProjects.hasNature(project), "adding the nature turns validation on");
        assertEquals(List.of(RsamlProjects.BUILDER_ID), builders(), "the nature adds RsaML's builder");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(EXPERIMENT_TWO, summaries(file), "the build marks the findings the model states");

        RsamlProjects.removeNature(project, null);
        assertFalse(RsamlProjects.hasNature(project), "removing the nature turns validation off");
        assertEquals(List.of(), builders(), "removing the nature removes RsaML's builder");
        assertEquals(List.of(), summaries(project), "removing the nature removes its markers");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(List.of(), summaries(project), "a build without the nature marks nothing");
    }

    @Test
    void cleaningTheProjectRemovesTheMarkersAndAFullBuildRestoresThem() throws Exception {
        RsamlProjects.addNature(project, null);
        IFile file = copy(TestRepository.example("exp2-defects.rsaml"), "exp2-defects.rsaml");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(EXPERIMENT_TWO, summaries(file), "the build marks the findings the model states");

        project.build(IncrementalProjectBuilder.CLEAN_BUILD, null);
        assertEquals(List.of(), summaries(file), "Clean removes the markers");
        project.build(IncrementalProjectBuilder.FULL_BUILD, null);
        assertEquals(EXPERIMENT_TWO, summaries(file), "a full build after Clean restores the markers");
    }

    private IFile copy(Path source, String workspacePath) throws Exception {
        IFile file = project.getFile(workspacePath);
        if (file.getParent() instanceof IFolder folder && !folder.exists()) {
            createFolders(folder);
        }
        file.create(Files.newInputStream(source), true, null);
        return file;
    }

    private static void createFolders(IFolder folder) throws CoreException {
        if (folder.getParent() instanceof IFolder parent && !parent.exists()) {
            createFolders(parent);
        }
        folder.create(true, true, null);
    }

    private List<String> builders() throws CoreException {
        return Arrays.stream(project.getDescription().getBuildSpec()).map(c -> c.getBuilderName()).collect(Collectors.toList());
    }

    private static List<IMarker> markers(IResource resource) throws CoreException {
        return Arrays.stream(resource.findMarkers(RsamlMarkers.PROBLEM, true, IResource.DEPTH_INFINITE))
                .sorted(Comparator.comparing(m -> m.getAttribute(RsamlMarkers.RULE_ID, ""))).collect(Collectors.toList());
    }

    private static IMarker marker(IResource resource, String ruleId) throws CoreException {
        return markers(resource).stream().filter(m -> ruleId.equals(m.getAttribute(RsamlMarkers.RULE_ID, ""))).findFirst()
                .orElseThrow(() -> new AssertionError("no " + ruleId + " marker on " + resource));
    }

    /** "RSA-08 line 50 error" per marker, sorted by rule id. */
    private static List<String> summaries(IResource resource) throws CoreException {
        Map<Integer, String> severities = Map.of(IMarker.SEVERITY_ERROR, "error", IMarker.SEVERITY_WARNING, "warning",
                IMarker.SEVERITY_INFO, "info");
        return markers(resource).stream().map(m -> m.getAttribute(RsamlMarkers.RULE_ID, "?") + " line "
                + m.getAttribute(IMarker.LINE_NUMBER, -1) + " " + severities.get(m.getAttribute(IMarker.SEVERITY, -1)))
                .collect(Collectors.toList());
    }

    /** What exp2-defects.rsaml states it gives ({@code <!-- expect: -->}), as "RSA-08 line 50 error". */
    private static List<String> experimentTwo() {
        try {
            List<String> expected = new ArrayList<>(ExpectedFinding.of(TestRepository.example("exp2-defects.rsaml")).stream()
                    .map(f -> f.ruleId() + " line " + f.line() + " " + f.severity()).toList());
            assertEquals(5, expected.stream().filter(f -> f.endsWith(" error")).count(), "exp2-defects.rsaml states the paper's five defects");
            expected.sort(null);
            return expected;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static List<Long> ids(IResource resource) throws CoreException {
        return markers(resource).stream().map(IMarker::getId).sorted().collect(Collectors.toList());
    }
}
