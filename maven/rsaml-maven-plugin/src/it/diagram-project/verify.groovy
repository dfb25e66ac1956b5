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
expected.each { assert log.contains("RsaML: wrote target/rsaml/diagrams/$it") }
def svg = javax.xml.parsers.DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new File(dir, 'exp2-defects-architecture.svg'))
assert svg.documentElement.tagName == 'svg'
// Every rule the model's <!-- expect: --> comments state decorates the HTML report.
def rules = (new File(basedir, 'model/exp2-defects.rsaml').text =~ /<!-- expect: (RSA-\d\d) /).collect { it[1] } as Set
assert !rules.isEmpty()
def html = new File(dir, 'exp2-defects-architecture.html').text
rules.each { assert html.contains("data-rule=\"$it\"") : "the report decorates an element with $it" }
// <timing>on</timing>: the architecture view shows the processors' utilisation, the mission view does not.
assert new File(dir, 'rover-architecture.svg').text.contains('processor default (preemptive fixed priority): utilisation ')
assert !new File(dir, 'rover-mission.svg').text.contains('utilisation ')
return true
