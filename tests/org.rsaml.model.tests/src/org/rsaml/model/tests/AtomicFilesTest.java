/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.support.AtomicFiles;

/** Files RsaML produces (reports, diagrams, timelines) are replaced whole, readable by others, never left half written. */
class AtomicFilesTest {

    @Test
    void aFileIsReplacedWholeWithTheUmasksPermissionsAndNothingIsLeftBeside(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("out/diagram.svg");
        AtomicFiles.writeString(file, "x".repeat(100_000));
        AtomicFiles.writeString(file, "<svg/>");
        assertEquals("<svg/>", Files.readString(file), "the new content, nothing of the old");
        try (Stream<Path> files = Files.list(file.getParent())) {
            assertEquals(List.of(file), files.toList(), "no temporary file is left");
        }
        if (Files.getFileStore(file).supportsFileAttributeView("posix")) {
            Path ordinary = Files.createFile(dir.resolve("ordinary"));
            assertEquals(Files.getPosixFilePermissions(ordinary), Files.getPosixFilePermissions(file),
                    "the permissions of any new file (the umask's), not a temporary file's owner-only ones");
        }
    }

    @Test
    void aFailingWriterLeavesTheOldFileAndNoTemporaryFile(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("report.json");
        Files.writeString(file, "old");
        IOException e = assertThrows(IOException.class, () -> AtomicFiles.write(file, out -> {
            out.write("half");
            throw new IOException("disk full");
        }), "a failing writer's exception is passed on");
        assertEquals("disk full", e.getMessage(), "the writer's failure is passed on");
        assertEquals("old", Files.readString(file), "the old file is kept");
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList(), "no temporary file is left");
        }
    }

    @Test
    void aDirectoryWhereTheFileGoesIsRefusedWithTheReason(@TempDir Path dir) throws Exception {
        Path taken = Files.createDirectories(dir.resolve("timeline.svg"));
        FileSystemException e = assertThrows(FileSystemException.class, () -> AtomicFiles.writeString(taken, "<svg/>"), "writing over a directory is refused with a file-system error");
        assertEquals("it is a directory", AtomicFiles.reason(e, taken), "the reason, without repeating the file");
        assertEquals("permission denied (/x/y)", AtomicFiles.reason(new java.nio.file.AccessDeniedException("/x/y"), taken),
                "another file is named");
    }

    @Test
    void aFileReachedThroughALinkIsReplacedWhereItIsAndKeepsItsPermissions(@TempDir Path dir) throws Exception {
        Path real = Files.writeString(Files.createDirectories(dir.resolve("shared")).resolve("robot.rsa"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("robot.rsa"), Path.of("shared/robot.rsa"));
        boolean posix = Files.getFileStore(real).supportsFileAttributeView("posix");
        if (posix) {
            Files.setPosixFilePermissions(real, java.nio.file.attribute.PosixFilePermissions.fromString("rw-rw----"));
        }
        AtomicFiles.writeString(link, "new");
        assertTrue(Files.isSymbolicLink(link), "the link is still a link");
        assertEquals("new", Files.readString(real), "the file the link points at is replaced");
        if (posix) {
            assertEquals("rw-rw----", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(real)),
                    "a replaced file keeps its own permissions (here group-writable)");
        }
        try (Stream<Path> files = Files.list(real.getParent())) {
            assertEquals(List.of(real), files.toList(), "no temporary file is left beside it");
        }
    }

    @Test
    void aLinkToAFileNotYetThereIsWrittenThroughLikeALiveOne(@TempDir Path dir) throws Exception {
        // As after 'ln -s ../shared/report.json out/report.json' before the first run: the report goes where the link
        // points, as it does once the file is there, and the link stays a link.
        Path shared = Files.createDirectories(dir.resolve("shared"));
        Path link = Files.createSymbolicLink(Files.createDirectories(dir.resolve("out")).resolve("report.json"), Path.of("../shared/report.json"));
        AtomicFiles.writeString(link, "first");
        assertTrue(Files.isSymbolicLink(link), "the dangling link is still a link, not replaced by a regular file");
        assertEquals("first", Files.readString(shared.resolve("report.json")), "the file is made where the link points");
        AtomicFiles.writeString(link, "second");
        assertEquals("second", Files.readString(shared.resolve("report.json")), "and replaced there the next time");
        try (Stream<Path> files = Files.list(dir.resolve("out"))) {
            assertEquals(List.of(link), files.toList(), "nothing beside the link");
        }
    }

    @Test
    void aLinkIntoAMissingFolderOrALoopOfLinksIsRefusedNamingWhereItLeads(@TempDir Path dir) throws Exception {
        Path link = Files.createSymbolicLink(dir.resolve("timeline.svg"), Path.of("gone/timeline.svg"));
        FileSystemException e = assertThrows(FileSystemException.class, () -> AtomicFiles.writeString(link, "<svg/>"),
                "a link into a folder that does not exist is refused");
        assertEquals("it is a symbolic link to " + dir.toAbsolutePath().resolve("gone/timeline.svg")
                + ", whose folder does not exist; create the folder or remove the link", AtomicFiles.reason(e, link),
                "the reason names where the link leads and what to do");
        assertTrue(Files.isSymbolicLink(link) && !Files.exists(dir.resolve("gone")), "the link is kept and no folder is made elsewhere");

        Path a = Files.createSymbolicLink(dir.resolve("a.json"), Path.of("b.json"));
        Files.createSymbolicLink(dir.resolve("b.json"), Path.of("a.json"));
        FileSystemException loop = assertThrows(FileSystemException.class, () -> AtomicFiles.writeString(a, "{}"), "a loop of links is refused");
        assertEquals("too many levels of symbolic links (a loop of links?)", AtomicFiles.reason(loop, a), "the reason says it is a loop");
        assertTrue(Files.isSymbolicLink(a), "the links are kept");
    }

    @Test
    void aFolderWhereNoFileCanBeMadeIsNamedNotTheHiddenTemporaryFile() throws Exception {
        // /proc takes no new files, whoever asks (permissions would not stop root): the failure is said of the
        // report and its folder, not of the hidden temporary file the user never asked for.
        Path file = Path.of("/proc/report.sarif");
        FileSystemException e = assertThrows(FileSystemException.class, () -> AtomicFiles.writeString(file, "{}"),
                "a folder where no file can be made fails the write");
        assertEquals("no such file or directory: no file can be created in /proc", AtomicFiles.reason(e, file),
                "the reason names the folder and no temporary file");
    }
}
