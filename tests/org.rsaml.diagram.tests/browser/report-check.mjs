// SPDX-License-Identifier: EPL-2.0
// Opens an RsaML HTML report in the system's headless Chromium (puppeteer-core: no browser download),
// acts as a user would (clicks each finding, an element, the zoom buttons), saves screenshots and
// prints what it saw as one JSON document. The assertions are made by BrowserTest.java.
//
// node report-check.mjs REPORT.html OUTPUT_DIR CHROMIUM [ELEMENT_QNAME]
// node report-check.mjs --svg OUTPUT_DIR CHROMIUM FILE.svg...   renders each image as the browser's own
//   document: parse errors and the errors Chromium logs for invalid SVG (bad attribute values, ...) are
//   reported with the size drawn and a screenshot.
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import puppeteer from 'puppeteer-core';

const svgMode = process.argv[2] === '--svg';
const args = process.argv.slice(svgMode ? 3 : 2);
const report = svgMode ? null : args.shift();
const [outDir, executablePath, ...rest] = args;
const elementQname = rest[0];
const seen = { requests: [], errors: [], findings: [], clicks: [], images: [] };

const browser = await puppeteer.launch({
  executablePath,
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--hide-scrollbars'],
  defaultViewport: { width: 1600, height: 1000 },
});
try {
  if (svgMode) {
    for (const file of rest) {
      seen.images.push(await renderSvg(file));
    }
  } else {
    await checkReport();
  }
} finally {
  await browser.close();
}
process.stdout.write(JSON.stringify(svgMode ? { images: seen.images } : seen, null, 2) + '\n');

async function renderSvg(file) {
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') { errors.push(m.text()); } });
  await page.goto(pathToFileURL(file).href, { waitUntil: 'load' });
  const drawn = await page.evaluate(() => {
    const root = document.documentElement;
    const parseError = document.getElementsByTagName('parsererror').length > 0;
    const box = root.getBBox ? root.getBBox() : { width: 0, height: 0 };
    return { root: root.localName, parseError, width: box.width, height: box.height,
      elements: document.querySelectorAll('[data-qname]').length };
  });
  const name = file.split('/').pop().replace(/\.svg$/, '.png');
  const screenshot = join(outDir, name);
  const clip = await page.evaluate(() => {
    const r = document.documentElement.getBoundingClientRect();
    return { x: 0, y: 0, width: Math.max(1, Math.ceil(r.width)), height: Math.max(1, Math.ceil(r.height)) };
  });
  writeFileSync(screenshot, await page.screenshot({ type: 'png', clip, captureBeyondViewport: true }));
  await page.close();
  return { file, errors, ...drawn, screenshot };
}

