/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// A clean project passes, reports are written with the usual permissions, the excluded draft is not read.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD SUCCESS')
assert log.contains('RsaML: 1 file checked: 0 errors, 0 warnings; reports in target')
assert !log.contains('unfinished.rsaml')
def sarif = new groovy.json.JsonSlurper().parse(new File(basedir, 'target/rsaml/rsaml.sarif'))
assert sarif.version == '2.1.0'
assert sarif.runs[0].results.isEmpty()
// Every rule of the catalogue, in id order, and one JUnit test case per rule.
def catalogue = new Properties()
new File(basedir, '../../../../../bundles/org.rsaml.validation/rules/rules.properties').withReader('UTF-8') { catalogue.load(it) }
def ids = catalogue.stringPropertyNames().collect { it.substring(0, it.indexOf('.')) }.unique().sort()
assert sarif.runs[0].tool.driver.rules*.id == ids
def junit = new groovy.xml.XmlSlurper().parse(new File(basedir, 'target/rsaml/TEST-rsaml.xml'))
assert junit.@tests.text() == String.valueOf(ids.size())
assert junit.@failures.text() == '0'

// The plugin's class realm, as Maven resolved it: the report library, not the command line (picocli).
def lines = log.readLines()
def first = lines.findIndexOf { it.contains('Populating class realm plugin>org.rsaml:rsaml-maven-plugin') }
assert first >= 0 : 'no class realm in the debug log'
def realm = lines.drop(first + 1).takeWhile { it.contains('Included: ') || it.contains('Excluded: ') }
def included = realm.findAll { it.contains('Included: ') }
assert included.any { it.contains('org.rsaml:org.rsaml.report:jar') }
assert included.any { it.contains('com.google.code.gson:gson:jar') }
assert !included.any { it.contains('picocli') } : included.findAll { it.contains('picocli') }
assert !included.any { it.contains('org.rsaml.cli') }

// Report files get what the umask gives any new file (not owner-only), as a compiler's output does.
def probe = new File(basedir, 'target/umask-probe')
probe.createNewFile()
def expected = java.nio.file.Files.getPosixFilePermissions(probe.toPath())
for (name in ['rsaml.sarif', 'TEST-rsaml.xml']) {
    def actual = java.nio.file.Files.getPosixFilePermissions(new File(basedir, 'target/rsaml/' + name).toPath())
    assert actual == expected : name + ': ' + actual + ', expected ' + expected
}
return true
