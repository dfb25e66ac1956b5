/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Every model in both views and both formats, under target/rsaml/diagrams, named after the model.
def log = new File(basedir, 'build.log').text
assert log.contains('BUILD SUCCESS')
def dir = new File(basedir, 'target/rsaml/diagrams')
def expected = ['exp2-defects', 'rover'].collectMany { m -> ['architecture', 'mission'].collectMany { v -> ['svg', 'html'].collect { f -> "$m-$v.$f" as String } } } as Set
assert dir.list() as Set == expected
expected.each { assert log.contains("RsaML: drew target/rsaml/diagrams/$it") }
def svg = javax.xml.parsers.DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new File(dir, 'exp2-defects-architecture.svg'))
assert svg.documentElement.tagName == 'svg'
assert new File(dir, 'exp2-defects-architecture.html').text.contains('data-rule="RSA-08"')
// <timing>on</timing>: the architecture view shows the processors' utilisation, the mission view does not.
assert new File(dir, 'rover-architecture.svg').text.contains('processor default (preemptive fixed priority): utilisation ')
assert !new File(dir, 'rover-mission.svg').text.contains('utilisation ')
return true
