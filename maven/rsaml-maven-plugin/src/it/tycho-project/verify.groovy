/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// In a Tycho build (eclipse-plugin packaging) the plugin runs in verify and fails on the faulty model.
def log = new File(basedir, 'build.log').text
assert log.contains('[ eclipse-plugin ]')
assert log.contains('--- tycho-compiler:')
assert log.contains("[ERROR] model/rover.rsaml:8:5: error RSA-08: Module 'planner' takes 20.0 ms but layer 'decision' allows at most 2.0 ms")
assert log.contains('RsaML validation failed: 1 file checked: 1 error, 0 warnings (fail on error)')
assert new File(basedir, 'target/rsaml/rsaml.sarif').isFile()
return true
