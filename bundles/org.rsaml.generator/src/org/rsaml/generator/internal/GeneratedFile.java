/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal;

/**
 * One file of a generated project.
 *
 * @param path      relative to the output directory, with {@code /} separators, built only from
 *                  sanitised names
 * @param content   the file's text (UTF-8, {@code \n} line ends)
 * @param userOwned whether the architect owns the file: written only when it does not exist yet
 *                  (generation gap); otherwise it is regenerated on every run
 * @param hooks     for a user-owned module class, the methods the generated code calls and the
 *                  architect may implement (to tell them later which the model no longer calls)
 * @param stubs     the subset of hooks the class is created with (to tell them which are new)
 */
public record GeneratedFile(String path, String content, boolean userOwned, java.util.List<String> hooks,
        java.util.List<String> stubs) {

    public static GeneratedFile generated(String path, CharSequence content) {
        return new GeneratedFile(path, content.toString(), false, java.util.List.of(), java.util.List.of());
    }

    public static GeneratedFile user(String path, CharSequence content) {
        return new GeneratedFile(path, content.toString(), true, java.util.List.of(), java.util.List.of());
    }

    public static GeneratedFile user(String path, CharSequence content, java.util.List<String> hooks, java.util.List<String> stubs) {
        return new GeneratedFile(path, content.toString(), true, java.util.List.copyOf(hooks), java.util.List.copyOf(stubs));
    }
}
