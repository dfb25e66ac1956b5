/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.spi;

import java.util.List;

/**
 * One file of a generated project.
 *
 * @param path      relative to the output directory, with {@code /} separators, built only from
 *                  sanitised names
 * @param content   the file's text (UTF-8, {@code \n} line ends)
 * @param userOwned whether the architect owns the file: written only when it does not exist yet
 *                  (generation gap); otherwise it is regenerated on every run
 * @param hooks     for a user-owned class, the methods the generated code calls and the architect
 *                  may implement (to tell them later which the model no longer calls)
 * @param stubs     the subset of hooks the class is created with (to tell them which are new)
 * @param scanner   how to find the names an existing user-owned file uses (null without hooks)
 */
public record GeneratedFile(String path, String content, boolean userOwned, List<String> hooks, List<String> stubs,
        NameScanner scanner) {

    public GeneratedFile {
        hooks = List.copyOf(hooks);
        stubs = List.copyOf(stubs);
    }

    /** A file regenerated on every run. */
    public static GeneratedFile generated(String path, CharSequence content) {
        return new GeneratedFile(path, content.toString(), false, List.of(), List.of(), null);
    }

    /** A file of the architect's, created once. */
    public static GeneratedFile user(String path, CharSequence content) {
        return new GeneratedFile(path, content.toString(), true, List.of(), List.of(), null);
    }

    /** A class of the architect's, created once, whose methods are tracked across model changes. */
    public static GeneratedFile user(String path, CharSequence content, List<String> hooks, List<String> stubs, NameScanner scanner) {
        return new GeneratedFile(path, content.toString(), true, hooks, stubs, scanner);
    }
}
