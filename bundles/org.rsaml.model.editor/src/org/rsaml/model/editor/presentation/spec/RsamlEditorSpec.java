/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.presentation.spec;

import org.rsaml.model.edit.provider.spec.RsamlItemProviderAdapterFactorySpec;
import org.rsaml.model.editor.presentation.RsamlEditor;

/** The tree editor, with RsaML's labels ("Module resourceChecker — real-time, 2.5 ms") and the edit bundle's icons. */
public class RsamlEditorSpec extends RsamlEditor {

    /** The generated editor adds the generated item providers; RsaML's go in front of them. */
    @Override
    protected void initializeEditingDomain() {
        super.initializeEditingDomain();
        adapterFactory.insertAdapterFactory(new RsamlItemProviderAdapterFactorySpec());
    }
}
