// End-to-end test of the calculator page as a shop tool (issue 13, parts 1, 3 and 7): Playwright
// (playwright-core) drives Debian's headless Chromium against a live cutcalc.
//
//   - first load: every section shows the result of its default inputs without a click, from
//     exactly one calculation (the requests one calculation of that section sends);
//   - links: per section, an edited calculation's "Copy link" URL opened in a new page gives the
//     same inputs and the same shown numbers;
//   - "Copy as curl": per section, the copied commands, run with `sh -c` against the live server,
//     are the requests the page sent (same URL and body) and print the answers the page got;
//   - "Download CSV": each table's file, parsed with an RFC 4180 parser, is the shown table (the Rz
//     curve: the curve the page received); header of field names and units, '.' decimals, CRLF,
//     and the page's CSV writer quotes commas, quotes and line breaks;
//   - typing several characters quickly is one request (after the pause), Enter calculates at once;
//   - back and forward restore the previous calculation (inputs and results, across sections);
//   - at 375 px and 1280 px the new buttons work from the keyboard alone (Tab, Enter);
//   - on every page: no console error, page error, failed request, HTTP error or CSP violation.
// The clipboard: the context is granted clipboard-read/write and the test reads what the page
// wrote with navigator.clipboard.readText().
//
// Environment: CUTCALC_URL (required), E2E_PAGE_URL, E2E_ARTIFACT_DIR, CHROMIUM_PATH, as in
// calculator.test.mjs.
import { before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { promisify } from 'node:util';

import { PAGE_SECTIONS, env, chromiumForThisFile, repo } from './browser.mjs';
import { ARTIFACT_DIR, PAGE_URL, TEST_MS, WAIT_MS, assertClean, openRecordedPage, settle } from './page_session.mjs';

// The requests one calculation of each section sends (entry: one pass, the setup and its
// program; speeds: the points, then the arc for up- and for down-milling), and an edit that makes
// the section's inputs differ from its defaults.
const SECTIONS = [
  {
    id: 'entry',
    requests: { '/v1/entry-length': 1, '/v1/main-time': 1, '/v1/main-time/program': 1 },
    edit: ['/cutter_diameter_mm', '25'],
    csv: { button: 'entry-passes-csv', table: true },
  },
  {
    id: 'speeds',
    requests: { '/v1/resultant-speeds': 3 },
    edit: ['/tool_speed_rpm', '2500'],
    csv: { button: 'speeds-points-csv', table: true },
  },
  {
    id: 'groove',
    requests: { '/v1/roughness/groove-wall': 1 },
    edit: ['/feed_mm', '0.2'],
    csv: { button: 'groove-curve-csv', curve: '/v1/roughness/groove-wall' },
  },
  { id: 'bore', requests: { '/v1/roughness/bore-milling': 1 }, edit: ['/teeth', '6'] },
  { id: 'polygon', requests: { '/v1/polygon-hole/gcode': 1 }, edit: ['/faces', '5'] },
  { id: 'grooving', requests: { '/v1/grooving/cycle': 1 }, edit: ['/feed_per_rev_mm', '0.1'] },
  {
    id: 'flat',
    requests: { '/v1/lathe-flat': 1 },
    edit: ['/steps', '6'],
    csv: { button: 'flat-steps-csv', table: true },
  },
  {
    // The program itself is not in the link (its text area): the control is.
    id: 'program-time',
    requests: { '/v1/program-time': 1 },
    edit: ['/dialect', 'fanuc'],
    csv: { button: 'program-time-slowest-csv', table: true },
  },
];
const byId = id => SECTIONS.find(s => s.id === id);
// Sections here are optional, but each is a page section of the route table (cutcalc --routes).
test('every section here is a page section of the route table, in its order', () => {
  assert.deepEqual(SECTIONS.map(s => s.id), PAGE_SECTIONS.filter(id => SECTIONS.some(s => s.id === id)));
});

const browser = chromiumForThisFile();
before(() => mkdirSync(ARTIFACT_DIR, { recursive: true }));

// ------------------------------------------------------------------ a page and what happens on it
const openPage = (url, viewport) => openRecordedPage(browser(), url, { viewport, clipboard: true });



// The numbers (and codes) a section shows: [pointer, source, full value] of every data-result.
async function shownResults(page, id) {
  return page.evaluate(
    id =>
      [...document.querySelectorAll(`#${id}-result [data-result]`)].map(el => [
        el.getAttribute('data-result'),
        el.getAttribute('data-source') ?? '',
        el.getAttribute('data-value'),
      ]),
    id,
  );
}

async function formValues(page, id) {
  return page.evaluate(
    id =>
      [...document.querySelectorAll(`#${id}-form [name^="/"]`)].filter(c => !c.disabled).map(c => [c.name, c.value]),
    id,
  );
}

const countByPath = exchanges => {
  const counts = {};
  for (const e of exchanges) counts[e.path] = (counts[e.path] ?? 0) + 1;
  return counts;
};
const sectionExchanges = (exchanges, id) => exchanges.filter(e => e.path in byId(id).requests);

async function readClipboard(page) {
  return page.evaluate(() => navigator.clipboard.readText());
}

// Types `text` into the section's input `name` as a person would (select all, then key by key).
async function typeInto(page, id, name, text, delay = 40) {
  const input = page.locator(`#${id}-form [name="${name}"]`);
  await input.click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.type(text, { delay });
}

// A calculation asked for with Enter in a field, waited for until the page is quiet; a select
// (the program time's control) calculates on its change, after the page's pause.
async function calculateWith(page, log, id, name, text) {
  const select = page.locator(`#${id}-form select[name="${name}"]`);
  if ((await select.count()) === 1) {
    await select.selectOption(text);
  } else {
    await typeInto(page, id, name, text, 0);
    await page.keyboard.press('Enter');
  }
  await settle(log);
}

// ------------------------------------------------------------------ RFC 4180
// Records of CSV text: fields separated by commas, records by CRLF; a quoted field may hold
// commas, CRLF and doubled quotes. Strict: a quote inside an unquoted field is an error.
function parseCsv(text) {
  const records = [];
  let record = [];
  let field = '';
  let i = 0;
  let quoted = false;
  while (i < text.length) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') {
        field += '"';
        i += 2;
      } else if (c === '"') {
        quoted = false;
        i += 1;
        assert.ok(i >= text.length || text[i] === ',' || text.startsWith('\r\n', i), `CSV: text after a closing quote at ${i}`);
      } else {
        field += c;
        i += 1;
      }
    } else if (c === '"') {
      assert.equal(field, '', `CSV: a quote inside an unquoted field at ${i}`);
      quoted = true;
      i += 1;
    } else if (c === ',') {
      record.push(field);
      field = '';
      i += 1;
    } else if (text.startsWith('\r\n', i)) {
      record.push(field);
      records.push(record);
      record = [];
      field = '';
      i += 2;
    } else {
      assert.ok(c !== '\r' && c !== '\n', `CSV: a bare line break at ${i} (records end with CRLF)`);
      field += c;
      i += 1;
    }
  }
  assert.ok(!quoted, 'CSV: an unterminated quoted field');
  assert.ok(field === '' && record.length === 0, 'CSV: the last record does not end with CRLF');
  return records;
}

