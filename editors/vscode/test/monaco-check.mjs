// SPDX-License-Identifier: EPL-2.0
// The language server in a real editor: the Monaco editor (test/monaco/index.html) in the system's headless
// Chromium (puppeteer-core, no browser download) talks to `rsaml language-server`, which this script starts
// and relays over a WebSocket. It opens examples-text/exp2-defects.rsa and checks, as a user would see them:
// - the editor's markers are exactly `rsaml validate --format json`'s findings for that file (rule id,
//   severity, line, column, message), and the first one is drawn as a squiggle;
// - typing `connect m0` on a new line and asking for completion (Ctrl+Space) lists, in the suggestion
//   widget, every output port starting with `m0` that the file connects from;
// - asking for completion on an empty line of a module lists the keywords `input` and `output`.
// Needs rsaml.jar (cli/org.rsaml.cli/target, built before this module), Java and Chromium
// ($RSAML_CHROMIUM, or /usr/bin/chromium...): says in one line what is missing and fails.
import { existsSync, readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { spawn, spawnSync } from 'node:child_process';
import { fileURLToPath, pathToFileURL } from 'node:url';
import path from 'node:path';
import { WebSocketServer } from 'ws';
import puppeteer from 'puppeteer-core';

const here = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const root = path.resolve(here, '../..');
// A failed check says what the editor showed, in one message, and exits 1 (after closing the browser and the server).
const fail = (message) => { throw Object.assign(new Error(message), { check: true }); };
process.on('uncaughtException', (e) => {
  console.error('monaco-check: ' + (e.check ? e.message : e.stack || e));
  process.exit(1);
});
const started = Date.now();

const chromium = [process.env.RSAML_CHROMIUM, '/usr/bin/chromium', '/usr/bin/chromium-browser', '/usr/bin/google-chrome']
  .find((p) => p && existsSync(p));
if (!chromium) {
  console.error('monaco-check: Chromium is missing (install the Debian package chromium, or set RSAML_CHROMIUM)');
  process.exit(1);
}
const jar = path.join(root, 'cli/org.rsaml.cli/target/rsaml.jar');
if (!existsSync(jar)) {
  console.error('monaco-check: ' + jar + ' is missing (build it: ./mvnw -pl cli/org.rsaml.cli -am package -DskipTests)');
  process.exit(1);
}
const java = process.env.JAVA_HOME ? path.join(process.env.JAVA_HOME, 'bin/java') : 'java';
const modelFile = path.join(root, 'examples-text/exp2-defects.rsa');
const text = readFileSync(modelFile, 'utf8');

// What rsaml validate says of the file: the expected markers.
const validate = spawnSync(java, ['-jar', jar, 'validate', '--format', 'json', modelFile],
  { encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'] });
if (validate.status !== 0 && validate.status !== 1) fail('rsaml validate failed (exit ' + validate.status + ') on ' + modelFile);
const report = JSON.parse(validate.stdout);
const expected = report.files.flatMap((f) => f.findings)
  .map((f) => `${f.ruleId} ${f.severity} ${f.line}:${f.column} ${f.message}`).sort();
if (expected.length === 0) fail('rsaml validate finds nothing in ' + modelFile + ': the test would prove nothing');

// The page, Monaco's files, and the language server behind a WebSocket.
const monacoDir = path.join(here, 'node_modules/monaco-editor/min');
const types = { '.js': 'text/javascript', '.css': 'text/css', '.html': 'text/html', '.ttf': 'font/ttf', '.json': 'application/json' };
const http = createServer((req, res) => {
  const url = new URL(req.url, 'http://localhost');
  let file;
  if (url.pathname === '/') file = path.join(here, 'test/monaco/index.html');
  else if (url.pathname === '/file') {
    res.writeHead(200, { 'content-type': 'application/json' });
    res.end(JSON.stringify({ uri: pathToFileURL(modelFile).href, root: pathToFileURL(path.dirname(modelFile)).href, text }));
    return;
  } else if (url.pathname.startsWith('/vs/')) file = path.join(monacoDir, path.normalize(url.pathname));
  if (!file || !file.startsWith(here) || !existsSync(file)) { res.writeHead(404); res.end(); return; }
  res.writeHead(200, { 'content-type': types[path.extname(file)] || 'application/octet-stream' });
  res.end(readFileSync(file));
});
const servers = [];
const serverErrors = [];
const wss = new WebSocketServer({ server: http, path: '/lsp' });
wss.on('connection', (socket) => {
  const server = spawn(java, ['-jar', jar, 'language-server'], { stdio: ['pipe', 'pipe', 'pipe'] });
  servers.push(server);
  server.stderr.on('data', (d) => serverErrors.push(String(d)));
  let buffer = Buffer.alloc(0);
  server.stdout.on('data', (chunk) => {
    buffer = Buffer.concat([buffer, chunk]);
    for (;;) {
      const end = buffer.indexOf('\r\n\r\n');
      if (end < 0) return;
      const length = Number(/Content-Length: *(\d+)/i.exec(buffer.subarray(0, end).toString('ascii'))[1]);
      if (buffer.length < end + 4 + length) return;
      socket.send(buffer.subarray(end + 4, end + 4 + length).toString('utf8'));
      buffer = buffer.subarray(end + 4 + length);
    }
  });
  socket.on('message', (data) => {
    const body = Buffer.from(String(data), 'utf8');
    server.stdin.write('Content-Length: ' + body.length + '\r\n\r\n');
    server.stdin.write(body);
  });
  socket.on('close', () => server.kill());
  server.on('exit', () => socket.close());
});
await new Promise((resolve) => http.listen(0, '127.0.0.1', resolve));
const address = 'http://127.0.0.1:' + http.address().port + '/';

const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  defaultViewport: { width: 1200, height: 800 },
});
try {
  const page = await browser.newPage();
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  await page.goto(address, { waitUntil: 'load' });
  const state = () => page.evaluate(() => ({ errors: window.rsaml.errors, diagnostics: window.rsaml.diagnostics }));
  try {
    await page.waitForFunction(() => window.rsaml.errors.length > 0 || window.rsaml.diagnostics > 0, { timeout: 120000, polling: 200 });
  } catch (e) {
    fail('no diagnostics reached the editor within 120 s: ' + JSON.stringify(await state()) + ' ' + pageErrors + ' ' + serverErrors.join(''));
  }
  const first = await state();
  if (first.errors.length) fail('the page failed: ' + first.errors.join('; ') + ' ' + serverErrors.join(''));

  // The markers, as the editor holds them, against rsaml validate's findings.
  const markers = await page.evaluate(() => monaco.editor.getModelMarkers({ owner: 'rsaml' }).map((m) => ({
    code: m.code, severity: { 8: 'error', 4: 'warning', 2: 'info', 1: 'hint' }[m.severity],
    line: m.startLineNumber, column: m.startColumn, message: m.message })));
  const actual = markers.map((m) => `${m.code} ${m.severity} ${m.line}:${m.column} ${m.message}`).sort();
  if (JSON.stringify(actual) !== JSON.stringify(expected)) {
    fail('the editor\'s markers are not rsaml validate\'s findings\n  validate: ' + expected.join('\n            ')
      + '\n  editor:   ' + actual.join('\n            '));
  }
  // The first finding is drawn: a squiggle on its line (which is in view when the file opens).
  const topLine = Math.min(...markers.map((m) => m.line));
  const drawn = await page.evaluate((line) => {
    const editor = window.rsaml.editor;
    const top = editor.getTopForLineNumber(line) - editor.getScrollTop();
    return [...document.querySelectorAll('.view-overlays .squiggly-error')].map((el) => parseFloat(el.parentElement.style.top))
      .some((t) => Math.abs(t - top) < 1);
  }, topLine);
  await page.screenshot({ path: path.join(here, 'target/monaco-markers.png') }).catch(() => {});
  if (!drawn) fail('no error squiggle drawn on line ' + topLine + ', which has a marker (target/monaco-markers.png)');

  // Completion as a user asks for it: type on a new line before the architecture's closing brace, press Ctrl+Space.
  const suggestAt = async (line, typed) => {
    await page.evaluate((line) => {
      const editor = window.rsaml.editor;
      const model = editor.getModel();
      editor.setPosition({ lineNumber: line, column: model.getLineMaxColumn(line) });
      editor.revealLineInCenter(line);
      editor.focus();
    }, line);
    await page.keyboard.press('Enter');
    await page.keyboard.type(typed);
    const asked = await page.evaluate(() => window.rsaml.completions.length);
    await page.keyboard.down('Control');
    await page.keyboard.press('Space');
    await page.keyboard.up('Control');
    try {
      await page.waitForFunction((asked) => window.rsaml.completions.length > asked, { timeout: 60000, polling: 100 }, asked);
      await page.waitForSelector('.suggest-widget.visible .monaco-list-row', { timeout: 60000 });
    } catch (e) {
      fail('no suggestions shown after typing "' + typed + '" at line ' + (line + 1) + ': '
        + JSON.stringify(await page.evaluate(() => window.rsaml.completions)));
    }
    const shown = await page.$$eval('.suggest-widget.visible .monaco-list-row .label-name', (els) => els.map((e) => e.textContent));
    await page.screenshot({ path: path.join(here, 'target/monaco-completion-' + line + '.png') }).catch(() => {});
    await page.keyboard.press('Escape');
    return shown;
  };
  const lines = text.split('\n');
  const closing = lines.lastIndexOf('}') + 1; // 1-based line of the architecture's closing brace
  const sources = [...new Set([...text.matchAll(/^\s*connect\s+([\w.]+)\s*->/gm)].map((m) => m[1]).filter((s) => s.startsWith('m0')))];
  if (sources.length === 0) fail('the model connects from no port starting with m0: the test would prove nothing');
  const names = await suggestAt(closing - 1, '  connect m0');
  const missingNames = sources.filter((s) => !names.includes(s));
  if (missingNames.length) fail('completion after "connect m0" lacks ' + missingNames.join(', ') + '; shown: ' + names.join(', '));

  // Keywords: on an empty line inside the first module.
  const moduleLine = lines.findIndex((l) => /^\s*module\s+\w+\s*\{/.test(l)) + 1;
  const keywords = await suggestAt(moduleLine, '      ');
  const missingKeywords = ['input', 'output'].filter((k) => !keywords.includes(k));
  if (missingKeywords.length) fail('completion in a module lacks the keywords ' + missingKeywords.join(', ') + '; shown: ' + keywords.join(', '));

  console.log('monaco-check: ' + markers.length + ' markers equal to rsaml validate\'s findings, completion shows '
    + sources.join(', ') + ' and input, output (' + ((Date.now() - started) / 1000).toFixed(1) + ' s)');
} finally {
  await browser.close();
  for (const s of servers) s.kill();
  wss.close();
  http.close();
}
