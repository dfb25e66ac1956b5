/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Draws the repository's experiment 2 as it is, with the findings its <!-- expect: --> comments state.
new File(basedir, 'model/exp2-defects.rsaml').text = new File(rsamlRoot, 'examples/exp2-defects.rsaml').text
return true