async function downloadText(page, action) {
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: WAIT_MS }), action()]);
  return { name: download.suggestedFilename(), text: readFileSync(await download.path(), 'utf8') };
}

// A CSV cell against the value it stands for: numbers as numbers (the cell with '.' decimals),
// everything else as text.
function assertCell(cell, want, where) {
  if (typeof want === 'number' || (want !== '' && want !== null && !Number.isNaN(Number(want)) && /^[-+0-9.eE]+$/.test(String(want)))) {
    assert.match(cell, /^-?\d+(\.\d+)?(e[-+]?\d+)?$/, `${where}: "${cell}" is not a number with '.' decimals`);
    assert.equal(Number(cell), Number(want), `${where}: ${cell} != ${want}`);
  } else {
    assert.equal(cell, String(want ?? ''), where);
  }
}

// ================================================================== the tests
describe('calculator page as a shop tool', () => {
  test('first load: every section shows its results without a click, from one calculation each', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      for (const section of SECTIONS) {
        const shown = await shownResults(page, section.id);
        assert.ok(shown.length > 0, `#${section.id}-result shows no result after load`);
        const placeholder = await page.locator(`#${section.id}-result .placeholder`).count();
        assert.equal(placeholder, 0, `#${section.id}-result still shows a placeholder`);
        const mine = sectionExchanges(log.exchanges, section.id);
        assert.deepEqual(countByPath(mine), section.requests, `${section.id}: the requests on load are not those of one calculation`);
        for (const e of mine) assert.equal(e.status, 200, `${section.id}: ${e.path} answered ${e.status} on load`);
      }
      assert.equal(log.exchanges.length, SECTIONS.reduce((n, s) => n + Object.values(s.requests).reduce((a, b) => a + b, 0), 0), 'no other request on load');
      await assertClean(page, log, 'first load');
    } finally {
      await context.close();
    }
  });

  for (const section of SECTIONS) {
    test(`${section.id}: "Copy link" opened in a new page fills the form and gives the same results`, { timeout: TEST_MS }, async () => {
      const first = await openPage(PAGE_URL);
      const second = { context: null };
      try {
        await settle(first.log);
        const [name, text] = section.edit;
        await calculateWith(first.page, first.log, section.id, name, text);
        const inputs = await formValues(first.page, section.id);
        assert.ok(inputs.some(([n, v]) => n === name && v === text), `${section.id}: ${name} is not ${text}`);
        const results = await shownResults(first.page, section.id);
        await first.page.locator(`#${section.id}-copy-link`).click();
        await first.page.waitForFunction(id => /copied/.test(document.getElementById(`${id}-copy-status`)?.textContent ?? ''), section.id);
        const link = await readClipboard(first.page);
        const url = new URL(link);
        assert.equal(url.hash, `#${section.id}`, `the link ${link} goes to #${section.id}`);
        assert.equal(url.searchParams.get(`${section.id}${name.replaceAll('/', '.')}`), text, `the link ${link} carries ${name} = ${text}`);
        assert.ok([...url.searchParams.keys()].every(k => k.startsWith(`${section.id}.`)), `the link ${link} carries only #${section.id}'s inputs`);

        Object.assign(second, await openPage(link));
        await settle(second.log);
        assert.deepEqual(await formValues(second.page, section.id), inputs, `${section.id}: the link does not fill the form as it was`);
        assert.deepEqual(await shownResults(second.page, section.id), results, `${section.id}: the link does not give the same results`);
        assert.deepEqual(countByPath(sectionExchanges(second.log.exchanges, section.id)), section.requests, `${section.id}: the link's page calculates more than once`);
        await assertClean(first.page, first.log, `${section.id} (first page)`);
        await assertClean(second.page, second.log, `${section.id} (opened link)`);
      } finally {
        await first.context.close();
        await second.context?.close();
      }
    });
  }

  for (const section of SECTIONS) {
    test(`${section.id}: "Copy as curl" run with sh -c sends the page's requests and prints its answers`, { timeout: TEST_MS }, async () => {
      const { context, page, log } = await openPage(PAGE_URL);
      try {
        await settle(log);
        const sent = sectionExchanges(log.exchanges, section.id);
        await page.locator(`#${section.id}-copy-curl`).click();
        await page.waitForFunction(id => /copied/.test(document.getElementById(`${id}-copy-status`)?.textContent ?? ''), section.id);
        const script = await readClipboard(page);
        const commands = script.split('\n');
        assert.equal(commands.length, sent.length, `one curl command per request the page sent:\n${script.slice(0, 500)}`);
        // Each command names a request the page sent: the same URL and the same body, byte for byte.
        const unquote = word => word.slice(1, -1).replaceAll("'\\''", "'");
        const requested = commands.map(command => {
          const url = /^curl -sS ('(?:[^']|'\\'')*')/.exec(command);
          const body = / --data-raw ('(?:[^']|'\\'')*')/.exec(command);
          assert.ok(url && body, `not a curl command of the page: ${command.slice(0, 200)}`);
          return `${unquote(url[1])} ${unquote(body[1])}`;
        });
        assert.deepEqual(requested.sort(), sent.map(e => `${e.url} ${e.body}`).sort(), 'the commands are the requests the page sent');

        const { stdout } = await promisify(execFile)('sh', ['-c', script], { maxBuffer: 64 * 1024 * 1024 });
        const answers = stdout.split('\n').filter(line => line !== '');
        assert.equal(answers.length, sent.length, 'one answer per command');
        const canonical = answers.map(line => JSON.stringify(JSON.parse(line))).sort();
        assert.deepEqual(canonical, sent.map(e => JSON.stringify(e.json)).sort(), 'the answers are the ones the page got');
        console.log(`# ${section.id}: ${commands.length} curl command(s), answers equal to the page's`);
        await assertClean(page, log, `${section.id} curl`);
      } finally {
        await context.close();
      }
    });
  }

  for (const section of SECTIONS.filter(s => s.csv)) {
    test(`${section.id}: "Download CSV" is the shown ${section.csv.table ? 'table' : 'Rz curve'} (RFC 4180)`, { timeout: TEST_MS }, async () => {
      const { context, page, log } = await openPage(PAGE_URL);
      try {
        await settle(log);
        const { name, text } = await downloadText(page, () => page.locator(`#${section.csv.button}`).click());
        assert.match(name, /\.csv$/, `the file name ${name}`);
        const [header, ...rows] = parseCsv(text);
        for (const cell of header) assert.match(cell, /^[a-z][a-z0-9_]*( \[[^\]]+\])?$/, `header cell "${cell}": a field name, its unit in brackets`);
        let want;
        if (section.csv.table) {
          // The table next to the button: its rows' cells (a row header, then data-value cells).
          want = await page.evaluate(id => {
            const table = document.getElementById(id).previousElementSibling.querySelector('table');
            return [...table.tBodies[0].rows].map(row =>
              [...row.cells].map(cell => cell.querySelector('[data-value]')?.getAttribute('data-value') ?? cell.textContent.trim()),
            );
          }, section.csv.button);
        } else {
          const exchange = log.exchanges.find(e => e.path === section.csv.curve && e.status === 200);
          want = exchange.json.curve.map(p => header.map(h => p[h.split(' ')[0]]));
          assert.deepEqual(header.map(h => h.split(' ')[0]), ['feed_mm', 'rz_um'], 'the curve\'s columns');
        }
        assert.ok(want.length > 0, 'the table has rows');
        assert.equal(rows.length, want.length, 'one CSV record per table row');
        rows.forEach((row, i) => {
          assert.equal(row.length, header.length, `record ${i + 1} has as many fields as the header`);
          row.forEach((cell, j) => assertCell(cell, want[i][j], `${name} record ${i + 1}, ${header[j]}`));
        });
        console.log(`# ${section.id}: ${name}, ${rows.length} records of ${header.length} fields equal to the page's`);
        await assertClean(page, log, `${section.id} CSV`);
      } finally {
        await context.close();
      }
    });
  }

  test('the CSV writer quotes commas, quotes and line breaks (RFC 4180)', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      const rows = [['a,b', 'say "x"', 'two\r\nlines', 'plain', 1.5, -2e-7]];
      const text = await page.evaluate(async rows => (await import('/ui/core/export.js')).csvText(['h1', 'h2', 'h3', 'h4', 'h5', 'h6'], rows), rows);
      assert.equal(text.split('\r\n')[0], 'h1,h2,h3,h4,h5,h6');
      assert.deepEqual(parseCsv(text), [['h1', 'h2', 'h3', 'h4', 'h5', 'h6'], ['a,b', 'say "x"', 'two\r\nlines', 'plain', '1.5', '-2e-7']]);
      await settle(log);
      await assertClean(page, log, 'CSV writer');
    } finally {
      await context.close();
    }
  });

  test('typing several characters quickly is one request; Enter calculates at once', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      const path = '/v1/roughness/groove-wall';
      let start = log.exchanges.length;
      await typeInto(page, 'groove', '/feed_mm', '0.25', 40);
      await settle(log);
      let fresh = log.exchanges.slice(start);
      assert.equal(fresh.length, 1, `4 keystrokes gave ${fresh.length} requests: ${fresh.map(e => e.body).join(' | ')}`);
      assert.equal(JSON.parse(fresh[0].body).feed_mm, 0.25, 'the request after the pause has the typed value');
      await page.waitForFunction(rz => document.querySelector('#groove-result [data-result="/rz_um"]')?.getAttribute('data-value') === String(rz), fresh[0].json.rz_um);

      // Enter does not wait for the pause, and the pause adds no second request.
      start = log.exchanges.length;
      await typeInto(page, 'groove', '/feed_mm', '0.3', 20);
      const typed = Date.now();
      await page.keyboard.press('Enter');
      while (log.exchanges.length === start && Date.now() - typed < WAIT_MS) await new Promise(resolve => setTimeout(resolve, 10));
      assert.ok(Date.now() - typed < 600, `Enter waited for the pause (${Date.now() - typed} ms)`);
      await settle(log);
      fresh = log.exchanges.slice(start);
      assert.deepEqual(fresh.map(e => [e.path, JSON.parse(e.body).feed_mm]), [[path, 0.3]], 'Enter: one request with the typed value');
      await assertClean(page, log, 'debounce');
    } finally {
      await context.close();
    }
  });

  test('back and forward restore the previous calculations', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      const snapshot = async () => ({
        groove: [await formValues(page, 'groove'), await shownResults(page, 'groove')],
        bore: [await formValues(page, 'bore'), await shownResults(page, 'bore')],
      });
      const states = [await snapshot()];
      await calculateWith(page, log, 'groove', '/feed_mm', '0.2');
      states.push(await snapshot());
      await calculateWith(page, log, 'groove', '/feed_mm', '0.3');
      states.push(await snapshot());
      await calculateWith(page, log, 'bore', '/teeth', '6');
      states.push(await snapshot());
      assert.notDeepEqual(states[1].groove[1], states[2].groove[1], 'two feeds, two results');
      const expectState = async (i, how) => {
        await settle(log);
        assert.deepEqual(await snapshot(), states[i], `${how}: not the calculation number ${i}`);
      };
      for (const i of [2, 1, 0]) {
        await page.goBack();
        await expectState(i, 'back');
      }
      for (const i of [1, 2, 3]) {
        await page.goForward();
        await expectState(i, 'forward');
      }
      await assertClean(page, log, 'history');
    } finally {
      await context.close();
    }
  });
});

