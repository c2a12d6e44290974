// End-to-end test of the setup sheets and the bore-milling diagram (issue 13, parts 2 and 6):
// Playwright (playwright-core) drives Debian's headless Chromium against a live cutcalc; the
// printed sheets are Chromium's own PDF (page.pdf(), print media), read back with poppler's
// pdftotext (text) and pdftoppm (a PNG for people).
//
//   - bore diagram: after the calculation the bore-milling section shows the bore and two cutter
//     positions to scale (bore radius / cutter radius in SVG units = R / r, centre distance / bore
//     radius = (R - r) / R, within 1 %) for two input sets, and the magnified cusp labelled with
//     the Delta the API computed;
//   - "Print sheet" marks its section and calls window.print() (stubbed: the test prints with
//     page.pdf()); the PDF holds the section's inputs (label, value, unit), its shown results and
//     its diagram's labels, on one page, and nothing of the other sections, no navigation, no
//     buttons; for a program (entry, polygon, grooving, flat) the program's file name and header, not its body;
//     'afterprint' clears the mark;
//   - printing without "Print sheet" (Ctrl+P) gives every section, each on its own page(s);
//   - in Russian and in inches (lang=ru&units=inch) the bore and entry sheets say every word from
//     the Russian catalogue (none of the English one) and give the lengths in inches;
//   - at 375 px and 1280 px every "Print sheet" button is reached with Tab and used with Enter;
//   - on every page: no console error, page error, failed request, HTTP error or CSP violation.
//
// Environment: CUTCALC_URL (required), E2E_PAGE_URL, E2E_ARTIFACT_DIR, CHROMIUM_PATH, as in
// calculator.test.mjs; PDFTOTEXT, PDFTOPPM (default: from PATH).
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';

import { PAGE_SECTIONS, env, chromiumForThisFile, repo } from './browser.mjs';
import { API, ARTIFACT_DIR, PAGE_URL, QUIET_MS, TEST_MS, WAIT_MS, assertClean, settle } from './page_session.mjs';

const run = promisify(execFile);
const PDFTOTEXT = env('PDFTOTEXT', 'pdftotext');
const PDFTOPPM = env('PDFTOPPM', 'pdftoppm');
const BORE_PATH = '/v1/roughness/bore-milling';

// Each section's title, and text only that section prints (a label and a result heading).
const SECTIONS = [
  { id: 'entry', title: 'Entry length and main time', own: ['Entry width B', 'Workpiece exit'] },
  { id: 'speeds', title: 'Resultant cutting speeds', own: ['Tool radius R', 'Workpiece speed n'] },
  { id: 'groove', title: 'Groove-wall roughness', own: ['Theoretical roughness', 'Target Rz T'] },
  { id: 'bore', title: 'Bore milling roughness', own: ['Cusp between adjacent tooth paths', 'Bore radius R'] },
  { id: 'polygon', title: 'Polygon-hole G-code', own: ['Inscribed diameter d', 'Arc-fit tolerance', 'Rotor tool: grinding and checking dimensions', 'Plunge to Z0'] },
  { id: 'grooving', title: 'Grooving cycle', own: ['Cycle: revolutions and shifts', 'Chip and wall roughness'] },
  { id: 'flat', title: 'Flat on a lathe', own: ['Steps and flatness', 'Step table'] },
];
// Sections here are optional, but each is a page section of the route table (cutcalc --routes).
test('every section here is a page section of the route table, in its order', () => {
  assert.deepEqual(SECTIONS.map(s => s.id), PAGE_SECTIONS.filter(id => SECTIONS.some(s => s.id === id)));
});
// Text of the page that is never on a sheet: navigation, buttons, the footer.
const SCREEN_ONLY = ['Calculate', 'Print sheet', 'Copy link', 'Copy as curl', 'Download', 'cutcalc calculator', 'HTTP API contract'];

// The page's catalogue modules as the browser loads them (ES modules; web/ has no package.json).
const catalogue = async name => {
  const source = readFileSync(path.join(repo, 'web', 'ui', 'core', `catalogue_${name}.js`), 'utf8');
  return (await import(`data:text/javascript,${encodeURIComponent(source)}`)).default;
};
const EN = await catalogue('en');
const RU = await catalogue('ru');

const browser = chromiumForThisFile();
let work;
before(() => {
  mkdirSync(ARTIFACT_DIR, { recursive: true });
  work = mkdtempSync(path.join(os.tmpdir(), 'print-sheet-'));
});
after(() => {
  if (work) rmSync(work, { recursive: true, force: true });
});

