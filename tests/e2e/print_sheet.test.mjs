// End-to-end test of the bore-milling diagram (issue 13, part 6): Playwright (playwright-core)
// drives Debian's headless Chromium against a live cutcalc.
//
//   - after the calculation the bore-milling section shows the bore and two cutter positions to
//     scale (bore radius / cutter radius in SVG units = R / r, centre distance / bore radius =
//     (R - r) / R, within 1 %) for two input sets, and the magnified cusp labelled with the Delta
//     the API computed;
//   - on every page: no console error, page error, failed request, HTTP error or CSP violation.
//
// Environment: CUTCALC_URL (required), E2E_PAGE_URL, E2E_ARTIFACT_DIR, CHROMIUM_PATH, as in
// calculator.test.mjs.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '..', '..');
const requireFromTools = createRequire(path.join(repo, 'tools', 'e2e', 'package.json'));
const { chromium } = requireFromTools('playwright-core');

const env = (name, fallback) => {
  const value = process.env[name];
  return value !== undefined && value !== '' ? value : fallback;
};
const API = (env('CUTCALC_URL') ?? '').replace(/\/$/, '');
if (!API) throw new Error('CUTCALC_URL is not set (the base URL of a running cutcalc)');
const PAGE_URL = env('E2E_PAGE_URL', `${API}/`);
const ARTIFACT_DIR = path.resolve(repo, env('E2E_ARTIFACT_DIR', path.join('build', 'e2e')));
const CHROMIUM = env('CHROMIUM_PATH', '/usr/bin/chromium');
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'];
const WAIT_MS = 20000;
const TEST_MS = 120000;
// Longer than the page's pause before it recalculates (calculation.js PAUSE_MS, 600 ms).
const QUIET_MS = 1200;
const BORE_PATH = '/v1/roughness/bore-milling';

let browser;
before(async () => {
  mkdirSync(ARTIFACT_DIR, { recursive: true });
  browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, timeout: 60000 });
});
after(async () => {
  await browser?.close();
});

// ------------------------------------------------------------------ a page and what happens on it
// Opens `url` and records the API answers and every sign of trouble, CSP violations included.
async function openPage(url, viewport = { width: 1280, height: 900 }) {
  const context = await browser.newContext({ viewport });
  const page = await context.newPage();
  page.setDefaultTimeout(WAIT_MS);
  const log = { answers: [], problems: [], inFlight: 0, lastActivity: Date.now() };
  await page.addInitScript(() => {
    window.__cspViolations = [];
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

// Waits until no request is in flight and none has started for QUIET_MS.
async function settle(log) {
  log.lastActivity = Math.max(log.lastActivity, Date.now());
  const deadline = Date.now() + WAIT_MS;
  while (log.inFlight > 0 || Date.now() - log.lastActivity < QUIET_MS) {
    assert.ok(Date.now() < deadline, `the page's requests did not settle within ${WAIT_MS} ms`);
    await new Promise(resolve => setTimeout(resolve, 50));
  }
}

async function assertClean(page, log, label) {
  const csp = await page.evaluate(() => window.__cspViolations ?? []);
  assert.deepEqual([...log.problems, ...csp.map(v => `CSP violation: ${v}`)], [], `${label}: trouble on the page`);
}

const lastAnswer = (log, endpoint) => {
  const found = log.answers.filter(a => a.path === endpoint && a.status === 200).at(-1);
  assert.ok(found, `no 200 answer from ${endpoint}`);
  return found.json;
};

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
