/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;

/**
 * The one way RsaML writes a file it produces (a report, a diagram, a timeline, a converted model): into a hidden
 * temporary file beside it, then moved over it, so a reader never sees half a file and a failure leaves the old one. A
 * new file gets the permissions any program's output gets (those the umask allows; {@code Files.createTempFile} would
 * make it owner-only), since CI often reads it as another user; a file replaced keeps its own. A file reached through a
 * symbolic link is written where the link points, the link kept, whether the file there exists yet or not (as a shell's
 * {@code >} writes through a link); a link whose target's folder does not exist, or a loop of links, is refused with a
 * reason naming where it leads.
 */
public final class AtomicFiles {

    /** What goes into the file. */
    @FunctionalInterface
    public interface Content {
        void writeTo(Writer out) throws IOException;
    }

    private AtomicFiles() {
    }

    /** Writes {@code text} (UTF-8) to {@code file}, replacing it; missing folders are created. */
    public static void writeString(Path file, String text) throws IOException {
        write(file, out -> out.write(text));
    }

    /**
     * Writes what {@code content} produces (UTF-8) to {@code file}, replacing it; missing folders are created.
     *
     * @throws FileSystemException with the reason {@code it is a directory} when a directory is where the file goes
     */
    public static void write(Path file, Content content) throws IOException {
        Interruptions.checkWrite();
        Path target = file.toAbsolutePath();
        Files.createDirectories(target.getParent());
        target = throughLinks(target);
        if (Files.isDirectory(target)) {
            throw new FileSystemException(target.toString(), null, "it is a directory");
        }
        // A file that is there already is replaced where it really is (through a symbolic link, the link stays)
        // and keeps its own permissions.
        Set<PosixFilePermission> permissions = null;
        if (Files.exists(target)) {
            target = target.toRealPath();
            if (Files.getFileStore(target).supportsFileAttributeView(PosixFileAttributeView.class)) {
                permissions = Files.getPosixFilePermissions(target);
            }
        }
        Path dir = target.getParent();
        Path temp;
        try {
            temp = newTemp(dir, target.getFileName().toString());
        } catch (FileSystemException e) {
            // The hidden temporary file is no name the user knows: the failure is said of the file they asked for.
            FileSystemException named = new FileSystemException(file.toString(), null,
                    reason(e, e.getFile() == null ? null : Path.of(e.getFile())) + ": no file can be created in " + dir);
            named.initCause(e);
            throw named;
        }
        try {
            try (Writer out = Files.newBufferedWriter(temp, StandardCharsets.UTF_8)) {
                content.writeTo(out);
            }
            if (permissions != null) {
                Files.setPosixFilePermissions(temp, permissions);
            }
            Interruptions.checkWrite(); // a command stopped while it wrote: the old file stays
            try {
                Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /**
     * Where a write to {@code path} lands: {@code path} itself, or, when it is a symbolic link (to a file that exists or
     * not yet), the path the links lead to.
     */
    private static Path throughLinks(Path path) throws IOException {
        Path at = path;
        for (int hops = 0; Files.isSymbolicLink(at); hops++) {
            if (hops == 40) {
                throw new FileSystemException(path.toString(), null, "too many levels of symbolic links (a loop of links?)");
            }
            Path link = Files.readSymbolicLink(at);
            Path folder = at.getParent();
            Path leadsTo = folder.resolve(link);
            if (leadsTo.getParent() == null) {
                return leadsTo; // the root folder, refused as a directory
            }
            if (!Files.isDirectory(leadsTo.getParent())) {
                throw new FileSystemException(path.toString(), null, "it is a symbolic link to " + leadsTo.normalize()
                        + ", whose folder does not exist; create the folder or remove the link");
            }
            at = leadsTo.getParent().toRealPath().resolve(leadsTo.getFileName());
        }
        return at;
    }

    /** A new, empty, hidden file beside the target, created as an ordinary file is. */
    private static Path newTemp(Path dir, String name) throws IOException {
        for (int attempt = 0;; attempt++) {
            Path temp = dir.resolve("." + name + "." + Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36) + ".tmp");
            try {
                Files.newByteChannel(temp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return temp;
            } catch (FileAlreadyExistsException e) {
                if (attempt > 100) {
                    throw e;
                }
            }
        }
    }

    /**
     * Why a file operation failed, as the operating system says it ({@code permission denied},
     * {@code not a directory}, ...), naming the file when it is not {@code target}.
     */
    public static String reason(IOException e, Path target) {
        String why;
        if (e instanceof FileSystemException fs) {
            why = fs.getReason() != null ? fs.getReason()
                    : e instanceof AccessDeniedException ? "permission denied"
                    : e instanceof NoSuchFileException ? "no such file or directory"
                    : e instanceof NotDirectoryException ? "not a directory"
                    : e instanceof FileAlreadyExistsException ? "it exists and is not a directory"
                    : e instanceof DirectoryNotEmptyException ? "it is a directory that is not empty"
                    : e.getClass().getSimpleName();
            String other = fs.getFile();
            if (other != null && (target == null || !Path.of(other).toAbsolutePath().equals(target.toAbsolutePath()))) {
                why += " (" + other + ")";
            }
        } else {
            why = e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
        }
        return why;
    }
}
