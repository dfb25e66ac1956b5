/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A model that cannot be read fails the build with the input error, located, and no stack trace.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log =~ /\[ERROR\] src\/main\/rsaml\/rover\.rsaml:5:\d+: error: malformed XML: /
assert log.contains('RsaML could not read 1 model file; see the errors above')
assert !log.contains('\tat org.rsaml')
return true
