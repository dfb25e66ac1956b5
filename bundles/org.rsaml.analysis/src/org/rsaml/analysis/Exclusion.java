/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import org.eclipse.emf.ecore.EObject;

/**
 * Work the generated runtime runs but the analysis cannot bound, and why.
 *
 * @param element   the module or function
 * @param label     {@code layer/module} or {@code layer/module.function}
 * @param processor where it runs
 * @param reason    why it is not analysed and what would make it analysable
 */
public record Exclusion(EObject element, String label, String processor, String reason) {
}
