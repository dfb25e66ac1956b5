/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cxx;

import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.rsaml.generator.spi.NameScanner;

/** C++ source as the targets that emit C++ read it back. */
public final class CxxCode {

    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

    private CxxCode() {
    }

    /** The identifiers of C++ text outside comments: a method named only in a comment is gone. */
    public static final NameScanner IDENTIFIERS = text -> {
        String code = text.replaceAll("(?s)/\\*.*?\\*/", " ").replaceAll("//[^\n]*", " ");
        Set<String> names = new TreeSet<>();
        Matcher m = IDENTIFIER.matcher(code);
        while (m.find()) {
            names.add(m.group());
        }
        return names;
    };
}
