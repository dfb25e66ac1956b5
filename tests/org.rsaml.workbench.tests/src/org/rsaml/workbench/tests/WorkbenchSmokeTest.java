/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.workbench.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.edit.domain.IEditingDomainProvider;
import org.eclipse.ui.IEditorDescriptor;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.Test;
import org.rsaml.model.Architecture;
import org.rsaml.tests.support.TestRepository;

/**
 * The set-up every UI test relies on: the build starts a real workbench (tycho-surefire's UI harness, on Xvfb in
 * CI), RsaML's tree editor is the editor of {@code .rsaml} files there, and it opens an example.
 */
class WorkbenchSmokeTest {

    private static final String EDITOR_ID = "org.rsaml.model.editor.presentation.RsamlEditorID";

    @Test
    void theTreeEditorOpensAnExampleInARunningWorkbench() throws Exception {
        assertTrue(PlatformUI.isWorkbenchRunning(), "the UI harness did not start a workbench");
        IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
        assertNotNull(page, "the workbench has no active page");

        IEditorDescriptor editor = PlatformUI.getWorkbench().getEditorRegistry().getDefaultEditor("exp2-defects.rsaml");
        assertNotNull(editor, "no editor is registered for .rsaml files");
        assertEquals(EDITOR_ID, editor.getId(), "the default editor of .rsaml files");

        IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject("smoke");
        if (!project.exists()) {
            project.create(new NullProgressMonitor());
        }
        project.open(new NullProgressMonitor());
        IFile file = project.getFile("exp2-defects.rsaml");
        if (!file.exists()) {
            try (InputStream model = Files.newInputStream(TestRepository.example("exp2-defects.rsaml"))) {
                file.create(model, true, new NullProgressMonitor());
            }
        }

        IEditorPart part = IDE.openEditor(page, file);
        try {
            assertEquals(EDITOR_ID, part.getSite().getId(), "the editor that opened exp2-defects.rsaml");
            IEditingDomainProvider domain = assertInstanceOf(IEditingDomainProvider.class, part,
                    "the tree editor has no EMF editing domain");
            Resource resource = domain.getEditingDomain().getResourceSet().getResources().get(0);
            assertTrue(resource.getErrors().isEmpty(), () -> "loading exp2 reported " + resource.getErrors());
            assertFalse(resource.getContents().isEmpty(), "the editor loaded an empty exp2-defects.rsaml");
            assertInstanceOf(Architecture.class, resource.getContents().get(0), "the root of exp2-defects.rsaml");
            assertFalse(part.isDirty(), "opening a model made the editor dirty");
        } finally {
            page.closeEditor(part, false);
        }
    }
}
