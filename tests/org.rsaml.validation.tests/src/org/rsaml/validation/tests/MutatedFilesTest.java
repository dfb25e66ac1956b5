/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rsaml.model.resource.SourceLocation;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.ModelLoadException;
import org.rsaml.validation.ModelLoader;

/**
 * Loading damaged and hostile variants of the examples (a fixed seed): whatever the bytes, the
 * loader either reads the model or says in one sentence, with a place inside the file, why not;
 * no other exception, no Java exception text, no absolute path, every element placed inside the file.
 */
class MutatedFilesTest {

    private static final long SEED = 20261124L;
    private static final int MUTATIONS = 300;

    private static final String[] VALUES = { "NaN", "Infinity", "-Infinity", "1e999", "", " ", "-1", "50ms", "0x10", "\u00e9\u20ac",
            "http://127.0.0.1:1/x.rsaml#//@sensors.0", "../x.rsaml#//@sensors.0", "/etc/passwd#//", "other.rsaml#//@sensors.0",
            "//@layers.99", "//@layers[name='nope']", "//@layers.0", "#", "//", "weekly", "rsaml:Nothing", "&#0;", "&amp;", "<", "\"" };

    @TempDir
    Path dir;

    @Test
    void everyMutationLoadsOrIsOneLocatedSentence() throws Exception {
        List<byte[]> examples = new ArrayList<>();
        try (Stream<Path> files = Files.list(TestRepository.root().resolve("examples"))) {
            for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".rsaml")).sorted()::iterator) {
                examples.add(Files.readAllBytes(f));
            }
        }
        assertFalse(examples.isEmpty(), "there are example models to mutate");
        Random random = new Random(SEED);
        List<String> broken = new ArrayList<>();
        for (int i = 0; i < MUTATIONS; i++) {
            byte[] original = examples.get(random.nextInt(examples.size()));
            int kind = random.nextInt(12);
            byte[] bytes = mutate(original, kind, random);
            String name = "mutant-" + i + ".rsaml";
            Path file = dir.resolve(name);
            Files.write(file, bytes);
            String problem = check(file, name, bytes);
            if (problem != null) {
                broken.add("mutation " + i + " (kind " + kind + "): " + problem);
            }
        }
        if (!broken.isEmpty()) {
            fail(broken.size() + " of " + MUTATIONS + " mutations misbehaved:\n" + String.join("\n", broken.subList(0, Math.min(20, broken.size()))));
        }
    }

    /** What is wrong with how the file was loaded, or null. */
    private String check(Path file, String name, byte[] bytes) {
        int lines = lineBreaks(bytes) + 1;
        try {
            LoadedModel model = ModelLoader.load(file, name);
            for (Iterator<EObject> it = model.resource().getAllContents(); it.hasNext();) {
                SourceLocation at = model.location(it.next());
                if (at.line() < 1 || at.line() > lines || at.column() < 1) {
                    return "element placed at " + at + " in a file of " + lines + " lines";
                }
            }
            return null;
        } catch (ModelLoadException e) {
            String message = e.getMessage();
            if (message == null || message.isBlank() || message.contains("\n") || message.contains("\r")) {
                return "not one sentence: " + e;
            }
            if (message.contains("Exception") || message.contains("java.") || message.contains("org.eclipse")) {
                return "Java exception text: " + e;
            }
            if (message.contains(dir.toString())) {
                return "absolute path: " + e;
            }
            if (message.contains("null")) {
                return "garbled: " + e;
            }
            if (e.line() == 0 && !message.startsWith("the file is binary") && !message.startsWith("the file is empty")
                    && !message.startsWith("the file ends before its root element")) {
                return "no line, although the parser knows one: " + e;
            }
            if (!e.toString().startsWith(name + ":") || e.line() > lines || e.line() < 0 || e.column() < 0) {
                return "placed outside the file (" + lines + " lines): " + e;
            }
            return null;
        } catch (RuntimeException | Error e) {
            return "escaped: " + e;
        }
    }

    /** Line breaks as an XML 1.1 parser counts them at most: CR LF, CR, LF and NEL each end a line. */
    private static int lineBreaks(byte[] bytes) {
        String text = new String(bytes, StandardCharsets.ISO_8859_1);
        int n = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\n' || c == '\u0085' || c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n')) {
                n++;
            }
        }
        return n;
    }

    static byte[] mutate(byte[] original, int kind, Random random) {
        String text = new String(original, StandardCharsets.UTF_8);
        int at = random.nextInt(original.length);
        switch (kind) {
            case 0: // truncated
                return java.util.Arrays.copyOf(original, at);
            case 1: { // a byte flipped
                byte[] b = original.clone();
                b[at] = (byte) random.nextInt(256);
                return b;
            }
            case 2: { // a range deleted
                int end = Math.min(original.length, at + 1 + random.nextInt(200));
                byte[] b = new byte[original.length - (end - at)];
                System.arraycopy(original, 0, b, 0, at);
                System.arraycopy(original, end, b, at, original.length - end);
                return b;
            }
            case 3: { // a line duplicated
                List<String> lines = new ArrayList<>(List.of(text.split("\n", -1)));
                int l = random.nextInt(lines.size());
                lines.add(l, lines.get(l));
                return String.join("\n", lines).getBytes(StandardCharsets.UTF_8);
            }
            case 4: { // two lines swapped
                List<String> lines = new ArrayList<>(List.of(text.split("\n", -1)));
                java.util.Collections.swap(lines, random.nextInt(lines.size()), random.nextInt(lines.size()));
                return String.join("\n", lines).getBytes(StandardCharsets.UTF_8);
            }
            case 5, 6: { // an attribute value replaced by a hostile one
                List<int[]> values = new ArrayList<>();
                for (int q = text.indexOf("=\""); q >= 0; q = text.indexOf("=\"", q + 1)) {
                    int end = text.indexOf('"', q + 2);
                    if (end > 0) {
                        values.add(new int[] { q + 2, end });
                    }
                }
                int[] v = values.get(random.nextInt(values.size()));
                String value = VALUES[random.nextInt(VALUES.length)];
                return (text.substring(0, v[0]) + value + text.substring(v[1])).getBytes(StandardCharsets.UTF_8);
            }
            case 7: { // other line ends
                String[] ends = { "\r", "\r\n", "\u0085" };
                String end = ends[random.nextInt(ends.length)];
                String changed = text.replace("\n", end);
                if (end.equals("\u0085")) {
                    changed = changed.replace("version=\"1.0\"", "version=\"1.1\"");
                }
                return changed.getBytes(StandardCharsets.UTF_8);
            }
            case 8: // a byte-order mark, or UTF-16
                return random.nextBoolean() ? ("\uFEFF" + text).getBytes(StandardCharsets.UTF_8)
                        : ("\uFEFF" + text.replace("UTF-8", "UTF-16")).getBytes(random.nextBoolean() ? StandardCharsets.UTF_16LE : StandardCharsets.UTF_16BE);
            case 9: { // a DOCTYPE or an entity
                int root = text.indexOf("<rsaml:");
                return (text.substring(0, root) + "<!DOCTYPE r [<!ENTITY e SYSTEM \"file:///etc/passwd\">]>\n" + text.substring(root).replaceFirst("name=\"", "name=\"&e;"))
                        .getBytes(StandardCharsets.UTF_8);
            }
            case 10: { // a control character or a raw non-ASCII byte
                byte[] b = new byte[original.length + 1];
                System.arraycopy(original, 0, b, 0, at);
                b[at] = (byte) (random.nextBoolean() ? random.nextInt(32) : 0x80 + random.nextInt(128));
                System.arraycopy(original, at, b, at + 1, original.length - at);
                return b;
            }
            default: { // an element repeated in place (its start tag)
                int lt = text.indexOf('<', at % text.length());
                int gt = lt < 0 ? -1 : text.indexOf('>', lt);
                if (gt < 0) {
                    return original;
                }
                return (text.substring(0, gt + 1) + text.substring(lt, gt + 1) + text.substring(gt + 1)).getBytes(StandardCharsets.UTF_8);
            }
        }
    }
}
