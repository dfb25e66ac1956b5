/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.rsaml.cli.RsamlCli;
import org.rsaml.tests.support.TestRepository;

/** Runs {@code rsaml} in this JVM or as a real process, from a given working directory. */
final class Cli {

    /** The repository root: examples/ lives there. */
    static final Path ROOT = TestRepository.root();
    /** This module's test inputs. */
    static final Path INPUTS = ROOT.resolve("tests/org.rsaml.cli.tests/resources/inputs");
    static final Path JAR = Path.of(System.getProperty("rsaml.jar", ROOT + "/cli/org.rsaml.cli/target/rsaml.jar"));

    record Result(int code, String out, String err) {
        List<String> outLines() {
            return out.isEmpty() ? List.of() : List.of(out.split("\n"));
        }

        List<String> errLines() {
            return err.isEmpty() ? List.of() : List.of(err.split("\n"));
        }

        @Override
        public String toString() {
            return "exit " + code + "\n--- stdout\n" + out + "--- stderr\n" + err;
        }
    }

    private Cli() {
    }

    /** In process, from the repository root. */
    static Result run(String... args) {
        return runIn(ROOT, args);
    }

    static Result runIn(Path workingDirectory, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = RsamlCli.run(workingDirectory, args, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Result(code, out.toString().replace("\r\n", "\n"), err.toString().replace("\r\n", "\n"));
    }

    /** A real process: {@code command...} started in {@code workingDirectory}. */
    static Result process(Path workingDirectory, List<String> command) throws IOException, InterruptedException {
        ProcessBuilder builder = new ProcessBuilder(command).directory(workingDirectory.toFile());
        Path out = java.nio.file.Files.createTempFile("rsaml-out", ".txt");
        Path err = java.nio.file.Files.createTempFile("rsaml-err", ".txt");
        builder.redirectOutput(out.toFile()).redirectError(err.toFile());
        Process process = builder.start();
        if (!process.waitFor(120, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("timed out: " + command);
        }
        Result result = new Result(process.exitValue(), java.nio.file.Files.readString(out, StandardCharsets.UTF_8),
                java.nio.file.Files.readString(err, StandardCharsets.UTF_8));
        java.nio.file.Files.delete(out);
        java.nio.file.Files.delete(err);
        return result;
    }

    /** {@code java [jvmOptions] -jar rsaml.jar args...} */
    static List<String> java(List<String> jvmOptions, String... args) {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(jvmOptions);
        command.add("-jar");
        command.add(JAR.toString());
        command.addAll(List.of(args));
        return command;
    }
}
