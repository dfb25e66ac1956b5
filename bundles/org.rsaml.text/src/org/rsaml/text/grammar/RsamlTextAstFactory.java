/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.grammar;

import org.antlr.runtime.Token;
import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.conversion.ValueConverterException;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.parser.DefaultEcoreElementFactory;
import org.eclipse.xtext.parser.antlr.AntlrDatatypeRuleToken;

/**
 * Builds the model while parsing. A number or a value the parser could not read (it reported a syntax error
 * there, saying what is wrong) is left unset instead of becoming a second, internal error about a null value.
 */
public class RsamlTextAstFactory extends DefaultEcoreElementFactory {

    @Override
    public void set(EObject object, String feature, Object value, String ruleName, INode node) throws ValueConverterException {
        if (missing(value) && primitive(object.eClass().getEStructuralFeature(feature))) {
            return;
        }
        super.set(object, feature, value, ruleName, node);
    }

    private static boolean missing(Object value) {
        String text = value instanceof AntlrDatatypeRuleToken t ? t.getText() : value instanceof Token t ? t.getText()
                : value instanceof CharSequence c ? c.toString() : value == null ? null : "";
        return text == null || text.isEmpty();
    }

    private static boolean primitive(EStructuralFeature feature) {
        return feature instanceof EAttribute a && a.getEAttributeType().getInstanceClass() != null
                && a.getEAttributeType().getInstanceClass().isPrimitive();
    }
}