// ------------------------------------------------------------------ a page and what happens on it
// Opens `url` with window.print() stubbed (it counts its calls: a real print dialog would block
// the test) and records the API answers and every sign of trouble, CSP violations included.
async function openPage(url, viewport = { width: 1280, height: 900 }) {
  const context = await browser().newContext({ viewport });
  const page = await context.newPage();
  page.setDefaultTimeout(WAIT_MS);
  const log = { answers: [], problems: [], inFlight: 0, lastActivity: Date.now() };
  await page.addInitScript(() => {
    window.__cspViolations = [];
    window.__prints = 0;
    window.print = () => {
      window.__prints += 1;
    };
    document.addEventListener('securitypolicyviolation', e =>
      window.__cspViolations.push(`${e.violatedDirective} ${e.blockedURI}`),
    );
  });
  page.on('console', msg => {
    if (msg.type() === 'error') log.problems.push(`console error: ${msg.text()}`);
  });
  page.on('pageerror', error => log.problems.push(`page error: ${error.message}`));
  page.on('request', () => {
    log.inFlight += 1;
    log.lastActivity = Date.now();
  });
  page.on('requestfinished', async request => {
    const u = new URL(request.url());
    if (request.method() === 'POST' && u.pathname.startsWith('/v1/')) {
      const response = await request.response();
      const entry = { path: u.pathname, status: response?.status() ?? 0, json: null };
      try {
        entry.json = await response?.json();
      } catch {
        entry.json = null;
      }
      log.answers.push(entry);
    }
    log.inFlight -= 1;
    log.lastActivity = Date.now();
  });
  page.on('requestfailed', request => {
    log.inFlight -= 1;
    log.lastActivity = Date.now();
    log.problems.push(`request failed: ${request.method()} ${request.url()}: ${request.failure()?.errorText}`);
  });
  page.on('response', response => {
    if (response.status() >= 400) log.problems.push(`HTTP ${response.status()} for ${response.request().method()} ${response.url()}`);
  });
  const response = await page.goto(url, { waitUntil: 'load' });
  assert.equal(response?.status(), 200, `GET ${url}`);
  await settle(log);
  return { context, page, log };
}



const lastAnswer = (log, endpoint) => {
  const found = log.answers.filter(a => a.path === endpoint && a.status === 200).at(-1);
  assert.ok(found, `no 200 answer from ${endpoint}`);
  return found.json;
};

// ------------------------------------------------------------------ printing
// The page printed as Chromium prints it (A4, print media): its text, one string per page.
async function printedPages(page, name) {
  const pdf = path.join(work, `${name}.pdf`);
  await page.pdf({ path: pdf, format: 'A4', printBackground: true });
  const { stdout } = await run(PDFTOTEXT, ['-layout', '-enc', 'UTF-8', pdf, '-'], { maxBuffer: 1 << 24 });
  const pages = stdout.split('\f');
  if (pages.at(-1).trim() === '') pages.pop();
  return { pdf, pages };
}

// The first page of a printed sheet as a PNG, for people (build/e2e/).
async function savePng(pdf, name) {
  const prefix = path.join(ARTIFACT_DIR, name);
  await run(PDFTOPPM, ['-png', '-r', '70', '-f', '1', '-l', '1', '-singlefile', pdf, prefix]);
}

// pdftotext keeps words, not the layout: compare with runs of white space as one space.
const flat = text => text.replace(/\s+/g, ' ');
const includes = (text, part) => flat(text).includes(flat(part));

// What the section shows that its sheet must hold: its inputs (label without the unit, shown
// value, unit) and its shown results (the rounded numbers).
async function sheetExpectations(page, id) {
  return page.evaluate(id => {
    const section = document.getElementById(id);
    const inputs = [...section.querySelectorAll('table.sheet-inputs tr[data-input]')].map(row =>
      [...row.cells].map(cell => cell.textContent),
    );
    const results = [...section.querySelectorAll(`#${id}-result [data-result]`)].map(el => el.textContent);
    return { inputs, results };
  }, id);
}

// "Print sheet" of section `id`, then the PDF: the section's pages of text.
async function printSheet(page, id) {
  const before = await page.evaluate(() => window.__prints);
  await page.click(`#${id}-print`);
  await page.waitForFunction(n => window.__prints > n, before);
  const marked = await page.evaluate(() => [...document.querySelectorAll('[data-print-target]')].map(e => e.id));
  assert.deepEqual(marked, [id], 'Print sheet marks its own section, and only it');
  return printedPages(page, `sheet-${id}`);
}

