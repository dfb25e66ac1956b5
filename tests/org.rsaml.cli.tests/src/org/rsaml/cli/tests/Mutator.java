/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.BiFunction;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Seeded mutations of a well-formed model: what a hand edit, a bad merge, a broken tool or an
 * attacker makes of a {@code .rsaml} file. Mutation {@code i} of a run depends on the seed and
 * {@code i} only, so any failure is reproduced by its seed and index.
 */
final class Mutator {

    /** A mutated file: the bytes and what was done, for the failure message. */
    record Mutant(String name, byte[] bytes) {
    }

    private static final Pattern ATTRIBUTE = Pattern.compile(" ([A-Za-z:]+)=\"([^\"]*)\"");
    private static final Pattern NUMBER_ATTRIBUTE = Pattern.compile(
            " (period|delay|execDuration|maxExecTime|level|declaredLayers|startDate|duration)=\"([^\"]*)\"");
    private static final Pattern ENUM_ATTRIBUTE = Pattern.compile(
            " (execType|type|schedPolicy|category|dataType|synchroType|timeUnit|kind)=\"([^\"]*)\"");
    private static final Pattern NAME_ATTRIBUTE = Pattern.compile(" name=\"([^\"]*)\"");
    private static final Pattern REFERENCE = Pattern.compile(
            " (source|target|trigger|sensors|actuators|usedBy|achieves|plans|actions|realisedBy|receiver|requests)=\"([^\"]*)\"");
    private static final Pattern ELEMENT_LINE = Pattern.compile("(?m)^[ \\t]*<[a-zA-Z][^\\n]*/>[ \\t]*\\r?\\n");

    private static final String[] NUMBERS = { "NaN", "Infinity", "-Infinity", "1e21", "1e308", "1.8e308", "-0", "0", "-1",
            "4.9e-324", "1e-400", "99999999999999999999999", "2147483648", "-2147483649", "0x10", "1,5", "50ms", " 5 ", "",
            "+3", "3.", ".5", "1e", "--1", "\u0665", "5&#10;" };
    private static final String[] ENUMS = { "bogus", "PERIODIC", "Periodic", "", " periodic", "periodic ", "0", "99",
            "realTime&#10;", "ms ", "h", "minutes" };
    private static final String[] NAMES = { "", " ", "\u6a21\u5757", "caf\u00e9", "e\u0301", "\ud83e\udd16robot",
            "\u202eevil", "a\u200bb", "a/b", "..", "CON", "class", "a b", "&#10;x", "x&#13;y", "x&#133;y", "x&#9;y",
            "::error file=a::b", "&lt;tag&gt;", "&amp;", "'quoted'", "x&#x2028;y", "\u0000", "%s%n" };
    private static final String[] REFERENCES = { "//@layers[name='nowhere']", "//@layers.99", "#//@layers.0",
            "//@missions.0", "//@layers.0", "//@layers.0/@modules.0", "other.rsaml#//@layers.0",
            "http://127.0.0.1:9/x.rsaml#//@layers.0", "jar:file:/nowhere.jar!/x.rsaml#//@layers.0", "", " ",
            "//@layers[name='a']/@modules[name='b'] //@layers.0", "//@", "//@layers[name=']" };
    private static final String[] PROLOGUES = {
            "<!DOCTYPE a [<!ENTITY e \"entity\">]>\n",
            "<!DOCTYPE a SYSTEM \"file:///etc/passwd\">\n",
            "<!DOCTYPE a [<!ENTITY x SYSTEM \"file:///etc/hostname\">]>\n",
            "<!DOCTYPE a [<!ENTITY % p SYSTEM \"http://127.0.0.1:9/p.dtd\"> %p;]>\n",
            "<!DOCTYPE a [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;\"><!ENTITY c \"&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;\">]>\n",
            "<!DOCTYPE a PUBLIC \"-//X//Y\" \"http://127.0.0.1:9/x.dtd\">\n",
            "<?xml-stylesheet href=\"http://127.0.0.1:9/s.xsl\"?>\n",
            "<!-- a comment before the root -->\n" };

    private final List<BiFunction<Random, byte[], Mutant>> mutations = List.of(
            this::truncate, this::flipBytes, this::deleteElement, this::duplicateElement, this::swapLines,
            this::deleteAttribute, this::duplicateAttribute, this::reorderAttributes, this::number, this::enumLiteral,
            this::empty, this::hugeName, this::name, this::reference, this::lineEndings, this::encoding, this::prologue,
            this::entityUse, this::combine);

    /** Mutation number {@code index} of the run seeded with {@code seed}, applied to one of {@code originals}. */
    Mutant mutate(long seed, int index, List<byte[]> originals, List<String> originalNames) {
        Random random = new Random(seed * 1_000_003L + index);
        int which = random.nextInt(originals.size());
        int kind = random.nextInt(mutations.size());
        Mutant m = mutations.get(kind).apply(random, originals.get(which));
        return new Mutant(originalNames.get(which).replace(".rsaml", "") + "-" + m.name(), m.bytes());
    }

