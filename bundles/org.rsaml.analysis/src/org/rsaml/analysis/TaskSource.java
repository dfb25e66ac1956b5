/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import org.eclipse.emf.ecore.EObject;

/**
 * A task of the analysis and the model element the generated runtime releases it for.
 *
 * @param task    the task as analysed
 * @param element the released function, action or module
 * @param kind    how the runtime releases it: "function", "action", "module" (timed releases on a
 *                real-time thread) or "reaction" (a sporadic module reacting on its worker thread)
 * @param note    what the derivation assumed for this task (e.g. action start dates counted as
 *                execution), or empty
 */
public record TaskSource(Task task, EObject element, String kind, String note) {
}
