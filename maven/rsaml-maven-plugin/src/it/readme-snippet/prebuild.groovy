/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
// Puts the first XML block of the README's "Maven plugin" section, unchanged, into this project's POM.
def readme = new File(rsamlRoot, 'README.md').text
def section = readme.substring(readme.indexOf('## Maven plugin'))
def start = section.indexOf('```xml\n') + '```xml\n'.length()
def snippet = section.substring(start, section.indexOf('```', start))
assert snippet.contains('<artifactId>rsaml-maven-plugin</artifactId>')
def pom = new File(basedir, 'pom.xml')
pom.text = pom.text.replace('<!-- README -->', snippet)
return true
