/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A faulty model fails the build; the log names the rule, the file and the line; reports are still written.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log.contains("[ERROR] src/main/rsaml/rover.rsaml:8:5: error RSA-08: Module 'planner' takes 20.0 ms but layer 'decision' allows at most 2.0 ms")
assert log.contains('RsaML validation failed: 2 files checked: 1 error, 0 warnings (fail on error)')
def sarif = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml.sarif'))
def result = sarif.runs[0].results[0]
assert result.ruleId == 'RSA-08'
assert result.locations[0].physicalLocation.artifactLocation.uri == 'src/main/rsaml/rover.rsaml'
assert result.locations[0].physicalLocation.region.startLine == 8
def junit = new groovy.xml.XmlSlurper().parse(new File(basedir, 'target/rsaml/TEST-rsaml.xml'))
assert junit.@failures.text() == '1'
return true
