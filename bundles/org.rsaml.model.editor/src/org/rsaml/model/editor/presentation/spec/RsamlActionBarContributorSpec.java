/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.editor.presentation.spec;

import org.rsaml.model.editor.presentation.RsamlActionBarContributor;

/** The editor's menus and tool bar, with a Validate action that checks RsaML's rules. */
public class RsamlActionBarContributorSpec extends RsamlActionBarContributor {

    public RsamlActionBarContributorSpec() {
        validateAction = new RsamlValidateAction();
    }
}
