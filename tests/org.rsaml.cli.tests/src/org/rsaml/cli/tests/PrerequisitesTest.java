/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The system tools the tests need, listed once (releng/prerequisites.txt), checked first and named in the README. */
class PrerequisitesTest {

    static final Path LIST = Cli.ROOT.resolve("releng/prerequisites.txt");

    static List<String> packages() throws Exception {
        return Files.readAllLines(LIST).stream().filter(l -> !l.isBlank() && !l.startsWith("#"))
                .map(l -> l.substring(0, l.indexOf('|')).trim()).toList();
    }

    @Test
    void theReadmeInstallLineNamesEveryListedPackage() throws Exception {
        String readme = Files.readString(Cli.ROOT.resolve("README.md"));
        String joined = readme.replace("\\\n", " ");
        String line = joined.lines().filter(l -> l.startsWith("sudo apt-get install -y ")).findFirst().orElseThrow();
        List<String> named = Arrays.asList(line.substring("sudo apt-get install -y ".length()).trim().split(" +"));
        List<String> listed = packages();
        assertTrue(listed.size() >= 5, listed::toString);
        assertTrue(named.containsAll(listed), () -> "README: " + named + ", releng/prerequisites.txt: " + listed);
    }

    @Test
    void aMissingToolStopsTheCheckWithItsNameAndTheInstallLine(@TempDir Path dir) throws Exception {
        // A PATH with the shell tools the script uses and the listed tools, except cmake.
        Path bin = Files.createDirectories(dir.resolve("bin"));
        for (String tool : List.of("sh", "dirname", "tr", "sed", "g++", "make", "node", "npm", "Xvfb", "xvfb-run", "xauth")) {
            wrap(bin, tool, false);
        }
        wrap(bin, "python3", true);
        Cli.Result missing = run(bin, "releng/prerequisites.sh");
        assertEquals(1, missing.code(), missing::toString);
        assertTrue(missing.out().contains("[ERROR]   cmake ("), missing::toString);
        assertFalse(missing.out().contains("[ERROR]   make ("), missing::toString);
        assertTrue(missing.out().contains("sudo apt-get install -y " + String.join(" ", packages())), missing::toString);
        assertEquals("cmake\n", run(bin, "releng/prerequisites.sh", "--missing").out(), "what .ci/run installs");

        wrap(bin, "cmake", false);
        Cli.Result complete = run(bin, "releng/prerequisites.sh");
        assertEquals(0, complete.code(), complete::toString);
        assertEquals("", complete.out(), complete::toString);
    }

    /**
     * {@code bin/tool} runs the tool found on this JVM's PATH; with {@code fullPath} it runs with that
     * PATH, as version-manager shims (pyenv) need.
     */
    private static void wrap(Path bin, String tool, boolean fullPath) throws Exception {
        String path = System.getenv("PATH");
        for (String dir : path.split(":")) {
            Path found = Path.of(dir, tool);
            if (Files.isExecutable(found)) {
                Path wrapper = bin.resolve(tool);
                Files.writeString(wrapper, "#!/bin/sh\n" + (fullPath ? "PATH='" + path + "' " : "") + "exec '" + found + "' \"$@\"\n");
                wrapper.toFile().setExecutable(true);
                return;
            }
        }
        throw new AssertionError(tool + " is not on the PATH");
    }

    private static Cli.Result run(Path bin, String... script) throws Exception {
        ProcessBuilder builder = new ProcessBuilder();
        List<String> command = new java.util.ArrayList<>(List.of(bin.resolve("sh").toString()));
        command.add(Cli.ROOT.resolve(script[0]).toString());
        command.addAll(Arrays.asList(script).subList(1, script.length));
        builder.command(command).environment().put("PATH", bin.toString());
        Path out = Files.createTempFile("prerequisites", ".txt");
        Process p = builder.redirectErrorStream(true).redirectOutput(out.toFile()).start();
        int code = p.waitFor();
        String text = Files.readString(out);
        Files.delete(out);
        return new Cli.Result(code, text, "");
    }
}
