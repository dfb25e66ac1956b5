/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;
import org.rsaml.validation.RsamlValidationSetup;

/**
 * Loading figures on legal but hostile files, whose cost used to grow faster than their size:
 * deep nesting (sub-goals, unknown elements inside an extension) and many connections between
 * the same two ports. Each file is written as text and loaded with {@link ModelLoader}; the best
 * of three loads is printed with what loading said. Prints a Markdown table. Optional arguments:
 * the connection counts, the sub-goal depths and the extension depths, each comma-separated.
 */
public final class HostileInputsBench {

    static final String HEAD = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<rsaml:Architecture xmi:version=\"2.0\""
            + " xmlns:xmi=\"http://www.omg.org/XMI\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
            + " xmlns:rsaml=\"http://www.rsaml.org/rsaml/1.0\" name=\"hostile\" declaredLayers=\"1\">\n";
    static final String TAIL = "</rsaml:Architecture>\n";

    public static void main(String[] args) throws Exception {
        RsamlValidationSetup.registerPackage();
        Path dir = Files.createTempDirectory("rsaml-hostile");
        List<String> rows = new ArrayList<>();
        for (int n : sizes(args, 0, "10000,20000,40000,80000,160000,320000")) {
            rows.add(row(dir, "connections between the same two ports", n, sameTwoPorts(n)));
        }
        for (int n : sizes(args, 1, "100,500,998,999,50000,100000")) {
            rows.add(row(dir, "nested sub-goals", n, nestedGoals(n)));
        }
        for (int n : sizes(args, 2, "900,50000")) {
            rows.add(row(dir, "nested elements in an xmi:Extension", n, nestedExtension(n)));
        }
        Files.delete(dir);
        System.out.println();
        System.out.println("| input | n | file | load (best of 3) | result |");
        System.out.println("|---|---:|---:|---:|---|");
        rows.forEach(System.out::println);
    }

    /** The sizes given as argument {@code i} (comma-separated; empty for none), or the defaults. */
    static int[] sizes(String[] args, int i, String defaults) {
        String given = args.length > i ? args[i] : defaults;
        return given.isBlank() ? new int[0] : java.util.Arrays.stream(given.split(",")).mapToInt(s -> Integer.parseInt(s.trim())).toArray();
    }

    static String row(Path dir, String what, int n, String text) throws Exception {
        Path file = dir.resolve("hostile.rsaml");
        Files.writeString(file, text);
        long best = Long.MAX_VALUE;
        String result = "";
        for (int run = 0; run < 3; run++) {
            long t0 = System.nanoTime();
            try {
                LoadedModel model = ModelLoader.load(file, "hostile.rsaml");
                result = "loaded, " + model.elementCount() + " elements";
            } catch (ModelLoadException e) {
                result = "refused: " + e;
            }
            best = Math.min(best, System.nanoTime() - t0);
        }
        String line = String.format("| %s | %,d | %.1f MB | %,d ms | %s |", what, n, Files.size(file) / 1e6, best / 1_000_000, result);
        System.out.println(line);
        Files.delete(file);
        return line;
    }

    /** {@code n} connections from the one output port of m1 to the one entry port of m2. */
    static String sameTwoPorts(int n) {
        StringBuilder s = new StringBuilder(HEAD).append("  <layers name=\"a\">\n")
                .append("    <modules name=\"m1\"><ports xsi:type=\"rsaml:OutputPort\" name=\"o\"/></modules>\n")
                .append("    <modules name=\"m2\"><ports xsi:type=\"rsaml:EntryPort\" name=\"e\"/></modules>\n  </layers>\n");
        for (int i = 0; i < n; i++) {
            s.append("  <connections source=\"//@layers[name='a']/@modules[name='m1']/@ports[name='o']\"")
                    .append(" target=\"//@layers[name='a']/@modules[name='m2']/@ports[name='e']\"/>\n");
        }
        return s.append(TAIL).toString();
    }

    /** A mission whose goal has sub-goals {@code n} levels deep (the root and the mission add two). */
    static String nestedGoals(int n) {
        StringBuilder s = new StringBuilder(HEAD).append("  <missions name=\"m\">\n");
        for (int i = 0; i < n; i++) {
            s.append(i == 0 ? "<goals" : "<subGoals").append(" name=\"g").append(i).append("\">\n");
        }
        for (int i = n - 1; i >= 0; i--) {
            s.append(i == 0 ? "</goals>\n" : "</subGoals>\n");
        }
        return s.append("  </missions>\n").append(TAIL).toString();
    }

    /** Unknown elements nested {@code n} levels deep inside an extension, which EMF skips. */
    static String nestedExtension(int n) {
        return HEAD + "  <xmi:Extension extender=\"x\">" + "<a>".repeat(n) + "</a>".repeat(n) + "</xmi:Extension>\n" + TAIL;
    }
}