function assertOnlySection(text, id) {
  const section = SECTIONS.find(s => s.id === id);
  assert.ok(includes(text, section.title), `${id}: the sheet has the section's title`);
  for (const part of section.own) assert.ok(includes(text, part), `${id}: the sheet has "${part}"`);
  for (const other of SECTIONS.filter(s => s.id !== id)) {
    for (const part of [other.title, ...other.own]) {
      assert.ok(!includes(text, part), `${id}: the sheet has "${part}" of the ${other.id} section`);
    }
  }
  for (const part of SCREEN_ONLY) assert.ok(!includes(text, part), `${id}: the sheet has "${part}" (screen only)`);
}

async function assertInputsAndResults(page, id, text) {
  const { inputs, results } = await sheetExpectations(page, id);
  assert.ok(inputs.length >= 4, `${id}: the sheet's inputs table has rows (${inputs.length})`);
  const wanted = await page.evaluate(
    id => [...document.querySelectorAll(`#${id}-form .field:not([hidden]) [name^="/"]`)].length,
    id,
  );
  assert.equal(inputs.length, wanted, `${id}: one input row per applicable field`);
  for (const [label, value, unit] of inputs) {
    assert.ok(includes(text, `${label} ${value} ${unit}`.trim()), `${id}: the sheet has the input "${label} ${value} ${unit}"`);
  }
  assert.ok(results.length >= 3, `${id}: results shown (${results.length})`);
  for (const shown of results) assert.ok(includes(text, shown), `${id}: the sheet has the result ${shown}`);
}

// ================================================================== the bore diagram
// The drawn radii and centres of the bore view, and the cusp view's label.
async function boreDrawing(page) {
  return page.evaluate(() => {
    const svg = document.querySelector('#bore-result svg[data-diagram="bore-milling"]');
    const cusp = document.querySelector('#bore-result svg[data-diagram="bore-cusp"]');
    if (!svg || !cusp) return null;
    const circle = el => ({ x: +el.getAttribute('cx'), y: +el.getAttribute('cy'), r: +el.getAttribute('r') });
    const label = cusp.querySelector('[data-role="cusp-label"]');
    return {
      bore: [...svg.querySelectorAll('circle[data-role="bore"]')].map(circle),
      cutters: [...svg.querySelectorAll('circle[data-role="cutter"]')].map(circle),
      cuspLabel: label?.textContent ?? '',
      cuspValue: label?.getAttribute('data-value') ?? '',
    };
  });
}

const within = (got, want, rel, what) =>
  assert.ok(Math.abs(got - want) <= rel * Math.abs(want), `${what}: ${got} vs ${want} (${rel * 100} %)`);

describe('bore-milling diagram', () => {
  const cases = [
    { name: 'defaults (R 81, r 32.4, 4 teeth)', query: '', R: 81, r: 32.4 },
    {
      name: 'a small bore, 2 teeth, a large feed',
      query: '?bore.bore_radius_mm=10&bore.cutter_radius_mm=6&bore.teeth=2&bore.feed_per_rev_mm=1.5&bore.milling=down#bore',
      R: 10,
      r: 6,
    },
  ];
  for (const c of cases) {
    test(`${c.name}: the bore and two cutters to scale, the cusp labelled with the API's value`, { timeout: TEST_MS }, async () => {
      const { context, page, log } = await openPage(`${PAGE_URL}${c.query}`);
      try {
        const answer = lastAnswer(log, BORE_PATH);
        const drawing = await boreDrawing(page);
        assert.ok(drawing, 'the bore section has its two diagrams after the calculation');
        assert.equal(drawing.bore.length, 1, 'one bore circle');
        assert.equal(drawing.cutters.length, 2, 'two cutter positions');
        const [bore] = drawing.bore;
        const [one, two] = drawing.cutters;
        within(bore.r / one.r, c.R / c.r, 0.01, 'bore radius / cutter radius (first position)');
        within(bore.r / two.r, c.R / c.r, 0.01, 'bore radius / cutter radius (second position)');
        for (const cutter of [one, two]) {
          within(Math.hypot(cutter.x - bore.x, cutter.y - bore.y) / bore.r, (c.R - c.r) / c.R, 0.01, 'centre distance / bore radius');
        }
        assert.ok(Math.hypot(one.x - two.x, one.y - two.y) > 0.05 * one.r, 'the two cutter positions are apart');
        assert.equal(Number(drawing.cuspValue), answer.cusp_height_um, 'the magnified cusp carries the computed Delta');
        within(Number(/=\s*([-0-9.e]+)/.exec(drawing.cuspLabel)?.[1]), answer.cusp_height_um, 5e-4, 'the number in the cusp label (4 significant digits)');
        const shot = `bore-diagram-${c.R}-${c.r}.png`;
        await page.locator('#bore-result').screenshot({ path: path.join(ARTIFACT_DIR, shot) });
        await assertClean(page, log, c.name);
      } finally {
        await context.close();
      }
    });
  }
});

