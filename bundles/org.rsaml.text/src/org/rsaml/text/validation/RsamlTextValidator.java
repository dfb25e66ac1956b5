/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.validation;

import org.eclipse.xtext.validation.EValidatorRegistrar;

/**
 * Checks of the text itself. There are none: a textual model is judged by RsaML's rules, as an XMI
 * one is, through the validator registered for the RsaML package (org.rsaml.validation).
 *
 * <p>Xtext makes this validator when the language's injector is made and would register it for the
 * RsaML package, beside RsaML's validator (in a composite) or, before org.rsaml.validation is active,
 * alone: the package would have a second validator, or one that judges nothing. It registers nothing.
 */
public class RsamlTextValidator extends AbstractRsamlTextValidator {

    @Override
    public void register(EValidatorRegistrar registrar) {
        // The RsaML package has one validator, org.rsaml.validation's RuleEValidator.
    }
}
