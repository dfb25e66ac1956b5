/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import java.util.List;

import org.rsaml.validation.Rule;

/**
 * The rule catalogue as the regeneration command wrote it in Java ({@code CompiledCatalog} in this bundle's
 * {@code src-gen/}, by releng/org.rsaml.docgen): the rules {@link RuleCatalog#parse} read from the catalogue file, and
 * that file's length and CRC-32. {@link RuleCatalog#load} finds the class by name, so that the bundle also compiles
 * while its generated code is being made again.
 */
interface CompiledRules {

    /** The length in bytes of the catalogue file the rules were read from. */
    int length();

    /** The CRC-32 of that file. */
    long crc();

    /** The rules in id order. */
    List<Rule> rules();
}