// ================================================================== setup sheets
describe('setup sheets (print)', () => {
  test('Print sheet of bore milling: its inputs, results and diagram on one page, nothing else', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      const { pdf, pages } = await printSheet(page, 'bore');
      assert.equal(pages.length, 1, 'the bore sheet is one page');
      const text = pages.join('\n');
      assertOnlySection(text, 'bore');
      await assertInputsAndResults(page, 'bore', text);
      const { cuspLabel } = await boreDrawing(page);
      assert.ok(includes(text, cuspLabel), `the sheet has the diagram's "${cuspLabel}"`);
      await savePng(pdf, 'print-sheet-bore');
      // The dialog closed: the page prints every section again.
      await page.evaluate(() => window.dispatchEvent(new Event('afterprint')));
      assert.equal(await page.locator('[data-print-target]').count(), 0, 'afterprint clears the mark');
      await assertClean(page, log, 'bore sheet');
    } finally {
      await context.close();
    }
  });

  for (const { id, endpoint } of [
    { id: 'entry', endpoint: '/v1/main-time/program' },
    { id: 'polygon', endpoint: '/v1/polygon-hole/gcode' },
    { id: 'grooving', endpoint: '/v1/grooving/cycle' },
    { id: 'flat', endpoint: '/v1/lathe-flat' },
  ]) {
    test(`Print sheet of ${id}: inputs, results, the program's file name and header, not its body`, { timeout: TEST_MS }, async () => {
      const { context, page, log } = await openPage(PAGE_URL);
      try {
        const program = lastAnswer(log, endpoint);
        const { pdf, pages } = await printSheet(page, id);
        const text = pages.join('\n');
        assertOnlySection(text, id);
        await assertInputsAndResults(page, id, text);
        assert.ok(includes(text, `File ${program.file_name}`), `${id}: the sheet names the file ${program.file_name}`);
        const lines = program.program.split('\n').map(l => l.trim()).filter(Boolean);
        const safe = lines.findIndex(line => /^G0?0\b.*Z/.test(line));
        assert.ok(safe > 0, `${id}: the program has a rapid to the safe height`);
        for (const line of lines.slice(0, safe + 1)) assert.ok(includes(text, line), `${id}: the sheet has the header line "${line}"`);
        assert.ok(!includes(text, 'M30'), `${id}: the sheet has the program's end (M30): the whole program, not its header`);
        await savePng(pdf, `print-sheet-${id}`);
        await assertClean(page, log, `${id} sheet`);
      } finally {
        await context.close();
      }
    });
  }

  test('Print sheet in Russian and in inches: Russian words only, lengths in inches', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(`${PAGE_URL}?lang=ru&units=inch`);
    try {
      // Words of the sheets (the print button and those of the screen are never on them).
      const sheetWords = ['sheet.inputs', 'sheet.calculation', 'button.print_sheet', 'button.calculate'];
      const bore = await printSheet(page, 'bore');
      assert.equal(bore.pages.length, 1, 'the Russian inch bore sheet is one page');
      const boreText = bore.pages.join('\n');
      await assertInputsAndResults(page, 'bore', boreText);
      const units = await page.evaluate(() =>
        Object.fromEntries([...document.querySelectorAll('#bore table.sheet-inputs tr[data-input]')].map(row => [row.dataset.input, row.cells[2].textContent])),
      );
      assert.equal(units['/bore_radius_mm'], RU['unit.in'], 'the bore radius in inches');
      assert.equal(units['/cutter_radius_mm'], RU['unit.in'], 'the cutter radius in inches');
      assert.equal(units['/feed_per_rev_mm'], RU['unit.in_per_rev'], 'the feed in inches per revolution');
      const boreKeys = ['section.bore_milling_roughness', 'label.bore_radius', 'sheet.inputs', 'sheet.calculation', 'legend.machined_surface', 'diagram.towards_bore_axis'];
      for (const key of boreKeys) assert.ok(includes(boreText, RU[key]), `bore: the sheet has "${RU[key]}" (${key})`);
      for (const key of [...boreKeys, 'button.print_sheet', 'button.calculate']) {
        assert.ok(!includes(boreText, EN[key]), `bore: the Russian sheet has "${EN[key]}" (${key})`);
      }
      for (const key of ['button.print_sheet', 'button.calculate']) assert.ok(!includes(boreText, RU[key]), `bore: the sheet has "${RU[key]}" (screen only)`);
      const { cuspLabel } = await boreDrawing(page);
      assert.ok(includes(boreText, cuspLabel), `bore: the sheet has the diagram's "${cuspLabel}"`);
      await savePng(bore.pdf, 'print-sheet-bore-ru-inch');

      const program = lastAnswer(log, '/v1/main-time/program');
      const entry = await printSheet(page, 'entry');
      const entryText = entry.pages.join('\n');
      await assertInputsAndResults(page, 'entry', entryText);
      assert.ok(includes(entryText, `${RU['sheet.file']} ${program.file_name}`), `entry: the sheet names the file ${program.file_name}`);
      assert.ok(includes(entryText, RU['sheet.program_header']), 'entry: the program header is named in Russian');
      assert.match(program.program, /\bG20\b/, 'the inch page asks for an inch program');
      for (const key of ['sheet.file', 'sheet.program_header', ...sheetWords]) {
        assert.ok(!includes(entryText, `${EN[key]} `), `entry: the Russian sheet has "${EN[key]}" (${key})`);
      }
      await savePng(entry.pdf, 'print-sheet-entry-ru-inch');
      await assertClean(page, log, 'Russian inch sheets');
    } finally {
      await context.close();
    }
  });

  test('printing the page (no Print sheet): every section, each from the top of a new page', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      const { pages } = await printedPages(page, 'whole-page');
      const startPages = SECTIONS.map(({ id, title }) => {
        const index = pages.findIndex(p => includes(p, title));
        assert.ok(index >= 0, `${id}: its title is printed`);
        assert.ok(pages[index].trim().startsWith(title), `${id}: its title begins page ${index + 1}`);
        return index;
      });
      for (let i = 1; i < startPages.length; i += 1) {
        assert.ok(startPages[i] > startPages[i - 1], `${SECTIONS[i].id} starts on a page after ${SECTIONS[i - 1].id} (${startPages})`);
      }
      for (const part of SCREEN_ONLY) assert.ok(!includes(pages.join('\n'), part), `the printed page has "${part}" (screen only)`);
      console.log(`# whole page: ${pages.length} pages, sections from pages ${startPages.map(i => i + 1).join(', ')}`);
      await assertClean(page, log, 'whole page');
    } finally {
      await context.close();
    }
  });
});

