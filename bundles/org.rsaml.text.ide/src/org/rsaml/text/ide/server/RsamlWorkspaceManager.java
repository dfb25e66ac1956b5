/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.xtext.ide.server.BuildManager.Buildable;
import org.eclipse.xtext.ide.server.WorkspaceManager;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.Issue;
import org.eclipse.xtext.xbase.lib.Procedures.Procedure2;

/**
 * Xtext's workspace, for the editors that start it without a folder ({@code rootUri} and {@code rootPath}
 * null: a single file opened, Helix, Kate, vim clients) and that send changes to documents they never opened.
 */
public class RsamlWorkspaceManager extends WorkspaceManager {

    @Override
    public void initialize(URI baseDir, Procedure2<? super URI, ? super Iterable<Issue>> issueAcceptor,
            CancelIndicator cancelIndicator) {
        if (baseDir == null) {
            initialize(List.of(), issueAcceptor, cancelIndicator);
        } else {
            super.initialize(baseDir, issueAcceptor, cancelIndicator);
        }
    }

    @Override
    public Buildable didChangeTextDocumentContent(URI uri, Integer version, Iterable<TextDocumentContentChangeEvent> changes) {
        if (!isDocumentOpen(uri)) {
            ServerLog.problem("textDocument/didChange for " + uri + ", which the editor has not opened (no textDocument/didOpen"
                    + " before it): the change is ignored; the document is checked once the editor opens it");
            return Buildable.NO_BUILD;
        }
        return super.didChangeTextDocumentContent(uri, version, changes);
    }
}
