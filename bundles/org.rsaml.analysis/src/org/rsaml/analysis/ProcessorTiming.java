/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.List;

import org.rsaml.model.Processor;

/**
 * The schedulability of one processor of an architecture.
 *
 * @param name    the processor's name ("default" for the modules no processor names)
 * @param element the model's processor, or null for the default one
 * @param result  the verdict per task and for the processor
 * @param sources per task of {@code result}, in the same order, what it comes from
 * @param notes   what the verdict assumes about the platform
 */
public record ProcessorTiming(String name, Processor element, ProcessorResult result, List<TaskSource> sources, List<String> notes) {

    public ProcessorTiming {
        sources = List.copyOf(sources);
        notes = List.copyOf(notes);
    }
}
