/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SortedMap;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Pattern;

/**
 * The output directory's {@value #FILE}: which files the last run generated (so the next run removes those the model no
 * longer produces and recognises its own files), the architect's methods of each user file, and the settings a
 * target keeps between runs. An unreadable or foreign manifest reads as empty: it only costs the clean-up.
 *
 * @param target    the target that wrote it, or null
 * @param generated the files it regenerates
 * @param hooks     per user file, the methods the generated code calls
 * @param keep      settings the target keeps (names only)
 */
record GeneratedManifest(String target, SortedSet<String> generated, Map<String, List<String>> hooks,
        SortedMap<String, String> keep) {

    static final String FILE = ".rsaml-generated";
    static final long MAX_BYTES = 64L << 20;
    /** What a kept setting may be: a name, nothing a path or a line could be built from. */
    static final Pattern KEEP = Pattern.compile("[A-Za-z][A-Za-z0-9_.-]{0,200}");
    private static final String TITLE = "# " + OutputWriter.MARKER + " (target ";

    GeneratedManifest {
        generated = Collections.unmodifiableSortedSet(new TreeSet<>(generated));
        hooks = Collections.unmodifiableMap(new LinkedHashMap<>(hooks));
        keep = Collections.unmodifiableSortedMap(new TreeMap<>(keep));
    }

    static GeneratedManifest read(Path dir) {
        String target = null;
        Set<String> generated = new TreeSet<>();
        Map<String, List<String>> hooks = new LinkedHashMap<>();
        Map<String, String> keep = new TreeMap<>();
        Path p = dir.resolve(FILE);
        try {
            // Larger than any real manifest (which lists one project's files): not one of ours.
            if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS) && Files.size(p) <= MAX_BYTES) {
                for (String line : Files.readAllLines(p, StandardCharsets.UTF_8)) {
                    String[] parts = line.strip().split(" ");
                    if (parts.length >= 2 && parts[0].equals("generated")) {
                        generated.add(parts[1]);
                    } else if (parts.length == 3 && parts[0].equals("keep") && KEEP.matcher(parts[1]).matches()
                            && KEEP.matcher(parts[2]).matches()) {
                        keep.put(parts[1], parts[2]);
                    } else if (line.startsWith(TITLE)) {
                        target = line.substring(TITLE.length()).replaceAll("\\).*", "");
                    } else if (parts.length >= 2 && parts[0].equals("hooks")) {
                        hooks.put(parts[1], List.of(parts).subList(2, parts.length));
                    }
                }
            }
        } catch (IOException e) {
            return new GeneratedManifest(null, new TreeSet<>(), Map.of(), new TreeMap<>());
        }
        return new GeneratedManifest(target, new TreeSet<>(generated), hooks, new TreeMap<>(keep));
    }

    String render() {
        StringBuilder out = new StringBuilder();
        out.append(TITLE).append(target).append("): the files it regenerates and the methods of your classes. Do not edit.\n");
        for (String g : generated) {
            out.append("generated ").append(g).append('\n');
        }
        for (Map.Entry<String, String> k : keep.entrySet()) {
            out.append("keep ").append(k.getKey()).append(' ').append(k.getValue()).append('\n');
        }
        for (Map.Entry<String, List<String>> h : hooks.entrySet()) {
            out.append("hooks ").append(h.getKey());
            for (String name : h.getValue()) {
                out.append(' ').append(name);
            }
            out.append('\n');
        }
        return out.toString();
    }
}
