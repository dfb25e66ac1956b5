/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// The generate goal writes the C++ project before validation runs; the architect's files exist.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD SUCCESS')
assert log =~ /RsaML: generated cpp into rover-cpp: \d+ written, 0 unchanged, 0 of yours kept/
assert new File(basedir, 'rover-cpp/CMakeLists.txt').isFile()
assert new File(basedir, 'rover-cpp/gen').isDirectory()
assert log.indexOf('RsaML: generated cpp') < log.indexOf('RsaML: 1 file checked')
return true
