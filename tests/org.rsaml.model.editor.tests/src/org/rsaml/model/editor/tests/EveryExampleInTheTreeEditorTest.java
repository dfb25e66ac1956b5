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
import java.util.stream.Stream;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.rsaml.ide.RsamlMarkers;
import org.rsaml.model.Architecture;
import org.rsaml.model.editor.presentation.spec.RsamlEditorSpec;
import org.rsaml.model.editor.presentation.spec.RsamlValidateAction;
import org.rsaml.tests.support.ExpectedFinding;
import org.rsaml.tests.support.TestRepository;

/**
 * Every example of {@code examples/} opens in RsaML's tree editor, shows its layers, and the editor's
 * <em>Validate</em> marks exactly the findings the model's {@code <!-- expect: -->} comments state (the command
 * line's rule, line and message), each once; an example without findings gets no marker.
 */
class EveryExampleInTheTreeEditorTest {

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

    static Stream<String> examples() throws Exception {
        try (Stream<Path> files = Files.list(TestRepository.root().resolve("examples"))) {
            List<String> names = files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rsaml")).sorted().toList();
            assertFalse(names.isEmpty(), "examples/ holds models");
            return names.stream();
        }
    }

    /** "RSA-08 line 50: RSA-08: Module ..." per RsaML marker of the file, sorted by line and text. */
    private static List<String> markers(IFile file) throws CoreException {
        return Arrays.stream(file.findMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO))
                .map(m -> m.getAttribute(RsamlMarkers.RULE_ID, "?") + " line " + m.getAttribute(IMarker.LINE_NUMBER, -1) + ": "
                        + m.getAttribute(IMarker.MESSAGE, "?"))
                .sorted(Comparator.comparingInt(EveryExampleInTheTreeEditorTest::line).thenComparing(Comparator.naturalOrder()))
                .toList();
    }

    private static int line(String marker) {
        String rest = marker.substring(marker.indexOf(" line ") + 6);
        return Integer.parseInt(rest.substring(0, rest.indexOf(':')));
    }

    @ParameterizedTest
    @MethodSource("examples")
    void opensAndValidateMarksExactlyItsExpectedFindings(String name) throws Exception {
        Path example = TestRepository.example(name);
        project = Workbench.newProject(name.replace(".rsaml", "") + "-tree");
        IFile file = Workbench.copy(project, example, name);
        IEditorPart part = IDE.openEditor(Workbench.page(), file);
        RsamlEditorSpec editor = assertInstanceOf(RsamlEditorSpec.class, part, name + " opens in RsaML's tree editor");
        Workbench.join(RsamlEditorSpec.ENABLE_VALIDATION_FAMILY);
        Workbench.join(ResourcesPlugin.FAMILY_AUTO_BUILD);

        Architecture root = (Architecture) editor.getEditingDomain().getResourceSet().getResources().get(0).getContents().get(0);
        assertFalse(root.getLayers().isEmpty(), name + " shows its layers");
        List<String> expected = ExpectedFinding.of(example).stream()
                .map(f -> f.ruleId() + " line " + f.line() + ": " + f.ruleId() + ": " + f.message())
                .sorted(Comparator.comparingInt(EveryExampleInTheTreeEditorTest::line).thenComparing(Comparator.naturalOrder()))
                .toList();

        file.deleteMarkers(RsamlMarkers.PROBLEM, false, IResource.DEPTH_ZERO);
        RsamlValidateAction validate = new RsamlValidateAction();
        validate.setActiveWorkbenchPart(editor);
        assertTrue(validate.updateSelection(new StructuredSelection(root)), "Validate is enabled on " + name);
        Workbench.closeNextDialog(validate::run, "validate-" + name.replace(".rsaml", ""));
        Workbench.waitUntil("Validate's markers on " + name, () -> {
            try {
                return markers(file).size() >= expected.size();
            } catch (CoreException e) {
                return false;
            }
        });
        Workbench.processEvents();
        assertEquals(expected, markers(file), name + ": Validate marks exactly the findings its expect comments state");
    }
}
