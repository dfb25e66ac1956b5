/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.grammar;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.eclipse.xtext.linking.impl.XtextLinkingDiagnostic;

/** A reference that names nothing: which name, what kind of element it must name, how names are written. */
public class RsamlTextLinkingErrors extends LinkingDiagnosticMessageProvider {

    @Override
    public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
        EClass type = context.getReference().getEReferenceType();
        String kind = "NamedElement".equals(type.getName()) ? "element" : Constructs.words(type.getName());
        String message = "'" + context.getLinkText() + "' names no " + kind + " of this file: write the name of "
                + Constructs.article(kind.replace(' ', '_')).replace('_', ' ')
                + " declared in it, qualified by its containers where the name alone is ambiguous (module.port)";
        return new DiagnosticMessage(message, Severity.ERROR, XtextLinkingDiagnostic.LINKING_DIAGNOSTIC);
    }
}
