/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.util.Arrays;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * A value a user writes for one of a fixed set of choices (a fail-on level, a report format, a diagram's view or
 * format, a timing mode), read the same way by every option and parameter: any case, surrounding blanks ignored,
 * and refused in one wording that names what was written and the choices there are.
 */
public final class Choices {

    private Choices() {
    }

    /**
     * The choice among {@code values} whose {@code label} is {@code text}.
     *
     * @param what what a choice is, for the refusal ({@code level}, {@code view})
     * @throws IllegalArgumentException {@code 'x' is not a WHAT; it is one of a, b, c} (also for {@code null})
     */
    public static <E> E parse(E[] values, Function<E, String> label, String what, String text) {
        String written = text == null ? "" : text.strip();
        for (E value : values) {
            if (label.apply(value).equalsIgnoreCase(written)) {
                return value;
            }
        }
        throw new IllegalArgumentException("'" + text + "' is not a " + what + "; it is one of "
                + Arrays.stream(values).map(label).collect(Collectors.joining(", ")));
    }
}