// ================================================================== keyboard only
for (const width of [375, 1280]) {
  describe(`setup sheets at ${width} px, keyboard only`, () => {
    test('every Print sheet button is reached with Tab and used with Enter', { timeout: TEST_MS }, async () => {
      const { context, page, log } = await openPage(PAGE_URL, { width, height: 812 });
      try {
        await page.evaluate(() => document.activeElement?.blur());
        for (const { id } of SECTIONS) {
          let reached = false;
          for (let i = 0; i < 300 && !reached; i += 1) {
            await page.keyboard.press('Tab');
            reached = await page.evaluate(id => document.activeElement?.id === `${id}-print`, id);
          }
          assert.ok(reached, `Tab does not reach #${id}-print`);
          const before = await page.evaluate(() => window.__prints);
          await page.keyboard.press('Enter');
          await page.waitForFunction(n => window.__prints > n, before);
          const marked = await page.evaluate(() => [...document.querySelectorAll('[data-print-target]')].map(e => e.id));
          assert.deepEqual(marked, [id], `Enter on #${id}-print marks ${id} for printing`);
          const overflow = await page.evaluate(() => document.scrollingElement.scrollWidth);
          assert.ok(overflow <= width, `the page scrolls sideways at ${width} px (${overflow})`);
        }
        await assertClean(page, log, `${width} px keyboard`);
      } finally {
        await context.close();
      }
    });
  });
}
