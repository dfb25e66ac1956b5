/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.plugin.EcorePlugin;

/**
 * What a model file may make RsaML open: regular local files of bounded size, and through
 * references only {@code .rsaml} files in the referencing file's folder or below it.
 */
final class LoadPolicy {

    private LoadPolicy() {
    }

    /** Whether RsaML may open this address at all: a local file, or a file of the Eclipse workspace. */
    static boolean isLocal(URI uri) {
        // file:///path (an empty authority, as editors and language clients write it) is local too; file://host/ is not.
        return uri != null && (uri.isFile() && (!uri.hasAuthority() || uri.authority().isEmpty()) || uri.isPlatformResource());
    }

    /** The local file behind a file or workspace address, or null. */
    static Path localFile(URI uri) {
        URI local = uri;
        if (uri.isPlatformResource()) {
            local = EcorePlugin.resolvePlatformResourcePath(uri.toPlatformString(true));
            if (local == null || !local.isFile()) {
                return null;
            }
        }
        try {
            return local.isFile() ? Path.of(local.toFileString()) : null;
        } catch (InvalidPathException e) {
            return null;
        }
    }

    /** Why the resource at {@code uri} must not be opened, or null when it may. Opens nothing. */
    static String refuseToOpen(URI uri, long maxSize) {
        if (uri == null) {
            return null;
        }
        if (!isLocal(uri)) {
            return "'" + uri + "' is not a local file; RsaML reads models only from local files and never opens network or other addresses";
        }
        Path file = localFile(uri);
        if (file == null) {
            return null;
        }
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(file, BasicFileAttributes.class);
        } catch (NoSuchFileException e) {
            return "no such file";
        } catch (AccessDeniedException e) {
            return "the file cannot be read (permission denied)";
        } catch (IOException e) {
            return "the file cannot be read (" + e.getClass().getSimpleName() + ")";
        }
        if (attributes.isDirectory()) {
            return "is a directory, not an .rsaml file";
        }
        if (!attributes.isRegularFile()) {
            return "is not a regular file (a device, a pipe or a socket); RsaML reads models only from regular files";
        }
        if (attributes.size() > maxSize) {
            return "the file is larger (" + mib(attributes.size()) + ") than the " + mib(maxSize) + " RsaML reads";
        }
        return null;
    }

    private static String mib(long bytes) {
        return bytes >= 1 << 20 ? bytes / (1 << 20) + " MiB" : bytes + " bytes";
    }

    /**
     * Why a reference written as {@code literal} in the document at {@code document} must not be
     * followed, or null when it may. Only relative references to {@code .rsaml} files in the
     * document's folder or below it are followed; a symbolic link may not lead out of that folder.
     */
    static String refuseReference(String literal, URI document) {
        URI written;
        try {
            written = URI.createURI(literal).trimFragment();
        } catch (IllegalArgumentException e) {
            return "'" + literal + "' is not a valid reference";
        }
        String hint = "; a reference may name only an .rsaml file in the model's folder or below it, by a relative path";
        if (written.scheme() != null || written.hasAuthority()) {
            return "reference to '" + written + "' refused: RsaML never opens network or other non-file addresses" + hint;
        }
        if (written.hasAbsolutePath() || written.hasDevice()) {
            return "reference to '" + written + "' refused: absolute paths are not followed" + hint;
        }
        for (String segment : written.segments()) {
            if (segment.equals("..") || URI.decode(segment).equals("..")) {
                return "reference to '" + written + "' refused: '..' would leave the model's folder" + hint;
            }
        }
        String last = written.lastSegment();
        if (last == null || !last.endsWith(".rsaml")) {
            return "reference to '" + written + "' refused: it does not name an .rsaml file" + hint;
        }
        if (document == null || !document.isHierarchical() || document.isRelative()) {
            return null;
        }
        Path from = localFile(document);
        Path to = localFile(written.resolve(document));
        if (from == null || to == null || from.getParent() == null) {
            return null;
        }
        Path folder = from.toAbsolutePath().normalize().getParent();
        if (!to.toAbsolutePath().normalize().startsWith(folder)) {
            return "reference to '" + written + "' refused: it leaves the model's folder" + hint;
        }
        try {
            if (Files.exists(to) && !to.toRealPath().startsWith(folder.toRealPath())) {
                return "reference to '" + written + "' refused: a symbolic link leads out of the model's folder" + hint;
            }
        } catch (IOException e) {
            return null; // reported when the file is loaded
        }
        return null;
    }
}
