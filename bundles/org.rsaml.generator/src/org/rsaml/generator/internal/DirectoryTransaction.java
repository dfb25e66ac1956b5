/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.rsaml.generator.GenerationException;
import org.rsaml.model.support.Interruptions;

/**
 * Changes an output directory all at once or not at all: the new files are written into a temporary directory beside
 * the output and moved into place, each replaced or removed file kept aside until every move has succeeded, so a
 * failure puts the directory back as it was.
 */
final class DirectoryTransaction {

    /** What one move did, and so how it is undone. */
    private enum Change {
        CREATED, REPLACED, DELETED
    }

    private record Step(String path, Change change) {
    }

    private final Path dir;
    private final Path out;

    /**
     * @param dir the output directory, absolute and normalised
     * @param out the output directory as the architect named it, for messages
     */
    DirectoryTransaction(Path dir, Path out) {
        this.dir = dir;
        this.out = out;
    }

    /**
     * Writes {@code toWrite} (relative path to content) and removes {@code stale}.
     *
     * @throws GenerationException naming the output when anything failed; the directory is then as it was
     */
    void commit(Map<String, byte[]> toWrite, List<String> stale) throws GenerationException {
        Path parent = dir.getParent();
        Path temp;
        try {
            Files.createDirectories(parent);
            temp = Files.createTempDirectory(parent, "." + dir.getFileName() + ".rsaml-");
        } catch (IOException e) {
            throw new GenerationException(out.toString(), "cannot create a temporary directory beside the output: " + e.getMessage(), e);
        }
        try {
            Path staged = temp.resolve("new");
            for (Map.Entry<String, byte[]> e : toWrite.entrySet()) {
                Path p = staged.resolve(e.getKey());
                Files.createDirectories(p.getParent());
                Files.write(p, e.getValue());
            }
            Interruptions.checkWrite(); // a command stopped while it wrote: the output directory stays as it was
            if (!Files.exists(dir)) {
                moveDirectory(staged, dir);
                return;
            }
            replaceFiles(temp.resolve("old"), staged, toWrite.keySet(), stale);
        } catch (IOException e) {
            throw new GenerationException(out.toString(), "cannot write the generated files: " + e.getMessage()
                    + " (the output directory was left as it was)", e);
        } finally {
            deleteTree(temp);
        }
    }

    private static void moveDirectory(Path staged, Path dir) throws IOException {
        try {
            Files.move(staged, dir, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException | FileAlreadyExistsException e) {
            Files.move(staged, dir);
        }
    }

    /** Moves each staged file over its target; on failure puts every replaced file back. */
    private void replaceFiles(Path backup, Path staged, Iterable<String> paths, List<String> stale) throws IOException {
        Deque<Step> done = new ArrayDeque<>();
        List<Path> createdDirs = new ArrayList<>();
        try {
            for (String rel : paths) {
                Path target = dir.resolve(rel);
                createParents(target.getParent(), createdDirs);
                boolean existed = Files.exists(target, LinkOption.NOFOLLOW_LINKS);
                if (existed) {
                    moveAside(backup, rel);
                }
                done.push(new Step(rel, existed ? Change.REPLACED : Change.CREATED));
                Files.move(staged.resolve(rel), target, StandardCopyOption.ATOMIC_MOVE);
            }
            for (String rel : stale) {
                if (!OutputPaths.plainFileInside(dir, dir.resolve(rel))) {
                    continue; // changed since it was checked: leave it alone
                }
                moveAside(backup, rel);
                done.push(new Step(rel, Change.DELETED));
            }
        } catch (IOException failure) {
            rollback(backup, done, createdDirs, failure);
            throw failure;
        }
        for (String rel : stale) {
            removeEmptyParents(dir.resolve(rel).getParent());
        }
    }

    private void moveAside(Path backup, String rel) throws IOException {
        Path aside = backup.resolve(rel);
        Files.createDirectories(aside.getParent());
        Files.move(dir.resolve(rel), aside, StandardCopyOption.ATOMIC_MOVE);
    }

    private void rollback(Path backup, Deque<Step> done, List<Path> createdDirs, IOException failure) {
        while (!done.isEmpty()) {
            Step step = done.pop();
            Path target = dir.resolve(step.path());
            try {
                if (step.change() != Change.DELETED) {
                    Files.deleteIfExists(target);
                }
                if (step.change() != Change.CREATED) {
                    Files.move(backup.resolve(step.path()), target, StandardCopyOption.ATOMIC_MOVE);
                }
            } catch (IOException e) {
                failure.addSuppressed(e);
            }
        }
        for (int i = createdDirs.size() - 1; i >= 0; i--) {
            try {
                Files.deleteIfExists(createdDirs.get(i));
            } catch (IOException e) {
                failure.addSuppressed(e);
            }
        }
    }

    private void createParents(Path p, List<Path> created) throws IOException {
        List<Path> missing = new ArrayList<>();
        for (Path q = p; q != null && !q.equals(dir) && !Files.exists(q); q = q.getParent()) {
            missing.add(0, q);
        }
        for (Path q : missing) {
            Files.createDirectory(q);
            created.add(q);
        }
    }

    private void removeEmptyParents(Path p) {
        for (Path q = p; q != null && q.startsWith(dir) && !q.equals(dir); q = q.getParent()) {
            if (!Files.isDirectory(q, LinkOption.NOFOLLOW_LINKS)) {
                return;
            }
            try (Stream<Path> children = Files.list(q)) {
                if (children.findAny().isPresent()) {
                    return;
                }
                Files.delete(q);
            } catch (IOException e) {
                return;
            }
        }
    }

    private static void deleteTree(Path root) {
        if (!Files.exists(root, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (Stream<Path> walk = Files.walk(root)) {
            for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException e) {
            // A leftover temporary directory is harmless; it is named after the output and hidden.
        }
    }
}
