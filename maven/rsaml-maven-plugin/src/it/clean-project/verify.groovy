/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A clean project passes, reports are written, the excluded draft is not read.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD SUCCESS')
assert log.contains('RsaML: 1 file checked: 0 errors, 0 warnings; reports in target')
assert !log.contains('unfinished.rsaml')
def sarif = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml.sarif'))
assert sarif.version == '2.1.0'
assert sarif.runs[0].results.isEmpty()
// Every rule of the catalogue, in id order, and one JUnit test case per rule.
def catalogue = new Properties()
new File(basedir, '../../../../../bundles/org.rsaml.model/model/rules.properties').withReader('UTF-8') { catalogue.load(it) }
def ids = catalogue.stringPropertyNames().collect { it.substring(0, it.indexOf('.')) }.unique().sort()
assert sarif.runs[0].tool.driver.rules*.id == ids
def junit = new groovy.xml.XmlSlurper().parse(new File(basedir, 'target/rsaml/TEST-rsaml.xml'))
assert junit.@tests.text() == String.valueOf(ids.size())
assert junit.@failures.text() == '0'
return true
