/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Mistakes a user makes on the command line, and report files as other users and tools read them. */
class UsabilityTest {

    @Test
    void aMisspelledCommandSuggestsTheClosestOne() {
        Cli.Result r = Cli.run("valdate", "examples/");
        assertEquals(2, r.code(), r::toString);
        assertTrue(r.err().contains("Did you mean validate?"), r::toString);
        BadInputTest.assertNoStackTrace(r);
    }

    @Test
    void aMisspelledOptionSuggestsTheClosestOne() {
        Cli.Result r = Cli.run("validate", "--fromat", "json", "examples/");
        assertEquals(2, r.code(), r::toString);
        assertTrue(r.err().contains("Did you mean --format?"), r::toString);

        Cli.Result generate = Cli.run("generate", "--targt", "cpp", "-o", "out", "examples/exp1-hybrid.rsaml");
        assertEquals(2, generate.code(), generate::toString);
        assertTrue(generate.err().contains("Did you mean --target?"), generate::toString);
    }

    @Test
    void aReportThatCannotBeWrittenSaysWhy(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("blocker"), "a file where a directory is needed");
        Cli.Result r = Cli.runIn(dir, "validate", "--output", "sarif=blocker/rsaml.sarif", Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString());
        assertEquals(2, r.code(), r::toString);
        assertTrue(r.err().contains("blocker/rsaml.sarif: error: cannot write the sarif report: it exists and is not a directory ("), r::toString);

        Files.createDirectories(dir.resolve("taken.sarif"));
        Cli.Result directory = Cli.runIn(dir, "validate", "--output", "taken.sarif", Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString());
        assertEquals(2, directory.code(), directory::toString);
        assertTrue(directory.err().contains("taken.sarif: error: cannot write the sarif report: it is a directory"), directory::toString);
        assertTrue(Files.isDirectory(dir.resolve("taken.sarif")), "the directory is left as it was");
    }

    @Test
    void aReportPathThatIsALinkIsWrittenWhereItPointsOrRefusedNamingWhere(@TempDir Path dir) throws Exception {
        // As after 'ln -s ../shared/rsaml.sarif ci/rsaml.sarif' before the first run: the report is made where the link
        // points and the link stays; a link into a folder that is not there is refused, saying where it leads.
        Path shared = Files.createDirectories(dir.resolve("shared"));
        Path ci = Files.createDirectories(dir.resolve("ci"));
        Files.createSymbolicLink(ci.resolve("rsaml.sarif"), Path.of("../shared/rsaml.sarif"));
        Files.createSymbolicLink(ci.resolve("rsaml.json"), Path.of("../gone/rsaml.json"));
        String model = Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString();
        Cli.Result r = Cli.runIn(dir, "validate", "--output", "ci/rsaml.sarif", model);
        assertEquals(0, r.code(), r::toString);
        assertTrue(Files.isSymbolicLink(ci.resolve("rsaml.sarif")), "the link is still a link, not replaced by the report");
        assertTrue(Files.readString(shared.resolve("rsaml.sarif")).contains("\"version\": \"2.1.0\""), "the SARIF report is where the link points");

        Cli.Result refused = Cli.runIn(dir, "validate", "--output", "ci/rsaml.json", model);
        assertEquals(2, refused.code(), refused::toString);
        assertTrue(refused.err().contains("ci/rsaml.json: error: cannot write the json report: it is a symbolic link to "
                + dir.toAbsolutePath().resolve("gone/rsaml.json") + ", whose folder does not exist; create the folder or remove the link"), refused::toString);
        assertTrue(Files.isSymbolicLink(ci.resolve("rsaml.json")) && !Files.exists(dir.resolve("gone")), "the link is kept and no folder is made");
    }

    @Test
    void reportFilesGetTheUsualPermissions(@TempDir Path dir) throws Exception {
        // What the umask gives any new file, as a compiler's output gets; not owner-only.
        Path probe = dir.resolve("probe");
        Files.newOutputStream(probe, StandardOpenOption.CREATE_NEW).close();
        Cli.Result r = Cli.runIn(dir, "validate", "--output", "sarif=r.sarif", "--output", "junit=r.xml", "--output", "r.json",
                "--output", "r.txt", Cli.ROOT.resolve("examples/exp1-hybrid.rsaml").toString());
        assertEquals(0, r.code(), r::toString);
        for (String name : new String[] { "r.sarif", "r.xml", "r.json", "r.txt" }) {
            assertEquals(Files.getPosixFilePermissions(probe), Files.getPosixFilePermissions(dir.resolve(name)), name);
        }
    }
}
