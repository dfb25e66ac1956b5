/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.spi;

import java.util.Map;
import java.util.Optional;

/** What a target may read of the output it generates into, from earlier runs. */
public interface OutputContext {

    /**
     * What this target asked to keep ({@link GeneratedProject#keep()}) when it last generated into
     * the same output, checked to be plain names; empty the first time.
     */
    Map<String, String> kept();

    /**
     * The text of a file of the architect's in the output (UTF-8), for files the generated ones
     * merge in; empty when there is none, or it is a link, outside the output, or over 1 MiB.
     *
     * @param path relative to the output directory, {@code /} separated
     */
    Optional<String> userFile(String path);

    /** An output that does not exist yet. */
    OutputContext EMPTY = new OutputContext() {
        @Override
        public Map<String, String> kept() {
            return Map.of();
        }

        @Override
        public Optional<String> userFile(String path) {
            return Optional.empty();
        }
    };
}
