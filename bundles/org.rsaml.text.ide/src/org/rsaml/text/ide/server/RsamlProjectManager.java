/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.util.function.Predicate;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.ide.server.ProjectManager;
import org.eclipse.xtext.resource.IExternalContentSupport.IExternalContentProvider;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsData;
import org.rsaml.model.resource.RsamlResource;

/**
 * Xtext's project, whose resource sets tell RsaML's loading policy which documents the editor holds: those are
 * read from the editor, not opened (an unsaved document has no file to open).
 */
public class RsamlProjectManager extends ProjectManager {

    @Override
    protected XtextResourceSet createFreshResourceSet(ResourceDescriptionsData index) {
        XtextResourceSet resourceSet = super.createFreshResourceSet(index);
        IExternalContentProvider editor = getOpenedDocumentsContentProvider();
        if (editor != null) {
            Predicate<URI> held = editor::hasContent;
            resourceSet.getLoadOptions().put(RsamlResource.OPTION_EDITOR_TEXT, held);
        }
        return resourceSet;
    }
}