// ================================================================== keyboard only
// Tab from the top of the page to each new button and press Enter on it: the links and curl
// commands land in the clipboard, the CSV files download; the page never scrolls sideways.
for (const width of [375, 1280]) {
  describe(`shop tools at ${width} px, keyboard only`, () => {
    test('Copy link, Copy as curl and Download CSV are reached with Tab and used with Enter', { timeout: TEST_MS }, async () => {
      const { context, page, log } = await openPage(PAGE_URL, { width, height: 812 });
      try {
        await settle(log);
        await page.evaluate(() => document.activeElement?.blur());
        const tabTo = async id => {
          for (let i = 0; i < 300; i += 1) {
            await page.keyboard.press('Tab');
            if (await page.evaluate(id => document.activeElement?.id === id, id)) return;
          }
          assert.fail(`Tab does not reach #${id}`);
        };
        // Enter on the focused button; what it put in the clipboard (emptied before, as is the
        // status line, so that an earlier copy is never read).
        const copied = async id => {
          await page.evaluate(async id => {
            document.getElementById(`${id}-copy-status`).textContent = '';
            await navigator.clipboard.writeText('');
          }, id);
          await page.keyboard.press('Enter');
          await page.waitForFunction(id => /copied/.test(document.getElementById(`${id}-copy-status`)?.textContent ?? ''), id);
          return readClipboard(page);
        };
        let files = 0;
        for (const section of SECTIONS) {
          await tabTo(`${section.id}-copy-link`);
          assert.equal(new URL(await copied(section.id)).hash, `#${section.id}`, `${section.id}: the link`);
          await tabTo(`${section.id}-copy-curl`);
          assert.match(await copied(section.id), /^curl -sS '/, `${section.id}: the curl command`);
          if (section.csv) {
            await tabTo(section.csv.button);
            const { name, text } = await downloadText(page, () => page.keyboard.press('Enter'));
            assert.match(name, /\.csv$/);
            assert.ok(parseCsv(text).length > 1, `${name} has records`);
            files += 1;
          }
          const overflow = await page.evaluate(() => document.scrollingElement.scrollWidth);
          assert.ok(overflow <= width, `the page scrolls sideways at ${width} px (${overflow})`);
        }
        await page.evaluate(() => window.scrollTo(0, 0));
        await page.screenshot({ path: path.join(ARTIFACT_DIR, `shop-tool-${width}.png`), fullPage: true });
        console.log(`# ${width} px: ${SECTIONS.length} links, ${SECTIONS.length} curl commands and ${files} CSV files from the keyboard`);
        await assertClean(page, log, `${width} px keyboard`);
      } finally {
        await context.close();
      }
    });
  });
}
