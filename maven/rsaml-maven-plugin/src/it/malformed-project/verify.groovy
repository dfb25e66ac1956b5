/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A model that cannot be read fails the build with the input error, located, and no stack trace.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD FAILURE')
assert log =~ /\[ERROR\] src\/main\/rsaml\/rover\.rsaml:5:\d+: error: malformed XML: /
assert log.contains('RsaML could not read 2 model files; see the errors above')
assert !log.contains('\tat org.rsaml')

// A model with a mistake on each of twelve lines: every one is in the log and in both reports, none summarised away.
def model = new File(basedir, 'src/main/rsaml/many-errors.rsaml').readLines()
def expected = (0..<model.size()).findAll { model[it].contains('<modules name="m') }.collect { it + 1 }
assert expected.size() == 12
def logged = (log =~ /\[ERROR\] src\/main\/rsaml\/many-errors\.rsaml:(\d+):\d+: error: .+/).collect { it[1] as int }
assert logged == expected
assert !log.contains('more error')
def sarif = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml.sarif'))
def notified = sarif.runs[0].invocations[0].toolExecutionNotifications
        .findAll { it.locations[0].physicalLocation.artifactLocation.uri.endsWith('many-errors.rsaml') }
        .collect { it.locations[0].physicalLocation.region.startLine }
assert notified == expected
def junit = new groovy.xml.XmlSlurper().parse(new File(basedir, 'target/rsaml/TEST-rsaml.xml'))
def error = junit.'**'.find { it.name() == 'testsuite' && it.@name.text().endsWith('many-errors.rsaml') }.testcase.error
assert error.text().readLines().collect { (it =~ /many-errors\.rsaml:(\d+):/)[0][1] as int } == expected
return true
