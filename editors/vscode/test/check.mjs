// SPDX-License-Identifier: EPL-2.0
// Checks the extension before and after packaging: the manifest associates .rsa with the language, its
// grammar and the language client; the highlighting names every word of RsamlText.xtext and no other;
// the packaged .vsix (given as argument) holds the manifest, the grammar, the client and its library.
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const here = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const fail = (message) => { console.error('check: ' + message); process.exit(1); };

const manifest = JSON.parse(readFileSync(path.join(here, 'package.json'), 'utf8'));
const language = (manifest.contributes.languages || []).find((l) => l.id === 'rsaml');
if (!language || !language.extensions.includes('.rsa')) fail('package.json does not associate .rsa with the rsaml language');
const grammar = (manifest.contributes.grammars || []).find((g) => g.language === 'rsaml');
if (!grammar) fail('package.json contributes no grammar for rsaml');
if (!manifest.main || !manifest.dependencies['vscode-languageclient']) fail('package.json has no language client');

const xtext = readFileSync(path.join(here, '../../bundles/org.rsaml.text/src/org/rsaml/text/RsamlText.xtext'), 'utf8')
  .replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/.*$/gm, '');
const terminals = xtext.indexOf('terminal ID');
const words = new Set([...xtext.slice(0, terminals).matchAll(/'([A-Za-z]+)'/g)].map((m) => m[1]));
const tm = readFileSync(path.join(here, grammar.path), 'utf8');
const highlighted = new Set([...tm.matchAll(/\\\\b\(\?:([A-Za-z|]+)\)\\\\b/g)].flatMap((m) => m[1].split('|')));
const missing = [...words].filter((w) => !highlighted.has(w));
const extra = [...highlighted].filter((w) => !words.has(w));
if (missing.length) fail('words of the grammar not highlighted: ' + missing.join(', '));
if (extra.length) fail('highlighted words that are not in the grammar: ' + extra.join(', '));

const vsix = process.argv[2];
if (vsix) {
  const listing = execFileSync('unzip', ['-l', vsix], { encoding: 'utf8' });
  for (const entry of ['extension/package.json', 'extension/extension.js', 'extension/syntaxes/rsaml.tmLanguage.json',
    'extension/node_modules/vscode-languageclient/package.json']) {
    if (!listing.includes(entry)) fail(vsix + ' lacks ' + entry);
  }
  const packed = JSON.parse(execFileSync('unzip', ['-p', vsix, 'extension/package.json'], { encoding: 'utf8' }));
  if (packed.version !== manifest.version || packed.name !== manifest.name) fail(vsix + ' holds another manifest');
}
console.log('check: ' + words.size + ' words highlighted' + (vsix ? ', ' + vsix + ' complete' : ''));
