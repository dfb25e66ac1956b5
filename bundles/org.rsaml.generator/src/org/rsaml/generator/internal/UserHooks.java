/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.rsaml.generator.spi.GeneratedFile;

/**
 * Compares the methods an architect's file defines with those the model now calls, so a renamed or removed element
 * never silently orphans their code and a new one is announced.
 */
final class UserHooks {

    private UserHooks() {
    }

    /**
     * @param text     the architect's file as it is
     * @param previous the methods the last run's generated code called in it, or null on a first run
     * @return one warning per kind of mismatch, naming the file and the methods
     */
    static List<String> check(GeneratedFile f, String text, List<String> previous) {
        List<String> warnings = new ArrayList<>();
        Set<String> present = f.scanner() == null ? Set.of() : f.scanner().namesIn(text);
        if (previous != null) {
            List<String> orphans = previous.stream().filter(h -> !f.hooks().contains(h) && present.contains(h)).toList();
            if (!orphans.isEmpty()) {
                warnings.add(f.path() + ": " + String.join(", ", orphans) + (orphans.size() == 1 ? " is" : " are")
                        + " no longer in the model, so the generated code does not call " + them(orphans)
                        + " any more; move the code to the renamed method or delete it");
            }
        }
        List<String> missing = f.stubs().stream().filter(h -> !present.contains(h)).toList();
        if (!missing.isEmpty()) {
            warnings.add(f.path() + ": new in the model: " + String.join(", ", missing)
                    + " (the generated base class runs a default; declare and define " + them(missing)
                    + " here to give " + them(missing) + " behaviour)");
        }
        return warnings;
    }

    private static String them(List<String> names) {
        return names.size() == 1 ? "it" : "them";
    }
}
