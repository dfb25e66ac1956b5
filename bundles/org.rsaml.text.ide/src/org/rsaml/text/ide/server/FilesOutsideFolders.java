/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide.server;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.xtext.ide.server.MultiRootWorkspaceConfigFactory;
import org.eclipse.xtext.util.IFileSystemScanner;
import org.eclipse.xtext.workspace.IProjectConfig;
import org.eclipse.xtext.workspace.ISourceFolder;
import org.eclipse.xtext.workspace.IWorkspaceConfig;

/**
 * The editor's workspace folders (none when it opens a single file) and one more project holding every
 * document opened outside them: Xtext builds a document only within a project, and a file opened on its own,
 * or an untitled one, is in no folder. That project is never scanned: it holds only what the editor opens.
 */
public class FilesOutsideFolders extends MultiRootWorkspaceConfigFactory {

    /** The project's name; a workspace folder's project is named after the folder, which cannot hold a colon. */
    static final String NAME = "rsaml:files-outside-folders";

    @Override
    public IWorkspaceConfig getWorkspaceConfig(List<WorkspaceFolder> folders) {
        List<WorkspaceFolder> given = folders == null ? List.of() : folders;
        for (WorkspaceFolder folder : given) {
            URI uri = getUriExtensions().toUri(folder.getUri());
            if (uri.isFile() && !Files.isDirectory(Path.of(uri.toFileString()))) {
                ServerLog.problem("the workspace folder " + folder.getUri() + " is not a directory on this machine:"
                        + " only the documents the editor opens are checked");
            }
        }
        return new Workspace(super.getWorkspaceConfig(given));
    }

    private static final class Workspace implements IWorkspaceConfig {
        private final IWorkspaceConfig folders;
        private final Outside outside = new Outside(this);

        Workspace(IWorkspaceConfig folders) {
            this.folders = folders;
        }

        @Override
        public Set<? extends IProjectConfig> getProjects() {
            Set<IProjectConfig> projects = new LinkedHashSet<>(folders.getProjects());
            projects.add(outside);
            return projects;
        }

        @Override
        public IProjectConfig findProjectContaining(URI member) {
            IProjectConfig project = folders.findProjectContaining(member);
            return project != null ? project : outside;
        }

        @Override
        public IProjectConfig findProjectByName(String name) {
            return NAME.equals(name) ? outside : folders.findProjectByName(name);
        }
    }

    private static final class Outside implements IProjectConfig, ISourceFolder {
        private static final URI PATH = URI.createURI(NAME.replace(':', '-') + ":/");
        private final IWorkspaceConfig workspace;

        Outside(IWorkspaceConfig workspace) {
            this.workspace = workspace;
        }

        @Override
        public String getName() {
            return NAME;
        }

        @Override
        public URI getPath() {
            return PATH;
        }

        @Override
        public Set<? extends ISourceFolder> getSourceFolders() {
            return Set.of(this);
        }

        @Override
        public ISourceFolder findSourceFolderContaining(URI member) {
            return this;
        }

        @Override
        public boolean contains(URI member) {
            return true;
        }

        @Override
        public List<URI> getAllResources(IFileSystemScanner scanner) {
            return List.of();
        }

        @Override
        public IWorkspaceConfig getWorkspaceConfig() {
            return workspace;
        }
    }
}
