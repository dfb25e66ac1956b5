/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;

import org.rsaml.generator.GenerationException;

/**
 * Where generated files may go: every path is resolved inside the output directory, no link is followed out of it,
 * and every refusal names the file as the architect sees it.
 */
final class OutputPaths {

    /** The longest file name (one path segment) common file systems accept, in bytes. */
    static final int MAX_NAME_BYTES = 255;

    private OutputPaths() {
    }

    /** The output is a writable directory, or one that can be created. */
    static void checkOutputDirectory(Path dir, Path out) throws GenerationException {
        if (Files.exists(dir)) {
            if (!Files.isDirectory(dir)) {
                throw new GenerationException(out.toString(), "the output path is a file, not a directory");
            }
            if (!Files.isWritable(dir)) {
                throw new GenerationException(out.toString(), "the output directory is not writable");
            }
            return;
        }
        Path parent = dir.getParent();
        while (parent != null && !Files.exists(parent)) {
            parent = parent.getParent();
        }
        if (parent == null || !Files.isDirectory(parent) || !Files.isWritable(parent)) {
            throw new GenerationException(out.toString(), "the output directory cannot be created here ("
                    + (parent == null ? "no parent directory" : parent + " is not a writable directory") + ")");
        }
    }

    /** Paths are built from sanitised names; this guards the guarantee that none leaves the output. */
    static Path resolveInside(Path dir, String relative, Path out) throws GenerationException {
        Path p = resolveQuietly(dir, relative);
        if (p == null) {
            throw new GenerationException(display(out, relative), "refusing to write outside the output directory");
        }
        for (String segment : relative.split("/")) {
            int bytes = segment.getBytes(StandardCharsets.UTF_8).length;
            if (bytes > MAX_NAME_BYTES) {
                throw new GenerationException(display(out, relative), "a file name made from a model name is " + bytes
                        + " bytes long, more than the " + MAX_NAME_BYTES + " file systems allow; shorten that name (nothing was written)");
            }
        }
        return p;
    }

    /** {@code relative} inside {@code dir}, or null when it is absolute, empty or climbs out. */
    static Path resolveQuietly(Path dir, String relative) {
        if (relative.isEmpty() || relative.startsWith("/") || relative.contains("\\") || relative.contains("\0")) {
            return null;
        }
        for (String segment : relative.split("/")) {
            if (segment.isEmpty() || segment.equals(".") || segment.equals("..")) {
                return null;
            }
        }
        Path p = dir.resolve(relative).normalize();
        return p.startsWith(dir) && !p.equals(dir) ? p : null;
    }

    /**
     * Whether p is a regular file reached from dir without following any link: the only kind of
     * file stale removal may delete, so a link in the output (or a crafted manifest) never leads it
     * outside the output tree.
     */
    static boolean plainFileInside(Path dir, Path p) {
        if (!p.startsWith(dir) || p.equals(dir)) {
            return false;
        }
        for (Path q = p; !q.equals(dir); q = q.getParent()) {
            if (Files.isSymbolicLink(q)) {
                return false;
            }
        }
        if (!Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
            return false;
        }
        try {
            return p.toRealPath().startsWith(dir.toRealPath());
        } catch (IOException e) {
            return false;
        }
    }

    /** No plain file stands where a directory of {@code file}'s path must be. */
    static void checkParents(Path dir, Path file, Path out) throws GenerationException {
        for (Path p = file.getParent(); p != null && p.startsWith(dir) && !p.equals(dir); p = p.getParent()) {
            if (Files.exists(p, LinkOption.NOFOLLOW_LINKS) && !Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
                throw new GenerationException(display(out, dir.relativize(p).toString()),
                        "a file is where RsaML needs a directory; move it away (nothing was written)");
            }
        }
    }

    static byte[] read(Path p, Path out, String relative) throws GenerationException {
        try {
            return Files.readAllBytes(p);
        } catch (IOException e) {
            throw new GenerationException(display(out, relative), "cannot be read: " + e.getMessage(), e);
        }
    }

    /** A generated file as the architect named the output. */
    static String display(Path out, String relative) {
        return out.resolve(relative).toString();
    }
}