    private static String text(byte[] bytes) {
        return new String(bytes, StandardCharsets.UTF_8);
    }

    private static Mutant of(String name, String text) {
        return new Mutant(name, text.getBytes(StandardCharsets.UTF_8));
    }

    /** A random match of {@code pattern}, or null. */
    private static Matcher pick(Random random, Pattern pattern, String text) {
        List<int[]> spans = new ArrayList<>();
        Matcher m = pattern.matcher(text);
        while (m.find()) {
            spans.add(new int[] { m.start(), m.end() });
        }
        if (spans.isEmpty()) {
            return null;
        }
        int[] span = spans.get(random.nextInt(spans.size()));
        Matcher chosen = pattern.matcher(text);
        chosen.find(span[0]);
        return chosen;
    }

    private static String replaceGroup(String text, Matcher m, int group, String value) {
        return text.substring(0, m.start(group)) + value + text.substring(m.end(group));
    }

    private static <T> T any(Random random, T[] values) {
        return values[random.nextInt(values.length)];
    }

    private Mutant truncate(Random random, byte[] original) {
        return new Mutant("truncated", Arrays.copyOf(original, random.nextInt(original.length)));
    }

    private Mutant flipBytes(Random random, byte[] original) {
        byte[] bytes = original.clone();
        int flips = 1 + random.nextInt(5);
        for (int i = 0; i < flips; i++) {
            int at = random.nextInt(bytes.length);
            bytes[at] ^= (byte) (1 << random.nextInt(8));
        }
        return new Mutant("flipped", bytes);
    }

