/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A latency requirement that can be missed fails the build; the log shows the verdict and the worst path.
// The validate goal reports the same verdict as a finding of RSA-23, located on the requirement.
def log = new File(basedir, 'build.log').text
assert log.contains("[ERROR] src/main/rsaml/base.rsaml:40:3: error RSA-23: Latency requirement 'scanToWheels' can be exceeded: the worst-case reaction time can reach 57 ms, more than 50 ms; worst path: navigation/obstacleDetector +44 ms -> control/velocityController +13 ms")
def sarif = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml.sarif'))
assert sarif.runs[0].results.any { it.ruleId == 'RSA-23' && it.level == 'error' }
assert log.contains('BUILD FAILURE')
assert log.contains("[ERROR]   verdict: MISSES: the worst-case reaction time can reach 57 ms, more than 50 ms")
assert log.contains("navigation/obstacleDetector: +44 ms (wait 40 ms + response 4 ms)")
assert log.contains('RsaML timing: a deadline or a latency requirement can be missed in src/main/rsaml/base.rsaml')
// The analyze goal's own reports: the timing rules' findings, through the same writers.
def timing = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml-timing.sarif'))
assert timing.runs[0].tool.driver.rules*.id == ['RSA-22', 'RSA-23', 'RSA-24', 'RSA-25']
assert timing.runs[0].results*.ruleId == ['RSA-23']
def junit = new groovy.xml.XmlSlurper().parse(new File(basedir, 'target/rsaml/TEST-rsaml-timing.xml'))
assert junit.'**'.findAll { it.name() == 'failure' }.size() == 1
// The witness as an SVG timeline: the worst path, a lane per stage, against the requirement.
def svg = new File(basedir, 'target/rsaml/timeline/mobileBaseSlowDetector-latency-scanToWheels.svg')
assert svg.isFile()
assert log.contains('RsaML: timeline written: target/rsaml/timeline/mobileBaseSlowDetector-latency-scanToWheels.svg')
def lanes = new groovy.xml.XmlSlurper().parse(svg).'**'.findAll { it.name() == 'rect' }*.title*.text()
assert lanes.any { it.startsWith('navigation/obstacleDetector: waits up to 40 ms') }
assert lanes.any { it == 'control/velocityController: responds within 3 ms' }
// The verdicts as JSON, the document rsaml analyze --format json prints: the missed requirement and its worst path.
def json = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/timing.json'))
assert json*.file == ['src/main/rsaml/base.rsaml']
assert json[0].verdict == 'misses'
def missed = json[0].latencies.find { it.requirement == 'scanToWheels' }
assert missed.verdict == 'misses' && missed.reactionTimeNs == 57000000 && missed.maxNs == 50000000
assert missed.worstPath*.stage == ['navigation/obstacleDetector', 'control/velocityController']
assert log.contains('RsaML: timing analysis written: target/rsaml/timing.json')
return true
