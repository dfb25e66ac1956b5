/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.spi;

import java.util.Set;

/**
 * The identifiers a file of the architect's really uses, in the file's own language (for C++:
 * outside comments). The file transaction uses it to tell which hooks a kept file implements.
 */
@FunctionalInterface
public interface NameScanner {
    Set<String> namesIn(String text);
}
