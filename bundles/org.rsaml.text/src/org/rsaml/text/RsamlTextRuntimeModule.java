/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.parser.IAstFactory;
import org.eclipse.xtext.parser.IEncodingProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.service.DispatchingProvider;
import org.eclipse.xtext.validation.IResourceValidator;
import org.rsaml.text.conversion.RsamlTextValueConverters;
import org.rsaml.text.grammar.RsamlTextAstFactory;
import org.rsaml.text.grammar.RsamlTextLinkingErrors;
import org.rsaml.text.grammar.RsamlTextSyntaxErrors;
import org.rsaml.text.naming.RsamlTextQualifiedNameConverter;
import org.rsaml.text.naming.RsamlTextQualifiedNameProvider;
import org.rsaml.text.resource.RsamlTextResource;
import org.rsaml.text.validation.RsamlTextResourceValidator;

import com.google.inject.Binder;

/** The textual syntax's services: RsaML's resource, names, value conversion, syntax errors in the language's words, RsaML's rules as its validation; files are UTF-8 everywhere. */
public class RsamlTextRuntimeModule extends AbstractRsamlTextRuntimeModule {

    @Override
    public Class<? extends XtextResource> bindXtextResource() {
        return RsamlTextResource.class;
    }

    @Override
    public Class<? extends IValueConverterService> bindIValueConverterService() {
        return RsamlTextValueConverters.class;
    }

    @Override
    public Class<? extends IQualifiedNameProvider> bindIQualifiedNameProvider() {
        return RsamlTextQualifiedNameProvider.class;
    }

    public Class<? extends IQualifiedNameConverter> bindIQualifiedNameConverter() {
        return RsamlTextQualifiedNameConverter.class;
    }

    public Class<? extends IResourceValidator> bindIResourceValidator() {
        return RsamlTextResourceValidator.class;
    }

    public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
        return RsamlTextSyntaxErrors.class;
    }

    public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
        return RsamlTextLinkingErrors.class;
    }

    public Class<? extends IAstFactory> bindIAstFactory() {
        return RsamlTextAstFactory.class;
    }

    @Override
    public void configureRuntimeEncodingProvider(Binder binder) {
        binder.bind(IEncodingProvider.class).annotatedWith(DispatchingProvider.Runtime.class).toInstance(uri -> "UTF-8");
    }
}
