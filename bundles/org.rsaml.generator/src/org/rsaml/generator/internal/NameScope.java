/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.util.HashSet;
import java.util.Locale;
import java.util.Set;

/**
 * The names taken in one scope (a namespace, a class, a folder). Names are handed out in model
 * order, so the first element keeps its sanitised name and a later one that collides with it
 * gets the first free suffix {@code _2}, {@code _3}, ...: the same model always gives the same
 * names. Folder and file scopes compare without case, for case-insensitive file systems.
 */
public final class NameScope {

    private final Set<String> taken = new HashSet<>();
    private final boolean ignoreCase;

    public NameScope(boolean ignoreCase, String... reserved) {
        this.ignoreCase = ignoreCase;
        for (String r : reserved) {
            taken.add(key(r));
        }
    }

    /** Takes {@code preferred}, or the first free {@code preferred_N}. */
    public String allocate(String preferred) {
        return allocate(preferred, "");
    }

    /**
     * Takes a name {@code n} such that {@code prefix + n + suffix} is free for every given
     * pair, and reserves all of them: for a port that becomes {@code in_x} and {@code on_x}, or a
     * class {@code X} that also needs {@code XBase}.
     *
     * @param affixes alternating prefix and suffix strings; {@code ""} for none
     */
    public String allocate(String preferred, String... affixes) {
        String[] pairs = affixes.length == 0 || (affixes.length == 1 && affixes[0].isEmpty()) ? new String[] { "", "" } : affixes;
        if (pairs.length % 2 != 0) {
            pairs = java.util.Arrays.copyOf(pairs, pairs.length + 1);
            pairs[pairs.length - 1] = "";
        }
        for (int n = 1;; n++) {
            String candidate = n == 1 ? preferred : preferred + "_" + n;
            boolean free = true;
            for (int i = 0; i < pairs.length && free; i += 2) {
                free = !taken.contains(key(pairs[i] + candidate + pairs[i + 1]));
            }
            if (free) {
                for (int i = 0; i < pairs.length; i += 2) {
                    taken.add(key(pairs[i] + candidate + pairs[i + 1]));
                }
                return candidate;
            }
        }
    }

    public boolean isTaken(String name) {
        return taken.contains(key(name));
    }

    private String key(String name) {
        return ignoreCase ? name.toLowerCase(Locale.ROOT) : name;
    }
}
