/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// An error that leaves the model without a task set: no verdict, the error named, the build failed
// although failOnMiss is false; the reports are written and say the model could not be analysed.
def log = new File(basedir, 'build.log').text
assert log.contains("[ERROR] src/main/rsaml/lock.rsaml:9:5: error: the timing cannot be analysed: RSA-10: Module 'm' takes 12.0 ms but runs every 10.0 ms")
assert !log.contains('verdict:')
assert !log.contains('MISSES')
assert !log.contains('can be missed')
assert log.contains('RsaML timing: cannot read or analyse src/main/rsaml/lock.rsaml; see the errors above')
assert log.contains('BUILD FAILURE')
def sarif = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml-timing.sarif'))
assert sarif.runs[0].results.isEmpty()
assert sarif.runs[0].invocations[0].executionSuccessful == false
assert sarif.runs[0].invocations[0].toString().contains('the timing cannot be analysed: RSA-10')
def junit = new groovy.xml.XmlSlurper().parse(new File(basedir, 'target/rsaml/TEST-rsaml-timing.xml'))
assert junit.'**'.findAll { it.name() == 'failure' }.isEmpty()
def errors = junit.'**'.findAll { it.name() == 'error' }
assert errors.size() == 1
assert errors[0].@message.text().startsWith('the timing cannot be analysed: RSA-10')
return true
