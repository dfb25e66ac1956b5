/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.core.commands.ParameterizedCommand;
import org.eclipse.core.expressions.IEvaluationContext;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.edit.command.SetCommand;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.viewers.TreeViewer;
import org.eclipse.jface.wizard.WizardDialog;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.ISources;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.handlers.IHandlerService;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.rsaml.ide.RsamlMarkers;
import org.rsaml.ide.RsamlProjects;
import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.editor.presentation.spec.RsamlEditorSpec;
import org.rsaml.model.editor.presentation.spec.RsamlModelWizardSpec;
import org.rsaml.model.editor.presentation.spec.RsamlValidateAction;
import org.rsaml.model.resource.RsamlResource;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The tree editor in a running IDE workbench, as an architect uses it: open a model, Validate it,
 * create one with the wizard, edit a property and save. Screenshots go to target/screenshots/.
 */
class TreeEditorTest {

    /** The README's picture of the tree editor. */
    private static final Path README_PICTURE = TestRepository.root().resolve("docs/images/tree-editor.png");

    private IProject project;

    @BeforeEach
    void sizeTheWindow() {
        PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1200, 800);
    }

    @AfterEach
    void closeAndDelete() throws CoreException {
        Workbench.page().closeAllEditors(false);
        Workbench.processEvents();
        if (project != null) {
            project.delete(true, true, null);
        }
    }

    private RsamlEditorSpec open(IFile file) throws CoreException {
        IEditorPart part = IDE.openEditor(Workbench.page(), file);
        RsamlEditorSpec editor = assertInstanceOf(RsamlEditorSpec.class, part, ".rsaml files open in RsaML's tree editor");
        Workbench.join(RsamlEditorSpec.ENABLE_VALIDATION_FAMILY);
        return editor;
    }

    private static Architecture root(RsamlEditorSpec editor) {
        return (Architecture) editor.getEditingDomain().getResourceSet().getResources().get(0).getContents().get(0);
    }

    /** "RSA-08 line 50: RSA-08: Module ..." per RsaML marker of the file, sorted by line. */
    private static List<String> markers(IFile file) throws CoreException {
        return Arrays.stream(file.findMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO))
                .sorted(Comparator.<IMarker>comparingInt(m -> m.getAttribute(IMarker.LINE_NUMBER, -1))
                        .thenComparing(m -> m.getAttribute(RsamlMarkers.RULE_ID, "?")))
                .map(m -> m.getAttribute(RsamlMarkers.RULE_ID, "?") + " line " + m.getAttribute(IMarker.LINE_NUMBER, -1) + ": "
                        + m.getAttribute(IMarker.MESSAGE, "?"))
                .toList();
    }

    private static void validate(RsamlEditorSpec editor, Object selected, String screenshot) {
        RsamlValidateAction validate = new RsamlValidateAction();
        validate.setActiveWorkbenchPart(editor);
        assertTrue(validate.updateSelection(new StructuredSelection(selected)), "Validate is enabled on " + selected);
        Workbench.closeNextDialog(validate::run, screenshot);
    }

    @Test
    void experimentTwoOpensAndValidateListsTheCommandLinesFiveFindings() throws Exception {
        Path example = TestRepository.example("exp2-defects.rsaml");
        project = Workbench.newProject("inspection-robot");
        IFile file = Workbench.copy(project, example, "exp2-defects.rsaml");
        assertFalse(RsamlProjects.hasNature(project), "a new project has no RsaML validation");
        RsamlEditorSpec editor = open(file);
        assertTrue(RsamlProjects.hasNature(project), "opening a model turns RsaML validation on for its project");
        Workbench.join(ResourcesPlugin.FAMILY_AUTO_BUILD);

        List<String> expected = ExpectedFinding.of(example).stream()
                .sorted(Comparator.comparingInt(ExpectedFinding::line).thenComparing(ExpectedFinding::ruleId))
                .map(f -> f.ruleId() + " line " + f.line() + ": " + f.ruleId() + ": " + f.message()).toList();
        assertEquals(5, ExpectedFinding.of(example).stream().filter(f -> f.severity().equals("error")).count(),
                "exp2 states the paper's five defects (and experiment 1's timing warning)");
        assertEquals(expected, markers(file), "the builder marks the findings the command line prints");

        file.deleteMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO);
        Architecture root = root(editor);
        validate(editor, root, "validate-exp2-dialog");
        Workbench.waitUntil("Validate's markers", () -> {
            try {
                return markers(file).size() >= expected.size();
            } catch (CoreException e) {
                return false;
            }
        });
        assertEquals(expected, markers(file), "Validate marks the command line's findings, on their lines");

        Workbench.page().showView(IPageLayout.ID_PROBLEM_VIEW);
        Workbench.page().activate(editor);
        Workbench.expandTreesStartingWith(editor.getSite().getShell(), "Errors (");
        // the editor is active again once the workbench has handled its activation (its current viewer set then)
        Workbench.waitUntil("the editor's tree, the editor active again", () -> editor.getViewer() != null);
        TreeViewer viewer = (TreeViewer) editor.getViewer();
        viewer.expandToLevel(root, 2);
        editor.setSelectionToViewer(List.of(root.getLayers().get(1).getModules().get(1)));
        Workbench.processEvents();
        String shows = Workbench.labels(viewer.getTree());
        assertTrue(shows.contains("resourceChecker"), () -> "the tree shows the modules:\n" + shows);
        Path picture = Workbench.writePng(Workbench.capture(editor.getSite().getShell()),
                Workbench.SCREENSHOTS.resolve("tree-editor.png"), shows);
        if (Boolean.getBoolean("rsaml.screenshots.update")) {
            Files.copy(picture, README_PICTURE, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        assertTrue(Files.readString(TestRepository.root().resolve("README.md")).contains("docs/images/tree-editor.png"),
                "the README shows the tree editor's picture");
        assertEquals(shows, Workbench.textOf(README_PICTURE), "docs/images/tree-editor.png is out of date (it shows another"
                + " tree): run the editor tests with -Drsaml.screenshots.update=true (README, Building the Eclipse editors)");
    }

    @Test
    void theWizardsModelIsValidAndItsProjectIsValidated() throws Exception {
        project = Workbench.newProject("rover");
        RsamlModelWizardSpec wizard = new RsamlModelWizardSpec() {
            @Override
            public void addPages() {
                super.addPages();
                newFileCreationPage.setFileName("rover.rsaml");
            }
        };
        wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(project));
        WizardDialog dialog = new WizardDialog(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(), wizard);
        dialog.setBlockOnOpen(false);
        dialog.open();
        Workbench.screenshot(dialog.getShell(), "new-model-wizard");
        assertTrue(wizard.performFinish(), "the wizard finishes");
        dialog.close();
        Workbench.join(RsamlEditorSpec.ENABLE_VALIDATION_FAMILY);

        IFile file = project.getFile("rover.rsaml");
        assertTrue(file.exists(), "the wizard creates the file");
        assertTrue(RsamlProjects.hasNature(project), "creating a model turns RsaML validation on");
        assertEquals(List.of(), RsamlModelValidator.validate(file.getLocation().toPath()), "the new model is valid");
        assertInstanceOf(RsamlEditorSpec.class, Workbench.page().getActiveEditor(), "the new model is open in the editor");
        Workbench.join(ResourcesPlugin.FAMILY_AUTO_BUILD);
        assertEquals(List.of(), markers(file), "the builder finds nothing in the new model");
    }

    @Test
    void aPropertyEditAndSaveGetsAMarkerFromTheBuilderAndKeepsTheComments() throws Exception {
        Path example = TestRepository.example("exp1-hybrid.rsaml");
        project = Workbench.newProject("hybrid-robot");
        IFile file = Workbench.copy(project, example, "exp1-hybrid.rsaml");
        RsamlEditorSpec editor = open(file);
        Workbench.join(ResourcesPlugin.FAMILY_AUTO_BUILD);
        // experiment 1's one finding, the timing warning it states (RSA-24)
        List<String> stated = ExpectedFinding.of(example).stream()
                .map(f -> f.ruleId() + " line " + f.line() + ": " + f.ruleId() + ": " + f.message()).toList();
        assertEquals(List.of("RSA-24"), ExpectedFinding.of(example).stream().map(ExpectedFinding::ruleId).toList(), "experiment 1 states one warning");
        assertEquals(stated, markers(file), "experiment 1 has no defect, only its timing warning");

        Layer control = root(editor).getLayers().stream().filter(l -> l.getName().equals("control")).findFirst().orElseThrow();
        Module module = control.getModules().get(0);
        // What the Properties view does when the architect types 2.5 into Exec Duration.
        Command edit = SetCommand.create(editor.getEditingDomain(), module, RsamlPackage.Literals.REAL_TIME_ELEMENT__EXEC_DURATION, 2.5);
        assertTrue(edit.canExecute(), "the editor can change the module's execution duration");
        editor.getEditingDomain().getCommandStack().execute(edit);
        assertTrue(editor.isDirty(), "the edited model is dirty");
        editor.doSave(new NullProgressMonitor());
        assertFalse(editor.isDirty(), "the save went through");
        Workbench.join(ResourcesPlugin.FAMILY_AUTO_BUILD);

        int line = ((RsamlResource) module.eResource()).locate(module).line();
        String message = "RSA-08: Module '" + module.getName() + "' takes 2.5 ms but layer 'control' allows at most "
                + control.getMaxExecTime() + " ms";
        // the warning stays, on f0_m01's line in the saved file
        ExpectedFinding warning = ExpectedFinding.of(example).get(0);
        org.eclipse.emf.ecore.EObject f0 = root(editor).getLayers().stream().flatMap(l -> l.getModules().stream()).flatMap(m -> m.getFunctions().stream())
                .filter(f -> warning.qualifiedName().endsWith("/" + f.getName())).findFirst().orElseThrow();
        int warned = ((RsamlResource) f0.eResource()).locate(f0).line();
        assertEquals(List.of("RSA-08 line " + line + ": " + message, "RSA-24 line " + warned + ": RSA-24: " + warning.message()), markers(file),
                "the builder marks the new defect, and experiment 1's warning stays");
        String saved = Files.readString(file.getLocation().toPath());
        assertTrue(saved.lines().toList().get(line - 1).contains("name=\"" + module.getName() + "\""),
                "the marker's line is the module's line in the saved file");
        assertEquals(comments(Files.readString(example)), comments(saved), "the save keeps the file's comments");
        Workbench.screenshot(editor.getSite().getShell(), "tree-editor-after-save");
    }

    /**
     * Configure > Disable RsaML validation turns it off and keeps it off when a model is opened;
     * Configure > Enable RsaML validation turns it on again, and the builder marks the model.
     */
    @Test
    void theConfigureCommandsTurnValidationOffForGoodAndOnAgain() throws Exception {
        project = Workbench.newProject("configured");
        IFile file = Workbench.copy(project, TestRepository.example("exp2-defects.rsaml"), "exp2-defects.rsaml");
        RsamlProjects.addNature(project, null);

        execute("org.rsaml.model.editor.disableValidation");
        assertFalse(RsamlProjects.hasNature(project), "Disable RsaML validation removes the nature");
        open(file);
        assertFalse(RsamlProjects.hasNature(project), "opening a model does not undo Disable");
        Workbench.join(ResourcesPlugin.FAMILY_AUTO_BUILD);
        assertEquals(List.of(), markers(file), "nothing validates the project");
        Workbench.page().closeAllEditors(false);

        execute("org.rsaml.model.editor.enableValidation");
        assertTrue(RsamlProjects.hasNature(project), "Enable RsaML validation adds the nature");
        Workbench.join(ResourcesPlugin.FAMILY_AUTO_BUILD);
        List<String> marked = markers(file);
        int stated = ExpectedFinding.of(TestRepository.example("exp2-defects.rsaml")).size();
        assertEquals(stated, marked.size(), () -> "the builder marks exp2's " + stated + " findings: " + marked);
    }

    /** Runs a command of the editor bundle on the project, as its menu item in Configure does. */
    private void execute(String commandId) throws Exception {
        IHandlerService handlers = PlatformUI.getWorkbench().getService(IHandlerService.class);
        ICommandService commands = PlatformUI.getWorkbench().getService(ICommandService.class);
        IEvaluationContext context = handlers.createContextSnapshot(false);
        context.addVariable(ISources.ACTIVE_CURRENT_SELECTION_NAME, new StructuredSelection(project));
        handlers.executeCommandInContext(new ParameterizedCommand(commands.getCommand(commandId), null), null, context);
        Workbench.processEvents();
    }

    private static List<String> comments(String text) {
        Matcher m = Pattern.compile("<!--(.*?)-->", Pattern.DOTALL).matcher(text);
        return m.results().map(r -> r.group(1)).toList();
    }
}
