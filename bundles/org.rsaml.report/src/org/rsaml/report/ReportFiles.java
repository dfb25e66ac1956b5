/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.report;

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
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes report files whole or not at all: a failed run never leaves half a report behind. Files
 * get the permissions any compiler output gets (those the umask allows), since CI often reads them
 * as another user.
 */
public final class ReportFiles {

    private ReportFiles() {
    }

    /** Writes {@code report} in {@code format} to {@code file}, replacing it. */
    public static void write(Path file, ReportFormat format, Report report, ReportOptions options) throws IOException {
        Path target = file.toAbsolutePath();
        Path dir = target.getParent();
        Files.createDirectories(dir);
        if (Files.isDirectory(target)) {
            throw new FileSystemException(target.toString(), null, "it is a directory");
        }
        Path temp = newTemp(dir, target.getFileName().toString());
        try {
            try (Writer out = Files.newBufferedWriter(temp, StandardCharsets.UTF_8)) {
                format.write(report, out, options);
            }
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
     * A new file beside the target, created as an ordinary file is (mode 0666 less the umask):
     * {@code Files.createTempFile} would make it owner-only.
     */
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