    private Mutant deleteElement(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, ELEMENT_LINE, text);
        return m == null ? truncate(random, original) : of("element-deleted", text.substring(0, m.start()) + text.substring(m.end()));
    }

    private Mutant duplicateElement(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, ELEMENT_LINE, text);
        return m == null ? truncate(random, original) : of("element-duplicated", text.substring(0, m.end()) + m.group() + text.substring(m.end()));
    }

    private Mutant swapLines(Random random, byte[] original) {
        List<String> lines = new ArrayList<>(Arrays.asList(text(original).split("\n", -1)));
        int a = random.nextInt(lines.size());
        int b = random.nextInt(lines.size());
        String line = lines.get(a);
        lines.set(a, lines.get(b));
        lines.set(b, line);
        return of("lines-swapped", String.join("\n", lines));
    }

    private Mutant deleteAttribute(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, ATTRIBUTE, text);
        if (m == null) {
            return truncate(random, original);
        }
        return of("attribute-deleted", text.substring(0, m.start()) + text.substring(m.end()));
    }

    private Mutant duplicateAttribute(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, ATTRIBUTE, text);
        if (m == null) {
            return truncate(random, original);
        }
        return of("attribute-duplicated", text.substring(0, m.end()) + m.group() + text.substring(m.end()));
    }

    private Mutant reorderAttributes(Random random, byte[] original) {
        String text = text(original);
        Matcher tag = pick(random, Pattern.compile("<[a-zA-Z:]+((?: [A-Za-z:]+=\"[^\"]*\")+)"), text);
        if (tag == null) {
            return truncate(random, original);
        }
        List<String> attributes = new ArrayList<>();
        Matcher a = ATTRIBUTE.matcher(tag.group(1));
        while (a.find()) {
            attributes.add(a.group());
        }
        java.util.Collections.shuffle(attributes, random);
        return of("attributes-reordered", replaceGroup(text, tag, 1, String.join("", attributes)));
    }

    private Mutant number(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, NUMBER_ATTRIBUTE, text);
        return m == null ? truncate(random, original) : of("number-" + m.group(1), replaceGroup(text, m, 2, any(random, NUMBERS)));
    }

    private Mutant enumLiteral(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, ENUM_ATTRIBUTE, text);
        return m == null ? truncate(random, original) : of("enum-" + m.group(1), replaceGroup(text, m, 2, any(random, ENUMS)));
    }

    private Mutant empty(Random random, byte[] original) {
        String[] variants = { "", " ", "\n\n", "<?xml version=\"1.0\"?>", "\ufeff", "<", "<a/>", "\u0000\u0000" };
        return of("empty", any(random, variants));
    }

    private Mutant hugeName(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, NAME_ATTRIBUTE, text);
        if (m == null) {
            return truncate(random, original);
        }
        String huge = (random.nextBoolean() ? "x" : "\u00e9").repeat(1000 + random.nextInt(200_000));
        return of("huge-name", replaceGroup(text, m, 1, huge));
    }

    private Mutant name(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, NAME_ATTRIBUTE, text);
        if (m == null) {
            return truncate(random, original);
        }
        return of("name", replaceGroup(text, m, 1, any(random, NAMES)));
    }

    private Mutant reference(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, REFERENCE, text);
        if (m == null) {
            return truncate(random, original);
        }
        String value = random.nextInt(3) == 0
                ? m.group(2).replaceFirst("name='[^']*'", "name='" + any(random, NAMES).replace("'", "") + "'")
                : any(random, REFERENCES);
        return of("reference-" + m.group(1), replaceGroup(text, m, 2, value));
    }

    private Mutant lineEndings(Random random, byte[] original) {
        String text = text(original).replace("\r\n", "\n");
        return switch (random.nextInt(5)) {
            case 0 -> of("crlf", text.replace("\n", "\r\n"));
            case 1 -> of("cr", text.replace("\n", "\r"));
            case 2 -> {
                StringBuilder mixed = new StringBuilder();
                for (String line : text.split("\n", -1)) {
                    mixed.append(line).append(any(random, new String[] { "\n", "\r\n", "\r" }));
                }
                yield of("mixed-endings", mixed.toString());
            }
            case 3 -> of("nel-xml11", text.replaceFirst("version=\"1.0\"", "version=\"1.1\"").replace("\n", "\u0085"));
            default -> of("cr-in-attribute", text.replaceFirst("description=\"", "description=\"\r\r"));
        };
    }

    private Mutant encoding(Random random, byte[] original) {
        String text = text(original);
        return switch (random.nextInt(7)) {
            case 0 -> new Mutant("utf8-bom", concat(new byte[] { (byte) 0xEF, (byte) 0xBB, (byte) 0xBF }, original));
            case 1 -> new Mutant("utf16le-bom", concat(new byte[] { (byte) 0xFF, (byte) 0xFE },
                    text.replaceFirst("UTF-8", "UTF-16").getBytes(StandardCharsets.UTF_16LE)));
            case 2 -> new Mutant("utf16be", text.replaceFirst("UTF-8", "UTF-16").getBytes(StandardCharsets.UTF_16BE));
            case 3 -> new Mutant("latin1-declared", text.replaceFirst("UTF-8", "ISO-8859-1").replaceFirst("name=\"", "name=\"\u00e9\u00e8")
                    .getBytes(Charset.forName("ISO-8859-1")));
            case 4 -> of("unknown-encoding", text.replaceFirst("UTF-8", "x-bogus-" + random.nextInt(100)));
            case 5 -> of("utf16-declared-utf8-bytes", text.replaceFirst("UTF-8", "UTF-16"));
            default -> {
                // A multi-byte character straddling the 8 KiB boundary of naive readers.
                String padded = text.replaceFirst("description=\"", "description=\"" + "a".repeat(8100) + "\u00e9\u4e2d\ud83e\udd16");
                yield of("multibyte-at-8k", padded);
            }
        };
    }

    private Mutant prologue(Random random, byte[] original) {
        String text = text(original);
        int root = Math.max(0, text.indexOf("<rsaml:"));
        return of("prologue", text.substring(0, root) + any(random, PROLOGUES) + text.substring(root));
    }

    private Mutant entityUse(Random random, byte[] original) {
        String text = text(original);
        Matcher m = pick(random, NAME_ATTRIBUTE, text);
        if (m == null) {
            return truncate(random, original);
        }
        String withUse = replaceGroup(text, m, 1, any(random, new String[] { "&e;", "&x;", "&c;", "&undefined;", "&#0;", "&#xD800;", "&#x110000;" }));
        int rootAfter = withUse.indexOf("<rsaml:");
        return of("entity", rootAfter < 0 ? withUse : withUse.substring(0, rootAfter)
                + "<!DOCTYPE rsaml:Architecture [<!ENTITY e \"entity\"><!ENTITY x SYSTEM \"file:///etc/hostname\">"
                + "<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;\"><!ENTITY c \"&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;\">]>\n"
                + withUse.substring(rootAfter));
    }

    /** Two or three of the above, one after the other. */
    private Mutant combine(Random random, byte[] original) {
        byte[] bytes = original;
        StringBuilder name = new StringBuilder("combined");
        int steps = 2 + random.nextInt(2);
        for (int i = 0; i < steps; i++) {
            // Only mutations that keep the text decodable as UTF-8 for the next step.
            List<BiFunction<Random, byte[], Mutant>> textual = List.of(this::deleteElement, this::duplicateElement,
                    this::deleteAttribute, this::duplicateAttribute, this::reorderAttributes, this::number, this::enumLiteral,
                    this::name, this::reference);
            Mutant m = textual.get(random.nextInt(textual.size())).apply(random, bytes);
            bytes = m.bytes();
            name.append('+').append(m.name());
        }
        return new Mutant(name.toString(), bytes);
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] c = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }
}
