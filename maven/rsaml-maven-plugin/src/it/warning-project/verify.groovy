/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// failOn=warning turns the RSA-11 warning into a failed build; every report format is written.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log.contains('[WARNING] src/main/rsaml/odometry.rsaml:5:5: warning RSA-11: ')
assert log.contains('(fail on warning)')
['rsaml.sarif', 'TEST-rsaml.xml', 'rsaml.json', 'rsaml.txt'].each {
    assert new File(basedir, "target/rsaml/$it").isFile() : "$it written"
}
assert new File(basedir, 'target/rsaml/rsaml.txt').text.contains('warning RSA-11')
return true
