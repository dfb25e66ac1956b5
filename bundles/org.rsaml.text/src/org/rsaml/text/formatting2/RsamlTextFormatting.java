/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.formatting2;

import java.util.List;

import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionAccess;
import org.eclipse.xtext.formatting2.regionaccess.ITextReplacement;
import org.eclipse.xtext.formatting2.regionaccess.TextRegionAccessBuilder;
import org.eclipse.xtext.resource.XtextResource;

import com.google.inject.Inject;
import com.google.inject.Provider;

/** The formatted text of a parsed textual model ({@link RsamlTextFormatter}), comments kept. */
public class RsamlTextFormatting {

    @Inject
    private Provider<TextRegionAccessBuilder> regionAccess;

    @Inject
    private Provider<FormatterRequest> requests;

    @Inject
    private IFormatter2 formatter;

    /** The whole text of the resource, formatted; the resource must have been read without syntax errors. */
    public String format(XtextResource resource) {
        ITextRegionAccess access = regionAccess.get().forNodeModel(resource).create();
        FormatterRequest request = requests.get();
        request.setTextRegionAccess(access);
        List<ITextReplacement> replacements = formatter.format(request);
        return access.getRewriter().renderToString(replacements);
    }
}
