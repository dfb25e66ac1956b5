/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.Finding;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.Severity;

/** Where the repository's files are, and how the tests run the tools a user would run. */
final class Tools {
    private Tools() {
    }

    static Path root() {
        return TestRepository.root();
    }

    static Path example(String name) {
        return root().resolve("examples").resolve(name);
    }

    static Path resource(String name) {
        return root().resolve("tests/org.rsaml.generator.tests/resources").resolve(name);
    }

    /** The example models without error findings: the ones generation accepts. */
    static List<String> cleanExamples() throws IOException, ModelLoadException {
        List<String> clean = new ArrayList<>();
        try (Stream<Path> files = Files.list(root().resolve("examples"))) {
            for (Path p : files.filter(f -> f.toString().endsWith(".rsaml")).sorted().toList()) {
                List<Finding> findings = RsamlModelValidator.validate(p);
                if (findings.stream().noneMatch(f -> f.severity() == Severity.ERROR)) {
                    clean.add(p.getFileName().toString());
                }
            }
        }
        return clean;
    }

    /**
     * A test option given as -DNAME=VALUE (the test bundle's pom hands it to the tests), or "" when
     * not given: the build passes an option it leaves empty as the text null.
     */
    static String option(String name) {
        String value = System.getProperty(name, "").strip();
        return value.equals("null") ? "" : value;
    }

    record Result(int exit, String output) {
    }

    /** Runs a command, its output (stdout and stderr) captured, and fails the test when it hangs. */
    static Result run(Path dir, long timeoutSeconds, String... command) throws IOException, InterruptedException {
        Path log = Files.createTempFile("rsaml-cmd", ".log");
        try {
            Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                    .redirectOutput(log.toFile()).start();
            if (!p.waitFor(timeoutSeconds, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                fail(String.join(" ", command) + " did not finish within " + timeoutSeconds + " s:\n" + tail(log));
            }
            return new Result(p.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
        } finally {
            Files.deleteIfExists(log);
        }
    }

    /** Runs a command that must succeed. */
    static String ok(Path dir, long timeoutSeconds, String... command) throws IOException, InterruptedException {
        Result r = run(dir, timeoutSeconds, command);
        assertEquals(0, r.exit(), () -> String.join(" ", command) + " failed:\n" + last(r.output(), 6000));
        return r.output();
    }

    /** Configures and builds a generated C++ project, warnings as errors; returns the executable. */
    static Path cmakeBuild(Path project, String executable) throws IOException, InterruptedException {
        return cmakeBuild(project, executable, "");
    }

    /**
     * The same, with more compiler flags (e.g. a sanitizer, which the link then needs too).
     * <p>
     * Builds are shared between the tests: a project is built once per content (every file of it,
     * generated and user-owned) and flags, in {@code target/cpp-builds/<digest>/}, and a test that
     * generates the same project again runs the same executable. The configure and build commands
     * and their checks are those of a fresh build; only the repetition is saved.
     */
    static synchronized Path cmakeBuild(Path project, String executable, String flags) throws IOException, InterruptedException {
        String key = digest(project, flags);
        Path cached = buildCache().resolve(key);
        Path exe = cached.resolve("build").resolve(executable);
        if (Files.isExecutable(exe) && Files.exists(cached.resolve("complete"))) {
            return exe;
        }
        deleteTree(cached);
        Path source = cached.resolve("project");
        copyTree(project, source);
        ok(source, 300, "cmake", "-S", ".", "-B", cached.resolve("build").toString(), "-DCMAKE_BUILD_TYPE=Debug",
                ("-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wpedantic -Werror " + flags).strip(), "-DCMAKE_EXE_LINKER_FLAGS=" + flags);
        ok(source, 600, "cmake", "--build", cached.resolve("build").toString(), "-j2");
        if (!Files.isExecutable(exe)) {
            fail("the build of " + project + " produced no executable " + executable);
        }
        Files.writeString(cached.resolve("complete"), project.toString());
        return exe;
    }

    /** Where the shared builds are: under the test bundle's target/. */
    static Path buildCache() {
        return root().resolve("tests/org.rsaml.generator.tests/target/cpp-builds");
    }

    /** A digest of every file of a project (paths and bytes, build output aside) and the flags. */
    private static String digest(Path project, String flags) throws IOException {
        try {
            java.security.MessageDigest sha = java.security.MessageDigest.getInstance("SHA-256");
            sha.update(flags.getBytes(StandardCharsets.UTF_8));
            for (Map.Entry<String, byte[]> f : snapshot(project).entrySet()) {
                if (f.getKey().startsWith("build/")) {
                    continue;
                }
                sha.update(("\0" + f.getKey() + "\0" + f.getValue().length + "\0").getBytes(StandardCharsets.UTF_8));
                sha.update(f.getValue());
            }
            return java.util.HexFormat.of().formatHex(sha.digest()).substring(0, 24);
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    private static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> walk = Files.walk(from)) {
            for (Path p : walk.toList()) {
                String rel = from.relativize(p).toString().replace('\\', '/');
                if (rel.equals("build") || rel.startsWith("build/")) {
                    continue;
                }
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(p, target);
                }
            }
        }
    }

    private static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> walk = Files.walk(dir)) {
            for (Path p : walk.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    /**
     * Says in the build's log how long a step of a slow test took, with the machine's load average (on CI's 2 cores, where
     * the time goes): "TEST: WHAT in 12.3 s (load 1.02 0.98 0.87 ...)".
     */
    static void took(String test, String what, long startedNanos) {
        String load;
        try {
            load = "load " + Files.readString(Path.of("/proc/loadavg")).strip();
        } catch (IOException e) {
            load = "load unknown";
        }
        System.out.printf("%s: %s in %.1f s (%s)%n", test, what, (System.nanoTime() - startedNanos) / 1e9, load);
    }

    /** Every file under dir, by relative path, with its bytes. */
    static Map<String, byte[]> snapshot(Path dir) throws IOException {
        Map<String, byte[]> files = new TreeMap<>();
        if (!Files.exists(dir)) {
            return files;
        }
        try (Stream<Path> walk = Files.walk(dir)) {
            for (Path p : walk.filter(Files::isRegularFile).toList()) {
                files.put(dir.relativize(p).toString().replace('\\', '/'), Files.readAllBytes(p));
            }
        }
        return files;
    }

    static boolean sameFiles(Map<String, byte[]> a, Map<String, byte[]> b) {
        if (!a.keySet().equals(b.keySet())) {
            return false;
        }
        return a.entrySet().stream().allMatch(e -> Arrays.equals(e.getValue(), b.get(e.getKey())));
    }

    private static String tail(Path log) {
        try {
            return last(Files.readString(log, StandardCharsets.UTF_8), 3000);
        } catch (IOException e) {
            return "";
        }
    }

    /** Replaces {@code what} in a file (the architect's code a test writes into a generated package), which must hold it. */
    static void replace(Path file, String what, String with) throws IOException {
        String text = Files.readString(file, StandardCharsets.UTF_8);
        if (!text.contains(what)) {
            fail(file + " does not contain " + what + ":\n" + text);
        }
        Files.writeString(file, text.replace(what, with), StandardCharsets.UTF_8);
    }

    static String last(String s, int n) {
        return s.length() <= n ? s : "..." + s.substring(s.length() - n);
    }
}
