/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.validation;

/**
 * Checks of the text itself. There are none: a textual model is judged by RsaML's rules, as an XMI
 * one is, through the validator registered for the RsaML package (org.rsaml.validation).
 */
public class RsamlTextValidator extends AbstractRsamlTextValidator {
}
