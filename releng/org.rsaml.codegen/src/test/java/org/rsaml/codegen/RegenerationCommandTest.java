/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.codegen;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.charset.MalformedInputException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * The regeneration command is written once in code ({@link RsamlCodegen#REGENERATE}); the pages and comments
 * that tell a person to run it say exactly that command, so they cannot drift from it.
 */
class RegenerationCommandTest {

    /** The profile the command names (taken from it, so that this file does not name it). */
    private static final String PROFILE = RsamlCodegen.REGENERATE.split(" ")[1];
    private static final Set<String> SKIPPED = Set.of(".git", "target", "src-gen", "xtend-gen", "node_modules");
    /** Where a person or a program can be told the command: pages, sources, build files, scripts. */
    private static final Set<String> TEXTS = Set.of("md", "java", "xtend", "mwe2", "xml", "properties", "groovy", "sh", "txt", "mjs", "json");

    @Test
    void everyMentionOfTheCommandIsTheCommandAndCodeUsesTheConstant() throws IOException {
        Path root = GeneratedCodeUpToDateTest.ROOT;
        Path home = root.resolve("releng/org.rsaml.codegen/src/main/java/org/rsaml/codegen/RsamlCodegen.java");
        List<String> wrong = new ArrayList<>();
        List<String> telling = new ArrayList<>();
        for (Path file : files(root)) {
            String text;
            try {
                text = Files.readString(file, StandardCharsets.UTF_8);
            } catch (MalformedInputException e) {
                continue; // not text
            }
            if (!text.contains(PROFILE) && !text.replaceAll("\\s+", " ").contains(PROFILE)) {
                continue;
            }
            String shown = root.relativize(file).toString().replace('\\', '/');
            String name = file.getFileName().toString();
            if ((name.endsWith(".java") || name.endsWith(".xtend")) && !file.equals(home)) {
                wrong.add(shown + ": names the profile instead of using RsamlCodegen.REGENERATE");
                continue;
            }
            // a command broken over two lines of a page is still the command
            String flat = text.replaceAll("\\s*\\n\\s*", " ");
            int mentions = count(flat, PROFILE);
            int commands = count(flat, RsamlCodegen.REGENERATE);
            if (name.equals("pom.xml")) {
                continue; // the profile's definition
            }
            if (mentions != commands) {
                wrong.add(shown + ": " + (mentions - commands) + " of its " + mentions + " mentions of " + PROFILE + " are not " + RsamlCodegen.REGENERATE);
            } else if (!file.equals(home)) {
                telling.add(shown);
            }
        }
        assertEquals(List.of(), wrong, "the regeneration command written otherwise than RsamlCodegen.REGENERATE");
        assertTrue(telling.contains("README.md"), "README tells how to regenerate: " + telling);
    }

    /**
     * The command regenerates before it compiles anything the generated code is used by: this module needs nothing
     * of RsaML but the tests' support, and the reactor, which keeps the root pom's order where dependencies allow,
     * builds it before the first bundle. (.ci/regeneration-check runs the command with every src-gen/ deleted.)
     */
    @Test
    void theGeneratorIsBuiltBeforeAnyBundle() throws IOException {
        Path root = GeneratedCodeUpToDateTest.ROOT;
        String pom = Files.readString(root.resolve("releng/org.rsaml.codegen/pom.xml"), StandardCharsets.UTF_8);
        List<String> rsaml = new ArrayList<>();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("<groupId>org\\.rsaml</groupId>\\s*<artifactId>([^<]+)</artifactId>").matcher(pom);
        while (m.find()) {
            rsaml.add(m.group(1));
        }
        assertEquals(List.of("org.rsaml.parent", "org.rsaml.tests.support"), rsaml,
                "org.rsaml.codegen's parent and dependencies of RsaML (the tests' support requires nothing of RsaML)");
        List<String> modules = new ArrayList<>();
        java.util.regex.Matcher module = java.util.regex.Pattern.compile("<module>([^<]+)</module>")
                .matcher(Files.readString(root.resolve("pom.xml"), StandardCharsets.UTF_8));
        while (module.find()) {
            modules.add(module.group(1));
        }
        assertEquals("releng/org.rsaml.codegen", modules.get(0), "the root pom's first module: " + modules);
    }

    private static int count(String text, String part) {
        int n = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + part.length())) {
            n++;
        }
        return n;
    }

    private static List<Path> files(Path root) throws IOException {
        try (Stream<Path> walk = Files.walk(root)) {
            return walk.filter(p -> {
                for (Path part : root.relativize(p)) {
                    if (SKIPPED.contains(part.toString())) {
                        return false;
                    }
                }
                String name = p.getFileName().toString();
                return Files.isRegularFile(p) && (TEXTS.contains(name.substring(name.lastIndexOf('.') + 1)) || !name.contains("."));
            }).sorted().toList();
        }
    }
}
