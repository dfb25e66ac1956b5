/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// After the last run (-Drsaml.failOn=never -Drsaml.formats=json -Drsaml.reportDirectory=target/custom):
// the properties took effect although the snippet is in the POM, and the hostile name stayed on its line.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD SUCCESS')
assert new File(basedir, 'target/custom/rsaml.json').isFile()
assert !new File(basedir, 'target/rsaml').exists()
def json = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/custom/rsaml.json'))
assert json.summary.failOn == 'never'
assert json.files[0].findings.any { it.message.contains('planner\n::error file=pom.xml,line=1::forged') }
// In the log the name is one escaped line: no forged finding, no workflow command.
assert log.contains("Module 'planner\\n::error file=pom.xml,line=1::forged\\r\\x85' takes 20.0 ms")
assert !log.readLines().any { it.startsWith('::') || it.contains('] ::') }
return true