async function checkReport() {
  const page = await browser.newPage();
  const url = pathToFileURL(report).href;
  page.on('request', (r) => { if (r.url() !== url) { seen.requests.push(r.url()); } });
  page.on('pageerror', (e) => seen.errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') { seen.errors.push(m.text()); } });
  await page.goto(url, { waitUntil: 'load' });

  const shot = async (name) => {
    const file = join(outDir, name);
    writeFileSync(file, await page.screenshot({ type: 'png' }));
    return file;
  };
  seen.summary = await page.$eval('#summary', (e) => e.textContent);
  seen.findings = await page.$$eval('#findings li', (items) => items.map((li) => ({
    rule: li.dataset.rule, qname: li.dataset.qname, severity: li.classList.contains('error') ? 'error' : 'warning',
  })));
  seen.screenshot = await shot('report.png');

  // The box of the element an item points at, in screen pixels, and whether it lies inside the diagram's area.
  const boxOf = (ids) => page.evaluate((ids) => {
    const svg = document.querySelector('#diagram > svg').getBoundingClientRect();
    const boxes = ids.map((id) => document.getElementById(id)).filter(Boolean).map((e) => e.getBoundingClientRect());
    if (boxes.length === 0) { return null; }
    const left = Math.min(...boxes.map((b) => b.left)), top = Math.min(...boxes.map((b) => b.top));
    const right = Math.max(...boxes.map((b) => b.right)), bottom = Math.max(...boxes.map((b) => b.bottom));
    return { width: right - left, height: bottom - top, view: [svg.width, svg.height],
      inside: left >= svg.left - 1 && top >= svg.top - 1 && right <= svg.right + 1 && bottom <= svg.bottom + 1 };
  }, ids);

  const items = await page.$$('#findings li');
  for (let i = 0; i < items.length; i++) {
    await page.click('#zoom-fit');
    const target = await page.evaluate((li) => li.dataset.target, items[i]);
    const before = await boxOf([target]);
    await items[i].click();
    const click = await page.evaluate(() => {
      const svg = document.querySelector('#diagram > svg').getBoundingClientRect();
      const lit = Array.from(document.querySelectorAll('#diagram .highlight'));
      const box = lit.length ? lit[0].getBoundingClientRect() : null;
      return {
        highlighted: lit.map((e) => e.dataset.qname),
        offset: box ? [box.left + box.width / 2 - (svg.left + svg.width / 2), box.top + box.height / 2 - (svg.top + svg.height / 2)] : null,
        details: (document.querySelector('#details .qname') || {}).textContent || '',
        visible: box ? box.width > 0 && box.height > 0 : false,
      };
    });
    click.before = before;
    click.after = await boxOf([target]);
    click.screenshot = await shot(`finding-${i + 1}-${seen.findings[i].rule}.png`);
    seen.clicks.push(click);
  }

  // What an overlay (the timing analysis) draws: its items, the elements styled as a latency path, and
  // what clicking each item highlights.
  await page.click('#zoom-fit');
  seen.overlay = await page.evaluate(() => {
    const svg = document.querySelector('#diagram > svg').getBoundingClientRect();
    return {
      sections: Array.from(document.querySelectorAll('aside h2')).map((h) => h.textContent),
      items: Array.from(document.querySelectorAll('.overlay-items li')).map((li) => ({
        text: li.querySelector('.text').textContent, style: li.className, targets: (li.dataset.targets || '').split(' ').filter(Boolean),
        shown: li.getBoundingClientRect().height > 0,
      })),
      path: Array.from(document.querySelectorAll('#diagram .latency-path')).map((g) => {
        const line = g.querySelector(':scope > .shape, :scope > path');
        const style = getComputedStyle(line);
        const b = g.getBoundingClientRect();
        return { qname: g.dataset.qname || '', kind: g.dataset.kind, stroke: style.stroke, width: style.strokeWidth, dash: style.strokeDasharray,
          visible: (b.width > 0 || b.height > 0) && b.left >= svg.left - 1 && b.right <= svg.right + 1 && b.top >= svg.top - 1 && b.bottom <= svg.bottom + 1 };
      }),
      texts: Array.from(document.querySelectorAll('#diagram text.overlay-misses, #diagram text.overlay-meets, #diagram text.overlay-unknown'))
        .map((t) => ({ text: t.textContent, fill: getComputedStyle(t).fill })),
      clicks: [],
    };
  });
  if (seen.overlay.items.length > 0) {
    seen.overlay.screenshot = await shot('overlay.png');
  }
  const overlayItems = await page.$$('.overlay-items li');
  for (let i = 0; i < overlayItems.length; i++) {
    await page.click('#zoom-fit');
    const targets = seen.overlay.items[i].targets;
    const before = await boxOf(targets);
    await overlayItems[i].click();
    const highlighted = await page.$$eval('#diagram .highlight', (els) => els.map((e) => e.dataset.qname));
    seen.overlay.clicks.push({ highlighted, before, after: await boxOf(targets), screenshot: await shot(`overlay-${i + 1}.png`) });
  }

  await page.click('#zoom-fit');
  if (elementQname) {
    await page.click(`#diagram g[data-qname="${elementQname}"] > text`);
    seen.element = await page.evaluate(() => ({
      details: document.querySelector('#details .qname').textContent,
      attributes: Object.fromEntries(Array.from(document.querySelectorAll('#details tr')).map((r) => [r.cells[0].textContent, r.cells[1].textContent])),
      findings: Array.from(document.querySelectorAll('#details .element-findings li')).map((li) => li.textContent),
      highlighted: Array.from(document.querySelectorAll('#diagram .highlight')).map((e) => e.dataset.qname),
    }));
  }

  const width = () => page.$eval('#diagram > svg', (s) => s.viewBox.baseVal.width);
  seen.zoom = { fit: await width() };
  await page.click('#zoom-in');
  seen.zoom.in = await width();
  await page.click('#zoom-out');
  await page.click('#zoom-out');
  seen.zoom.out = await width();
  const svgBox = await page.$eval('#diagram > svg', (s) => { const r = s.getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; });
  const before = await page.$eval('#diagram > svg', (s) => s.viewBox.baseVal.x);
  await page.mouse.move(svgBox[0] + svgBox[2] / 2, svgBox[1] + svgBox[3] / 2);
  await page.mouse.down();
  await page.mouse.move(svgBox[0] + svgBox[2] / 2 + 200, svgBox[1] + svgBox[3] / 2, { steps: 5 });
  await page.mouse.up();
  seen.pan = { before, after: await page.$eval('#diagram > svg', (s) => s.viewBox.baseVal.x) };
  await page.click('#zoom-fit');
  seen.overview = await shot('overview.png');
}
