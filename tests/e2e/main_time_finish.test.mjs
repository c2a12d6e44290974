// End-to-end test of the main-time form's equal passes and finishing level (spec
// entry-and-main-time.md section 15): in English and Russian, in mm and inch, the page sends
// `pass_split` and `finish` as entered (inches converted to mm), shows the finishing level's numbers
// of the reference case MN-finish-equal (next/main-time.json) in the page's units, and its pass
// table has the finishing traverse's time; the program is written for the same request; no console
// error, failed request or HTTP error.
//
// Environment: CUTCALC_URL (required), E2E_PAGE_URL, E2E_ARTIFACT_DIR, CHROMIUM_PATH, as in
// calculator.test.mjs.
import { before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';

import { chromiumForThisFile, reference, repo } from './browser.mjs';
import { ARTIFACT_DIR, PAGE_URL, TEST_MS, assertClean, openRecordedPage, settle } from './page_session.mjs';

const MM_PER_INCH = 25.4;
// The page's units that are lengths (units.js): shown in inches on the inch page.
const LENGTH_UNITS = new Set(['mm', 'mm_per_tooth', 'mm_per_rev', 'mm_per_min']);

const catalogue = async name => {
  const source = readFileSync(path.join(repo, 'web', 'ui', 'core', `catalogue_${name}.js`), 'utf8');
  return (await import(`data:text/javascript,${encodeURIComponent(source)}`)).default;
};
const CATALOGUES = { en: await catalogue('en'), ru: await catalogue('ru') };

const CASE = reference(path.join('next', 'main-time.json')).cases.find(c => c.id === 'MN-finish-equal');
const browser = chromiumForThisFile();
before(() => mkdirSync(ARTIFACT_DIR, { recursive: true }));

// The request's leaves as JSON Pointer -> value.
function leaves(obj, prefix = '', out = new Map()) {
  for (const [k, v] of Object.entries(obj)) {
    if (v !== null && typeof v === 'object') leaves(v, `${prefix}/${k}`, out);
    else out.set(`${prefix}/${k}`, v);
  }
  return out;
}

function pointerGet(doc, ptr) {
  let cur = doc;
  for (const key of ptr.slice(1).split('/')) {
    if (cur === null || typeof cur !== 'object' || !(key in cur)) return undefined;
    cur = cur[key];
  }
  return cur;
}

// Fills the entry form with the case's request: selects first, then every named input (the
// case's value, in inches on the inch page; empty when the case has none).
async function fillEntryForm(page, inch) {
  const wanted = leaves(CASE.request);
  const form = page.locator('#entry-form');
  for (const [ptr, value] of wanted) {
    const select = form.locator(`select[name="${ptr}"]`);
    if ((await select.count()) === 1) await select.selectOption(String(value));
  }
  const inputs = await form.evaluate(f =>
    [...f.querySelectorAll('input[name^="/"]')]
      .filter(c => !c.disabled && c.getClientRects().length > 0)
      .map(c => [c.name, document.querySelector(`label[for="${c.id}"] [data-unit]`)?.dataset.unit ?? '']),
  );
  for (const [name, unit] of inputs) {
    if (name.startsWith('/program/')) continue;
    const value = wanted.get(name);
    const shown = value === undefined ? '' : inch && LENGTH_UNITS.has(unit) ? value / MM_PER_INCH : value;
    await form.locator(`input[name="${name}"]`).fill(String(shown));
  }
}

const close = (a, b, tol) => Math.abs(a - b) <= tol;

describe('main time: equal passes and the finishing level', () => {
  for (const [lang, units] of [['en', 'mm'], ['ru', 'mm'], ['en', 'inch'], ['ru', 'inch']]) {
    test(`${lang}, ${units}: the finishing level's numbers are shown`, { timeout: TEST_MS }, async () => {
      assert.ok(CASE, 'MN-finish-equal is in next/main-time.json');
      const inch = units === 'inch';
      const query = new URLSearchParams({ ...(lang !== 'en' && { lang }), ...(inch && { units }) });
      const { context, page, log } = await openRecordedPage(browser(), `${PAGE_URL}?${query}`);
      try {
        await settle(log);
        await fillEntryForm(page, inch);
        const before = log.exchanges.length;
        await page.locator('#entry-form button[type="submit"]').click();
        await settle(log);
        const mine = log.exchanges.slice(before);
        const sent = mine.filter(e => e.path === '/v1/main-time').at(-1);
        assert.ok(sent, 'Calculate sent no /v1/main-time request');
        assert.equal(sent.status, 200, `/v1/main-time answered ${sent.status}: ${sent.text?.slice(0, 300)}`);
        const body = JSON.parse(sent.body);
        assert.equal(body.pass_split, 'equal', 'pass_split sent');
        for (const [ptr, want] of leaves(CASE.request.finish, '/finish')) {
          assert.ok(close(pointerGet(body, ptr), want, 1e-9), `${ptr}: sent ${pointerGet(body, ptr)}, want ${want}`);
        }
        const program = mine.filter(e => e.path === '/v1/main-time/program').at(-1);
        assert.equal(program?.status, 200, 'the pass program of the same request is written');
        assert.deepEqual(JSON.parse(program.body).finish, body.finish, 'the program gets the same finish');

        const shown = await page.evaluate(() =>
          [...document.querySelectorAll('#entry-result [data-result]')].map(el => ({
            ptr: el.getAttribute('data-result'),
            value: Number(el.getAttribute('data-value')),
            unit: el.getAttribute('data-unit') ?? '',
            text: el.textContent,
          })),
        );
        const expected = CASE.expect.body;
        const mustShow = ['/finish/depth_mm', '/finish/time_min', '/finish/spindle_speed_rpm', '/finish/feed_mm_per_min',
          '/finish/entry_feed_mm_per_min', '/finish/lateral_passes/0/time_min', '/finish/lateral_passes/1/time_min',
          '/main_time_min', '/depth_passes_mm/3'];
        for (const ptr of mustShow) {
          const el = shown.find(s => s.ptr === ptr);
          assert.ok(el, `${ptr} is not shown`);
          const want = pointerGet(expected, ptr);
          const tol = ptr.endsWith('_min') && !ptr.endsWith('_mm_per_min') ? CASE.tolerance.abs_min : CASE.tolerance.abs_mm;
          assert.ok(close(el.value, want, tol), `${ptr}: data-value ${el.value}, reference ${want}`);
          // The text: the value in the page's units, rounded to the decimals shown.
          const inPageUnits = inch && el.unit.startsWith('in') ? want / MM_PER_INCH : want;
          const m = /[-+]?\d+(?:[.,](\d+))?/.exec(el.text.replace(/[\u2009\u202f\u00a0 ](?=\d{3}\b)/g, ''));
          assert.ok(m, `${ptr}: no number in "${el.text}"`);
          const halfStep = 0.5 * 10 ** -(m[1]?.length ?? 0);
          assert.ok(close(Number(m[0].replace(',', '.')), inPageUnits, halfStep * (1 + 1e-9) + 1e-12),
            `${ptr}: shows "${el.text}", want ${inPageUnits} (${units})`);
          if (ptr === '/finish/depth_mm') assert.equal(el.unit, inch ? 'in' : 'mm', `${ptr}: data-unit`);
        }
        const heading = await page.locator('#entry-result h4').first().textContent();
        assert.equal(heading, CATALOGUES[lang]['result.finishing_level'], 'the finishing level heading');
        await page.screenshot({ path: path.join(ARTIFACT_DIR, `main-time-finish-${lang}-${units}.png`), fullPage: false });
        console.log(`# ${lang}, ${units}: ${mustShow.length} finishing-level numbers shown as the reference MN-finish-equal`);
        await assertClean(page, log, `${lang} ${units}`);
      } finally {
        await context.close();
      }
    });
  }
});
