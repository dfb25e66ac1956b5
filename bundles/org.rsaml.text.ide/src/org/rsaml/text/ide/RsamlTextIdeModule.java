/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.ide;

import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.rsaml.text.ide.server.RsamlTextHoverService;

/** Editor services of the textual syntax (completion, hover, ...) for the language server. */
public class RsamlTextIdeModule extends AbstractRsamlTextIdeModule {

    public Class<? extends IHoverService> bindIHoverService() {
        return RsamlTextHoverService.class;
    }
}
