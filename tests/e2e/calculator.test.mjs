// End-to-end test of the web calculator (GET /): Playwright (playwright-core) drives Debian's headless
// Chromium against a live cutcalc, written against the page's DOM contract (the page sections of
// the route table, `cutcalc --routes`, in its order; forms whose controls are named by the request's JSON Pointers;
// results carrying data-result/data-value; SVG diagrams whose parts carry data-role).
//
// Per section it fills the form with a reference case read at run time from ../shared/reference
// (the first 200-case whose request fields the form has), submits it (the groove section with the
// keyboard: focus a field, press Enter), and asserts
//   - the request the page sent carries the case's values;
//   - every shown number's data-value is the number the API returned, and equals the reference's
//     expected value within the reference's tolerance (numbers the reference does not list: the
//     API's answer to the same request, fetched from here);
//   - the displayed text is that value rounded (to the decimals shown) with its unit next to it;
//   - the diagrams have their parts (data-role) with non-empty geometry, the dimension texts of the
//     entry scheme match L_vr and X_n, the polygon has N vertices;
//   - polygon, grooving and flat: the program <pre> is the API's program, the Download program button
//     downloads a file (*.ngc, *.nc, *.MPF) whose content equals the API's text/plain answer to the
//     same request; grooving: the groove's dimension texts match W, h, B and X2, the pattern strip
//     draws the first revolutions; flat: the cross-section's dimension texts match d, w and D, the
//     tool at five steps, the step table has 2N + 1 rows, the magnified segment labels the flatness
//     error in µm;
//   - program time: the case's program goes into the text area and its machine into the Machine
//     fieldset; the velocity profile is drawn with the estimated and the nominal time.
// One invalid input (cutter diameter -5) must show the API's own message for that pointer next to
// the input, with aria-invalid and aria-describedby; a resubmit clears it. At 375 px and 1280 px,
// on the page's default values, every form is reached and submitted with the keyboard alone (Tab,
// Enter), and the page never scrolls sideways (checked after every section's result too).
// No console error, page error, failed request or unexpected HTTP error may occur (the one 4xx the
// invalid-input test provokes excepted).
//
// Environment:
//   CUTCALC_URL             base URL of the running cutcalc (required), e.g. http://127.0.0.1:8080
//   E2E_PAGE_URL            the page (default CUTCALC_URL + "/")
//   CUTCALC_REFERENCE_DIR   reference cases (default ../shared/reference, relative to the repo)
//   E2E_ARTIFACT_DIR        where the screenshots go (default build/e2e in the repo)
//   CHROMIUM_PATH           the browser (default /usr/bin/chromium; never downloaded)
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';

import { PAGE_SECTIONS, env, chromiumForThisFile, reference, repo } from './browser.mjs';

const API = (env('CUTCALC_URL') ?? '').replace(/\/$/, '');
if (!API) throw new Error('CUTCALC_URL is not set (the base URL of a running cutcalc)');
const PAGE_URL = env('E2E_PAGE_URL', `${API}/`);
const ARTIFACT_DIR = path.resolve(repo, env('E2E_ARTIFACT_DIR', path.join('build', 'e2e')));
const WAIT_MS = 20000; // one API answer plus rendering, on a busy two-core machine
const TEST_MS = 120000;

// ------------------------------------------------------------------ reference cases and tolerances

// Tolerance rules, as each reference file's `compare` states them.
const timeOrLength = tol => ptr => {
  const key = ptr.split('/').pop();
  return key.endsWith('_time_min') || key === 'main_time_min' ? tol.abs_min : tol.abs_mm;
};
const absOrRel = tol => (ptr, want) => Math.max(tol.abs, tol.rel * Math.abs(want));
const absPlusRel = tol => (ptr, want) => tol.abs + tol.rel * Math.abs(want);

// Documented request defaults: a case's field with this value may be left out when the form has no
// control for it (the API applies the same default).
const REQUEST_DEFAULTS = {
  '/offset_mm': 0,
  '/approach_mm': 2,
  '/extra_path_mm': 0,
  '/overrun_mm': 2,
  '/entry_feed_factor': 0.5,
  '/entry/angle_deg': 90,
  '/exit/angle_deg': 90,
  '/tool_feed_mm_per_min': 0,
  '/edge_inclination_deg': 0,
  '/tolerance_mm': 0.001,
  '/synchronization': 'feed_per_rev',
  '/safe_z_mm': 5,
  '/block_time_ms': 2,
};

const SECTIONS = [
  {
    id: 'entry',
    file: 'main-time.json',
    tolerance: c => timeOrLength(c.tolerance),
    // Prefer a single-pass case whose L_vr and X_n differ, so swapped dimension labels fail.
    // A straight path (L1 = 0), so that the page also writes the pass program.
    prefer: c => {
      if (Number(c.request.extra_path_mm ?? 0) > 0) return 2;
      const passes = c.expect.body.lateral_passes ?? [];
      const p = passes[0];
      return passes.length === 1 && p && Math.abs(p.entry_length_mm - p.start.x_mm) > 0.5 ? 0 : 1;
    },
    endpoints: {
      'main-time': '/v1/main-time',
      'entry-length': '/v1/entry-length',
      program: '/v1/main-time/program',
    },
    shown: {
      'main-time': ['/main_time_min'],
      'entry-length': ['/entry_length_mm'],
      program: ['/working_time_min', '/cycle_time_min'],
    },
    diagrams: {
      'entry-scheme': ['workpiece', 'contour', 'band', 'cutter-start', 'cutter-first-contact',
        'cutter-saturation', 'dimension-lvr', 'dimension-xn'],
      'exit-scheme': ['workpiece', 'contour', 'band', 'cutter-end'],
    },
  },
  {
    id: 'speeds',
    file: 'resultant-speeds.json',
    tolerance: c => absOrRel(c.tolerance),
    endpoints: { main: '/v1/resultant-speeds' },
    shown: { main: ['/engagement_half_angle_deg', '/points/0/resultant_speed_m_per_min'] },
    diagrams: { 'speed-vs-angle': ['curve-up', 'curve-down', 'axis-x', 'axis-y'] },
  },
  {
    id: 'groove',
    file: 'roughness-groove-wall.json',
    tolerance: c => absOrRel(c.tolerance),
    // With a target Rz the diagram also draws the target and the largest feed.
    prefer: c => (c.request.target_rz_um !== undefined ? 0 : 1),
    keyboard: true,
    endpoints: { main: '/v1/roughness/groove-wall' },
    shown: { main: ['/rz_um', '/ra_um'] },
    diagrams: { 'rz-vs-feed': ['curve', 'feed-marker'], 'bearing-curve': ['bearing-curve'] },
    targetDiagramRoles: ['target-line', 'max-feed-line'],
  },
  {
    id: 'bore',
    file: 'next/roughness-bore-milling.json',
    tolerance: c => absOrRel(c.tolerance),
    // With a target the page also shows the largest feed, and the plot the target and that feed.
    prefer: c => (c.request.target_cusp_um !== undefined ? 0 : 1),
    endpoints: { main: '/v1/roughness/bore-milling' },
    shown: { main: ['/cusp_height_um', '/max_feed_per_rev_mm'] },
    diagrams: { 'cusp-vs-feed': ['curve', 'feed-marker'] },
    targetField: 'target_cusp_um',
    targetDiagram: 'cusp-vs-feed',
    targetDiagramRoles: ['target-line', 'max-feed-line'],
  },
  {
    id: 'polygon',
    file: 'polygon-hole.json',
    tolerance: c => absPlusRel(c.tolerance),
    endpoints: { main: '/v1/polygon-hole/gcode' },
    shown: { main: ['/eccentricity_mm'] },
    diagrams: {
      'polygon-hole': ['polygon', 'centre-path', 'predicted-hole', 'rotor'],
      'polygon-corner': ['polygon', 'predicted-hole'],
      'polygon-rotor': ['rotor', 'corner-circle', 'neck-circle', 'corner-circle-diameter', 'neck-diameter', 'flank-radius', 'corner-angle'],
    },
    program: { arcs: true },
  },
  {
    id: 'grooving',
    file: 'next/grooving-cycle.json',
    tolerance: c => (ptr, want) => Math.max(c.tolerance.abs_min, c.tolerance.rel * Math.abs(want)),
    // A case with program options, so that the form's program fields are used too.
    prefer: c => (c.request.program !== undefined ? 0 : 1),
    endpoints: { main: '/v1/grooving/cycle' },
    shown: { main: ['/cycle_time_min', '/wall_rz_um', '/revolutions'] },
    diagrams: {
      'grooving-section': ['workpiece', 'groove', 'tool-start', 'tool-end', 'reference-point',
        'dimension-width', 'dimension-tool', 'dimension-shift', 'dimension-depth'],
      'grooving-pattern': ['pattern-walls', 'revolution', 'final-shift'],
    },
    program: { arcs: false },
  },
  {
    id: 'flat',
    file: 'next/lathe-flat.json',
    tolerance: c => absPlusRel(c.tolerance),
    // A case with program options, so that the form's program fields are used too.
    prefer: c => (c.request.program !== undefined ? 0 : 1),
    endpoints: { main: '/v1/lathe-flat' },
    shown: { main: ['/flatness_error_mm', '/machining_time_min', '/steps_table/0/c_deg'] },
    diagrams: {
      'flat-section': ['part', 'flats', 'flat-1', 'axis', 'tool-path', 'tool', 'dimension-axis-distance',
        'dimension-width', 'part-diameter'],
      'flat-spiral': ['flat-line', 'hump', 'step-start', 'step-end', 'dimension-flatness', 'exaggeration'],
    },
    program: { arcs: false },
  },
  {
    id: 'program-time',
    file: 'next/program-time.json',
    tolerance: c => absOrRel(c.tolerance),
    // The program goes into the text area; the machine into the Machine fieldset (page-wide).
    endpoints: { main: '/v1/program-time' },
    shown: { main: ['/estimated_time_min', '/nominal_time_min'] },
    diagrams: { 'velocity-profile': ['profile', 'estimated-time', 'nominal-time', 'axis-x', 'axis-y'] },
  },
];

// ------------------------------------------------------------------ small helpers
function pointerGet(doc, ptr) {
  if (ptr === '') return doc;
  let cur = doc;
  for (const raw of ptr.slice(1).split('/')) {
    const key = raw.replace(/~1/g, '/').replace(/~0/g, '~');
    if (cur === null || typeof cur !== 'object' || !(key in cur)) return undefined;
    cur = cur[key];
  }
  return cur;
}

// Request leaves as JSON Pointer -> scalar; null when the request has a list (no form control can
// take a whole list by the contract's rule of one control per field).
function leaves(obj, prefix = '', out = new Map()) {
  for (const [k, v] of Object.entries(obj)) {
    const ptr = `${prefix}/${k.replace(/~/g, '~0').replace(/\//g, '~1')}`;
    if (Array.isArray(v)) return null;
    if (v !== null && typeof v === 'object') {
      if (leaves(v, ptr, out) === null) return null;
    } else out.set(ptr, v);
  }
  return out;
}

// The unit a response field's name states, as the patterns a page may show it by.
function unitPattern(ptr) {
  const key = ptr.split('/').pop();
  const units = [
    ['_mm_per_min', /mm\s*\/\s*min/],
    ['_m_per_min', /(^|[^m])m\s*\/\s*min/],
    ['_mm_per_rev', /mm\s*\/\s*rev/],
    ['_mm_per_tooth', /mm/],
    ['_mm2', /mm\s*(²|2|\^2)/],
    ['_mm', /mm/],
    ['_um', /(µm|μm|um)/],
    ['_deg', /(°|deg)/],
    ['_rpm', /(rpm|min\s*(⁻¹|-1|\^-1)|1\s*\/\s*min|rev\s*\/\s*min)/],
    ['_min', /min/],
    ['_ms', /ms/],
  ];
  for (const [suffix, re] of units) if (key.endsWith(suffix)) return { suffix, re };
  return null;
}

// The first number in a displayed text, with what its rounding allows.
function shownNumber(text) {
  const t = text.replace(/\u2212/g, '-').replace(/(\d)[\u2009\u202f\u00a0 ](?=\d{3}\b)/g, '$1');
  const m = /[-+]?\d+(?:\.(\d+))?(?:[eE]([-+]?\d+))?/.exec(t);
  if (!m) return null;
  const decimals = m[1] ? m[1].length : 0;
  const exponent = m[2] ? Number(m[2]) : 0;
  return { value: Number(m[0]), text: m[0], halfStep: 0.5 * 10 ** (exponent - decimals) };
}

function numbersIn(text) {
  const t = text.replace(/\u2212/g, '-');
  return [...t.matchAll(/[-+]?\d+(?:\.(\d+))?/g)].map(m => ({
    value: Number(m[0]),
    halfStep: 0.5 * 10 ** -(m[1] ? m[1].length : 0),
  }));
}

async function apiPost(endpoint, bodyText, accept = 'application/json') {
  const response = await fetch(`${API}${endpoint}`, {
    method: 'POST',
    headers: { 'content-type': 'application/json', accept },
    body: bodyText,
  });
  const text = await response.text();
  return { status: response.status, headers: response.headers, text };
}

const cssString = s => JSON.stringify(s); // a quoted CSS string for attribute selectors

// ------------------------------------------------------------------ page observation
// Records every exchange with the API and every sign of trouble on a page.
function observe(page, label) {
  const log = { exchanges: [], problems: [], allowed4xx: false };
  page.on('console', msg => {
    if (msg.type() !== 'error') return;
    const text = msg.text();
    // Chromium logs every 4xx fetch as "Failed to load resource"; the invalid-input test expects one.
    if (log.allowed4xx && /status of 4\d\d/.test(text)) return;
    log.problems.push(`${label}: console error: ${text} (${msg.location().url ?? ''})`);
  });
  page.on('pageerror', error => log.problems.push(`${label}: page error: ${error.message}`));
  page.on('requestfailed', request => {
    log.problems.push(`${label}: request failed: ${request.method()} ${request.url()}: ${request.failure()?.errorText}`);
  });
  page.on('response', response => {
    const request = response.request();
    const url = new URL(response.url());
    const status = response.status();
    if (url.pathname.startsWith('/v1/') && request.method() === 'POST') {
      const accept = request.headers().accept ?? '';
      const entry = { path: url.pathname, status, accept, requestBody: request.postData() ?? '', json: null };
      entry.ready = response
        .text()
        .then(text => {
          entry.text = text;
          try {
            entry.json = JSON.parse(text);
          } catch {
            entry.json = null;
          }
        })
        .catch(() => {});
      log.exchanges.push(entry);
      if (status >= 400 && !(log.allowed4xx && status < 500)) {
        const problem = `${label}: unexpected HTTP ${status} from ${request.method()} ${url.pathname} ${entry.requestBody}`;
        log.problems.push(problem);
        entry.ready.then(() => {
          const i = log.problems.indexOf(problem);
          if (i >= 0) log.problems[i] = `${problem} -> ${(entry.text ?? '').slice(0, 300)}`;
        });
      }
    } else if (status >= 400) {
      log.problems.push(`${label}: HTTP ${status} for ${request.method()} ${response.url()}`);
    }
  });
  return log;
}

// The exchange that carries a section's result among the page's requests to one endpoint: a 200
// JSON answer whose request has the values the form was filled with (the main endpoint), and of
// those the one with the fewest other fields (the speeds section also asks the same endpoint for
// the arc samples of its diagram; those requests carry an extra field).
function pick(exchanges, endpoint, filled) {
  const candidates = exchanges.filter(e => {
    if (e.path !== endpoint || e.status !== 200 || /text\/plain/.test(e.accept)) return false;
    if (!filled) return true;
    let body;
    try {
      body = JSON.parse(e.requestBody);
    } catch {
      return false;
    }
    return [...filled].every(([ptr, value]) => pointerGet(body, ptr) === value);
  });
  const extra = e => {
    try {
      return Object.keys(JSON.parse(e.requestBody)).filter(k => !filled || ![...filled.keys()].some(p => p === `/${k}` || p.startsWith(`/${k}/`))).length;
    } catch {
      return Infinity;
    }
  };
  return candidates.sort((a, b) => extra(a) - extra(b))[0];
}

// Runs `action`, waits for a 200 answer from each endpoint (the first endpoint's request carrying
// `filled`), then for the page's requests to settle (its diagrams may need more of them), and
// returns the exchange per source. Fails early when an endpoint answered only with an error.
async function exchangesFor(log, endpoints, action, filled = null) {
  const start = log.exchanges.length;
  await action();
  const wanted = Object.entries(endpoints);
  const mainKey = wanted[0][0];
  const fresh = () => log.exchanges.slice(start);
  const choose = () =>
    Object.fromEntries(wanted.map(([key, endpoint]) => [key, pick(fresh(), endpoint, key === mainKey ? filled : null)]));
  const deadline = Date.now() + WAIT_MS;
  let firstError = null;
  for (;;) {
    const found = choose();
    if (wanted.every(([key]) => found[key])) break;
    const error = fresh().find(e => e.status >= 400 && !wanted.some(([key, ep]) => found[key] && ep === e.path));
    if (error && firstError === null) firstError = Date.now();
    const seen = () => fresh().map(e => `${e.path} ${e.status} ${e.requestBody.slice(0, 300)} -> ${(e.text ?? '').slice(0, 300)}`);
    if (firstError !== null && Date.now() - firstError > 3000) {
      await Promise.all(fresh().map(e => e.ready));
      assert.fail(`an error answer and no 200 from ${wanted.map(([, e]) => e).join(' and ')}: ${seen().join(' | ')}`);
    }
    if (Date.now() > deadline) {
      assert.fail(`no 200 answer from ${wanted.map(([, e]) => e).join(' and ')} within ${WAIT_MS} ms of submitting (seen: ${seen().join(' | ') || 'none'})`);
    }
    await new Promise(resolve => setTimeout(resolve, 50));
  }
  // Settle: no new request for 500 ms (at most 10 s).
  const settleEnd = Date.now() + 10000;
  let count = log.exchanges.length;
  let quietSince = Date.now();
  while (Date.now() - quietSince < 500 && Date.now() < settleEnd) {
    await new Promise(resolve => setTimeout(resolve, 50));
    if (log.exchanges.length !== count) {
      count = log.exchanges.length;
      quietSince = Date.now();
    }
  }
  await Promise.all(fresh().map(e => e.ready));
  return choose();
}

// Waits until the result area shows, for each source, the listed pointers with the API's values.
async function waitForResults(page, section, bySource) {
  const expected = [];
  for (const [source, pointers] of Object.entries(section.shown)) {
    for (const ptr of pointers) expected.push({ source, ptr, value: pointerGet(bySource[source].json, ptr) });
  }
  try {
    await page.waitForFunction(
      ({ id, expected, multiSource }) => {
        const root = document.getElementById(`${id}-result`);
        if (!root) return false;
        return expected.every(({ source, ptr, value }) =>
          [...root.querySelectorAll('[data-result]')].some(
            el =>
              el.getAttribute('data-result') === ptr &&
              (!multiSource || el.closest('[data-source]')?.getAttribute('data-source') === source) &&
              Number(el.getAttribute('data-value')) === value,
          ),
        );
      },
      { id: section.id, expected, multiSource: Object.keys(section.shown).length > 1 },
      { timeout: WAIT_MS },
    );
  } catch (error) {
    const shown = await resultElements(page, section.id);
    assert.fail(
      `#${section.id}-result does not show ${expected.map(e => `${e.ptr} (${e.source}) = ${e.value}`).join(', ')} ` +
        `within ${WAIT_MS} ms; it shows: ${JSON.stringify(shown.map(s => [s.source, s.ptr, s.value, s.text]))} (${error.message.split('\n')[0]})`,
    );
  }
}

async function resultElements(page, id) {
  return page.evaluate(id => {
    const root = document.getElementById(`${id}-result`);
    if (!root) return [];
    return [...root.querySelectorAll('[data-result]')].map(el => {
      let header = '';
      const cell = el.closest('td,th');
      const table = el.closest('table');
      if (cell && table) {
        const index = [...cell.parentElement.children].indexOf(cell);
        const headRow = table.querySelector('thead tr') ?? table.querySelector('tr');
        header = headRow?.children[index]?.textContent ?? '';
      }
      const rowHeader = el.closest('tr')?.querySelector('th')?.textContent ?? '';
      return {
        ptr: el.getAttribute('data-result'),
        value: el.getAttribute('data-value'),
        source: el.closest('[data-source]')?.getAttribute('data-source') ?? null,
        text: el.textContent,
        context: [el.parentElement?.textContent ?? '', header, rowHeader, el.getAttribute('aria-label') ?? ''],
        visible: !!(el.offsetWidth || el.offsetHeight || el.getClientRects().length),
      };
    });
  }, id);
}

// ------------------------------------------------------------------ filling a form
// Fills the section's form with a case's request; returns the leaves filled, or a reason the form
// does not fit the case (a field without a visible, enabled control).
async function fillWithCase(page, sectionId, request) {
  const all = leaves(request);
  if (all === null) return { unfit: 'the request has a list' };
  const form = page.locator(`#${sectionId}-form`);
  // Back to the page's defaults, and let the page react to the selects (visibility of fields).
  await form.evaluate(f => {
    f.reset();
    for (const s of f.querySelectorAll('select')) s.dispatchEvent(new Event('change', { bubbles: true }));
  });
  const controls = async () =>
    form.evaluate(f =>
      [...f.querySelectorAll('input[name], select[name], textarea[name]')].map(c => ({
        name: c.getAttribute('name'),
        tag: c.tagName.toLowerCase(),
        type: (c.getAttribute('type') ?? '').toLowerCase(),
        value: c.value,
        usable: !c.disabled && !!(c.offsetWidth || c.offsetHeight || c.getClientRects().length) && c.type !== 'hidden',
      })),
    );
  const filled = new Map();
  // Selects first (a contour type may show or hide its fields), then the others.
  for (const [ptr, value] of all) {
    const select = (await controls()).find(c => c.name === ptr && c.tag === 'select' && c.usable);
    if (!select) continue;
    try {
      await form.locator(`select[name=${cssString(ptr)}]`).selectOption(String(value), { timeout: 2000 });
    } catch {
      return { unfit: `select ${ptr} has no option ${value}` };
    }
    filled.set(ptr, value);
  }
  const now = await controls();
  for (const [ptr, value] of all) {
    if (filled.has(ptr)) continue;
    const mine = now.filter(c => c.name === ptr && c.usable);
    if (mine.length === 0) {
      if (ptr in REQUEST_DEFAULTS && REQUEST_DEFAULTS[ptr] === value) continue;
      return { unfit: `no visible control named ${ptr}` };
    }
    if (mine[0].type === 'radio') {
      const radio = form.locator(`input[name=${cssString(ptr)}][value=${cssString(String(value))}]`);
      if ((await radio.count()) !== 1) return { unfit: `no radio ${ptr} = ${value}` };
      await radio.check();
    } else if (mine[0].type === 'checkbox') {
      await form.locator(`input[name=${cssString(ptr)}]`).setChecked(Boolean(value));
    } else {
      // A text input, or a text area (a program to time).
      await form.locator(`${mine[0].tag}[name=${cssString(ptr)}]`).fill(String(value));
    }
    filled.set(ptr, value);
  }
  // Every other visible text or number field is emptied: left out of the request, the API default.
  for (const c of now) {
    if (filled.has(c.name) || c.tag !== 'input' || !c.usable) continue;
    if (['radio', 'checkbox', 'button', 'submit', 'reset', 'hidden'].includes(c.type)) continue;
    await form.locator(`input[name=${cssString(c.name)}]`).fill('');
  }
  return { filled };
}

async function fillWithFirstFittingCase(page, section) {
  const data = reference(section.file);
  // The form's defaults: a case that differs from them shows that the filled values are sent.
  const defaults = await page.locator(`#${section.id}-form`).evaluate(f => {
    f.reset();
    return Object.fromEntries([...f.querySelectorAll('input[name], select[name], textarea[name]')].map(c => [c.getAttribute('name'), c.value]));
  });
  const differs = c =>
    [...(leaves(c.request) ?? new Map())].some(
      ([ptr, value]) => ptr in defaults && String(value) !== defaults[ptr] && Number(defaults[ptr]) !== value,
    );
  const rank = c => (section.prefer ? section.prefer(c) : 0) * 2 + (differs(c) ? 0 : 1);
  const cases = data.cases.filter(c => c.expect.status === 200).sort((a, b) => rank(a) - rank(b));
  const reasons = [];
  for (const c of cases) {
    const result = await fillWithCase(page, section.id, c.request);
    if (result.filled) return { kase: c, filled: result.filled };
    reasons.push(`${c.id}: ${result.unfit}`);
  }
  assert.fail(`#${section.id}-form fits no 200-case of ${section.file}: ${reasons.join('; ')}`);
}

// ------------------------------------------------------------------ checks
function checkSentRequest(section, exchange, filled) {
  let sent;
  try {
    sent = JSON.parse(exchange.requestBody);
  } catch {
    assert.fail(`${section.id}: the page sent a body that is not JSON: ${exchange.requestBody.slice(0, 200)}`);
  }
  for (const [ptr, value] of filled) {
    const got = pointerGet(sent, ptr);
    assert.ok(
      got === value || (typeof value === 'number' && Number(got) === value && typeof got === 'number'),
      `${section.id}: the page sent ${ptr} = ${JSON.stringify(got)}, the form was filled with ${JSON.stringify(value)} (body ${exchange.requestBody})`,
    );
  }
  return sent;
}

// Every shown number: data-value is the API's number; it equals the reference within tolerance
// (or the API's answer to the same request, fetched from here, for fields the reference does not
// list); the text is that number rounded, with its unit.
async function checkShownNumbers(page, section, { bySource, referenceBodies, tolerance, direct }) {
  const shown = (await resultElements(page, section.id)).filter(s => s.visible);
  const multiSource = Object.keys(section.shown).length > 1;
  let checkedAgainstReference = 0;
  for (const s of shown) {
    const source = multiSource ? s.source : Object.keys(section.shown)[0];
    const where = `#${section.id}-result [data-result="${s.ptr}"]${multiSource ? ` (data-source ${s.source})` : ''}`;
    assert.ok(source in bySource, `${where}: data-source must be one of ${Object.keys(bySource).join(', ')}`);
    const apiValue = pointerGet(bySource[source].json, s.ptr);
    assert.notEqual(apiValue, undefined, `${where}: the API's response has no ${s.ptr}`);
    assert.notEqual(s.value, null, `${where}: no data-value attribute`);
    if (typeof apiValue === 'string') {
      assert.equal(s.value, apiValue, `${where}: data-value`);
      assert.ok(s.text.includes(apiValue) || s.text.trim().length > 0, `${where}: shows nothing`);
      continue;
    }
    assert.equal(typeof apiValue, 'number', `${where}: points at a ${typeof apiValue}, not a number`);
    const value = Number(s.value);
    assert.equal(value, apiValue, `${where}: data-value ${s.value} is not the API's ${apiValue}`);
    // Against the reference (or the API's answer to the same request, fetched directly).
    const refBody = referenceBodies[source];
    const want = refBody ? pointerGet(refBody, s.ptr) : undefined;
    if (typeof want === 'number') {
      const tol = tolerance(s.ptr, want);
      assert.ok(Math.abs(value - want) <= tol, `${where}: ${value} differs from the reference ${want} by more than ${tol}`);
      checkedAgainstReference += 1;
    } else {
      const directValue = pointerGet(direct[source], s.ptr);
      assert.equal(typeof directValue, 'number', `${where}: the API's direct answer has no number at ${s.ptr}`);
      const tol = tolerance(s.ptr, directValue);
      assert.ok(Math.abs(value - directValue) <= tol, `${where}: ${value} differs from the API's direct answer ${directValue}`);
    }
    // Displayed text: the value rounded, with its unit next to it.
    const number = shownNumber(s.text);
    assert.ok(number, `${where}: the text "${s.text}" shows no number`);
    const allowed = number.halfStep * (1 + 1e-9) + 1e-12 * Math.abs(value);
    assert.ok(
      Math.abs(number.value - value) <= allowed,
      `${where}: the text "${s.text.trim()}" is not ${value} rounded to the decimals shown`,
    );
    const unit = unitPattern(s.ptr);
    if (unit) {
      const places = [s.text, ...s.context];
      assert.ok(
        places.some(t => unit.re.test(t)),
        `${where}: no unit (${unit.suffix}) in "${s.text.trim()}" nor next to it ("${s.context[0].trim().slice(0, 120)}")`,
      );
    }
  }
  return { shown, checkedAgainstReference };
}

// The parts of a diagram: data-role elements with non-empty geometry. Returns per role the problems
// found and the texts inside.
async function diagramParts(page, sectionId, diagram, roles) {
  return page.evaluate(
    ({ sectionId, diagram, roles }) => {
      const section = document.getElementById(sectionId);
      const svgs = section ? [...section.querySelectorAll(`svg[data-diagram="${diagram}"]`)] : [];
      if (svgs.length !== 1) {
        const said = (document.getElementById(`${sectionId}-result`)?.textContent ?? '').replace(/\s+/g, ' ').trim();
        return { error: `${svgs.length} svg[data-diagram="${diagram}"] in #${sectionId} (its result area ends: "${said.slice(-160)}")` };
      }
      const svg = svgs[0];
      const rect = svg.getBoundingClientRect();
      const num = (el, a) => Number(el.getAttribute(a) ?? 0);
      const problemOf = el => {
        const tag = el.tagName.toLowerCase();
        if (/NaN|Infinity|undefined/.test(el.outerHTML)) return 'NaN, Infinity or undefined in its markup';
        if (tag === 'polyline' || tag === 'polygon') {
          const nums = (el.getAttribute('points') ?? '').trim().split(/[\s,]+/).filter(Boolean).map(Number);
          if (nums.length % 2 || nums.some(n => !Number.isFinite(n))) return 'points are not number pairs';
          const need = tag === 'polygon' ? 3 : 2;
          if (nums.length / 2 < need) return `${nums.length / 2} points`;
          const box = el.getBBox();
          if (!(box.width > 0 || box.height > 0)) return 'all points coincide';
          return null;
        }
        if (tag === 'path') {
          if (!/\d/.test(el.getAttribute('d') ?? '')) return 'empty d';
          return el.getTotalLength() > 0 ? null : 'zero length';
        }
        if (tag === 'circle') return num(el, 'r') > 0 ? null : `r = ${el.getAttribute('r')}`;
        if (tag === 'ellipse') return num(el, 'rx') > 0 && num(el, 'ry') > 0 ? null : 'zero radius';
        if (tag === 'line') {
          const length = Math.hypot(num(el, 'x2') - num(el, 'x1'), num(el, 'y2') - num(el, 'y1'));
          return length > 0 ? null : 'zero length';
        }
        if (tag === 'rect') return num(el, 'width') > 0 && num(el, 'height') > 0 ? null : 'zero size';
        if (tag === 'text' || tag === 'tspan') return el.textContent.trim() ? null : 'empty text';
        const shapes = el.querySelectorAll('polyline,polygon,path,circle,ellipse,line,rect,text,use');
        const problems = [...shapes].map(problemOf);
        if (shapes.length === 0) return `<${tag}> without shapes`;
        return problems.some(p => p === null) ? null : `no drawn shape inside (${problems.join('; ')})`;
      };
      const parts = {};
      for (const role of roles) {
        const els = [...svg.querySelectorAll(`[data-role="${role}"]`)];
        parts[role] = els.map(el => ({
          tag: el.tagName.toLowerCase(),
          problem: problemOf(el),
          texts: el.tagName.toLowerCase() === 'text' ? [el.textContent] : [...el.querySelectorAll('text')].map(t => t.textContent),
          points: (el.getAttribute('points') ?? '').trim().split(/[\s,]+/).filter(Boolean).length / 2,
        }));
      }
      return {
        title: svg.querySelector(':scope > title')?.textContent?.trim() ?? '',
        role: svg.getAttribute('role'),
        width: rect.width,
        height: rect.height,
        parts,
      };
    },
    { sectionId, diagram, roles },
  );
}

async function checkDiagrams(page, section, diagrams) {
  const found = {};
  for (const [diagram, roles] of Object.entries(diagrams)) {
    // A diagram may be drawn after the section's numbers (it can need requests of its own).
    await page
      .waitForFunction(
        ({ id, diagram, roles }) => {
          const svg = document.querySelector(`#${id} svg[data-diagram="${diagram}"]`);
          return !!svg && roles.every(role => svg.querySelector(`[data-role="${role}"]`));
        },
        { id: section.id, diagram, roles },
        { timeout: WAIT_MS },
      )
      .catch(() => {}); // diagramParts says what is missing
    const d = await diagramParts(page, section.id, diagram, roles);
    assert.ok(!d.error, `${section.id}: ${d.error}`);
    assert.ok(d.title, `${diagram}: no <title>`);
    assert.equal(d.role, 'img', `${diagram}: role`);
    assert.ok(d.width > 0 && d.height > 0, `${diagram}: not rendered (${d.width} x ${d.height})`);
    for (const role of roles) {
      const els = d.parts[role];
      assert.ok(els.length > 0, `${diagram}: no [data-role="${role}"]`);
      for (const el of els) assert.equal(el.problem, null, `${diagram} [data-role="${role}"] <${el.tag}>: ${el.problem}`);
    }
    found[diagram] = d;
  }
  return found;
}

function assertDimension(diagram, role, parts, want, label) {
  const texts = parts[role].flatMap(p => p.texts);
  assert.ok(texts.length > 0, `${diagram} [data-role="${role}"]: no <text>`);
  const ok = texts.some(t =>
    numbersIn(t).some(n => Math.abs(n.value - want) <= n.halfStep * (1 + 1e-9) + 1e-9),
  );
  assert.ok(ok, `${diagram} [data-role="${role}"]: text ${JSON.stringify(texts)} does not show ${label} = ${want}`);
}

// ------------------------------------------------------------------ the browser
const browser = chromiumForThisFile();
before(() => mkdirSync(ARTIFACT_DIR, { recursive: true }));

async function openPage(viewport, label) {
  const context = await browser().newContext({ viewport, acceptDownloads: true });
  const page = await context.newPage();
  page.setDefaultTimeout(WAIT_MS);
  const log = observe(page, label);
  const response = await page.goto(PAGE_URL, { waitUntil: 'load' });
  assert.equal(response?.status(), 200, `GET ${PAGE_URL}`);
  return { context, page, log };
}

async function noHorizontalScroll(page, width) {
  const { scrollWidth, wide } = await page.evaluate(width => {
    // The outermost elements that reach past the right edge, to say what overflows.
    const describe = el =>
      `${el.tagName.toLowerCase()}${el.id ? `#${el.id}` : ''}${[...el.classList].map(c => `.${c}`).join('')}` +
      `${el.dataset.diagram ? `[data-diagram=${el.dataset.diagram}]` : ''}${el.dataset.role ? `[data-role=${el.dataset.role}]` : ''}` +
      ` "${el.textContent.replace(/\s+/g, ' ').trim().slice(0, 60)}" (right ${Math.round(el.getBoundingClientRect().right + window.scrollX)})`;
    const clipped = el => {
      for (let a = el.parentElement; a && a !== document.body; a = a.parentElement) {
        if (getComputedStyle(a).overflowX !== 'visible') return true;
      }
      return false;
    };
    const over = [...document.body.querySelectorAll('*')].filter(
      el => el.getBoundingClientRect().right + window.scrollX > width + 0.5 && !clipped(el),
    );
    const outermost = over.filter(el => !over.includes(el.parentElement));
    return { scrollWidth: document.scrollingElement.scrollWidth, wide: outermost.slice(0, 5).map(describe) };
  }, width);
  assert.ok(
    scrollWidth <= width,
    `the page scrolls horizontally at ${width} px: scrollWidth ${scrollWidth}; reaching past the edge: ${wide.join(', ')}`,
  );
}

// ================================================================== 1280 px
describe('calculator page at 1280 px', () => {
  let page;
  let context;
  let log;
  before(async () => {
    ({ page, context, log } = await openPage({ width: 1280, height: 900 }, '1280px'));
  });
  after(async () => {
    await context?.close();
  });

  test('the route table\'s sections in order, a nav to them, forms with labelled controls', { timeout: TEST_MS }, async () => {
    assert.deepEqual(SECTIONS.map(s => s.id), PAGE_SECTIONS, 'a case here for every page section of the route table (cutcalc --routes), in its order');
    const layout = await page.evaluate(() => {
      const sections = [...document.querySelectorAll('section[id]')].map(s => ({
        id: s.id,
        labelledby: s.getAttribute('aria-labelledby'),
        title: document.getElementById(`${s.id}-title`)?.tagName ?? null,
        forms: [...s.querySelectorAll('form')].map(f => ({ id: f.id, novalidate: f.hasAttribute('novalidate') })),
        submits: [...s.querySelectorAll('form button[type="submit"]')].map(b => b.textContent.trim()),
        result: !!document.getElementById(`${s.id}-result`),
        resultLive: document.getElementById(`${s.id}-result`)?.getAttribute('aria-live') ?? null,
        controls: [...s.querySelectorAll('form input[name], form select[name]')]
          .filter(c => c.type !== 'hidden')
          .map(c => ({
            name: c.getAttribute('name'),
            id: c.id,
            label: c.id ? (document.querySelector(`label[for="${CSS.escape(c.id)}"]`)?.textContent.trim() ?? null) : null,
          })),
      }));
      const navTargets = [...document.querySelectorAll('nav a[href^="#"]')].map(a => a.getAttribute('href').slice(1));
      const ids = [...document.querySelectorAll('[id]')].map(e => e.id);
      const download = document.getElementById('polygon-download');
      return {
        sections,
        navTargets,
        duplicateIds: ids.filter((id, i) => ids.indexOf(id) !== i),
        download: download
          ? { type: download.getAttribute('type'), text: download.textContent.trim(), disabled: download.disabled }
          : null,
        program: document.getElementById('polygon-program')?.tagName ?? null,
      };
    });
    const wanted = PAGE_SECTIONS;
    assert.deepEqual(
      layout.sections.map(s => s.id).filter(id => wanted.includes(id)),
      wanted,
      `the ${wanted.length} sections of the route table, in its order`,
    );
    for (const id of wanted) assert.ok(layout.navTargets.includes(id), `the nav has no link to #${id}`);
    assert.deepEqual(layout.duplicateIds, [], 'ids must be unique');
    for (const s of layout.sections.filter(x => wanted.includes(x.id))) {
      assert.equal(s.labelledby, `${s.id}-title`, `#${s.id} aria-labelledby`);
      assert.equal(s.title, 'H2', `#${s.id}-title must be an <h2>`);
      assert.deepEqual(s.forms, [{ id: `${s.id}-form`, novalidate: true }], `#${s.id}: one <form id="${s.id}-form" novalidate>`);
      assert.deepEqual(s.submits, ['Calculate'], `#${s.id}-form: one submit button "Calculate"`);
      assert.ok(s.result, `no #${s.id}-result`);
      assert.equal(s.resultLive, 'polite', `#${s.id}-result aria-live`);
      assert.ok(s.controls.length > 0, `#${s.id}-form has no named controls`);
      for (const c of s.controls) {
        assert.match(c.name, /^(\/[a-z0-9_]+)+$/, `#${s.id}-form: control name "${c.name}" is not a JSON Pointer`);
        assert.ok(c.id, `#${s.id}-form: control ${c.name} has no id`);
        // Radio groups are labelled per option; everything else names its quantity.
        assert.ok(c.label, `#${s.id}-form: control ${c.name} (#${c.id}) has no <label for>`);
      }
    }
    // Enabled once the page's first calculation of the defaults has a program.
    assert.deepEqual({ ...layout.download, disabled: undefined }, { type: 'button', text: 'Download program', disabled: undefined }, '#polygon-download');
    assert.equal(layout.program, 'PRE', '#polygon-program must be a <pre>');
    // Labels name quantity, symbol and unit (e.g. "Cutter diameter D, mm").
    const entry = layout.sections.find(s => s.id === 'entry');
    const diameter = entry.controls.find(c => c.name === '/cutter_diameter_mm');
    assert.ok(diameter, '#entry-form has no control named /cutter_diameter_mm');
    assert.match(diameter.label, /diameter.*D.*mm/i, 'the cutter diameter label names quantity, symbol and unit');
    await noHorizontalScroll(page, 1280);
  });

  test('entry: an invalid cutter diameter shows the API message at its input', { timeout: TEST_MS }, async () => {
    const section = SECTIONS[0];
    const form = page.locator('#entry-form');
    const input = form.locator('[name="/cutter_diameter_mm"]');
    const inputId = await input.getAttribute('id');
    await input.fill('-5');
    log.allowed4xx = true;
    let found;
    const start = log.exchanges.length;
    try {
      await form.locator('button[type="submit"]').click();
      // At least one of the two endpoints answers 422 (the page may stop after the first).
      const deadline = Date.now() + WAIT_MS;
      while (!log.exchanges.slice(start).some(e => e.status === 422)) {
        assert.ok(Date.now() < deadline, `no 422 from ${Object.values(section.endpoints).join(' or ')} after submitting -5`);
        await new Promise(resolve => setTimeout(resolve, 50));
      }
      found = log.exchanges.slice(start).find(e => e.status === 422);
      await found.ready;
      await page.waitForSelector(`#${cssId(inputId)}-error`, { state: 'attached', timeout: WAIT_MS });
      await page.waitForFunction(id => (document.getElementById(`${id}-error`)?.textContent ?? '').trim() !== '', inputId);
    } finally {
      await new Promise(resolve => setTimeout(resolve, 300)); // let Chromium log the 4xx first
      log.allowed4xx = false;
    }
    // The API's own message for the request the page sent.
    const direct = await apiPost(found.path, found.requestBody);
    assert.equal(direct.status, 422, `the API answers ${direct.status} to ${found.requestBody}`);
    const problem = JSON.parse(direct.text);
    const item = (problem.errors ?? []).find(e => e.pointer === '/cutter_diameter_mm');
    assert.ok(item, `the API's errors[] has no /cutter_diameter_mm item: ${direct.text}`);
    const message = item.detail ?? item.message;
    const state = await page.evaluate(id => {
      const input = document.getElementById(id);
      const error = document.getElementById(`${id}-error`);
      return {
        text: error?.textContent.trim(),
        tag: error?.tagName,
        className: error?.className,
        rightAfter: input?.nextElementSibling === error,
        after: !!(input && error && input.compareDocumentPosition(error) & Node.DOCUMENT_POSITION_FOLLOWING),
        invalid: input?.getAttribute('aria-invalid'),
        describedby: (input?.getAttribute('aria-describedby') ?? '').split(/\s+/),
        visible: !!(error && (error.offsetWidth || error.offsetHeight)),
        formError: [...input.form.querySelectorAll('.form-error[role="alert"]')].map(e => ({
          text: e.textContent,
          visible: !!(e.offsetWidth || e.offsetHeight),
          first: e === input.form.firstElementChild,
        })),
      };
    }, inputId);
    assert.equal(state.text, message, `#${inputId}-error shows the API's message verbatim`);
    assert.match(message, /> ?0|positive|greater/i, 'a "must be > 0"-style message');
    assert.equal(state.tag, 'P', `#${inputId}-error is a <p>`);
    assert.ok(state.className.split(/\s+/).includes('field-error'), `#${inputId}-error has class field-error`);
    assert.ok(state.rightAfter, `#${inputId}-error is right after the input (next element sibling)`);
    assert.ok(state.visible, `#${inputId}-error is visible`);
    assert.equal(state.invalid, 'true', `#${inputId} aria-invalid`);
    assert.ok(state.describedby.includes(`${inputId}-error`), `#${inputId} aria-describedby names the message`);
    // The problem's detail goes to the form's alert at its top.
    assert.equal(state.formError.length, 1, '#entry-form has one <div class="form-error" role="alert">');
    const [box] = state.formError;
    assert.ok(box.first, 'the form error box is at the top of the form (its first element)');
    assert.ok(box.visible, 'the form error box is visible');
    assert.ok(box.text.includes(problem.detail), `the form error box "${box.text}" shows the problem's detail "${problem.detail}"`);
  });

  for (const section of SECTIONS) {
    const how = section.keyboard ? ' (submitted with Enter in a field)' : '';
    test(`${section.id}: a reference case gives the reference numbers and draws its diagrams${how}`, { timeout: TEST_MS }, async () => {
      await page.locator(`#${section.id}`).scrollIntoViewIfNeeded();
      const { kase, filled } = await fillWithFirstFittingCase(page, section);
      const form = page.locator(`#${section.id}-form`);
      const bySource = await exchangesFor(log, section.endpoints, async () => {
        if (section.keyboard) {
          const firstFilled = [...filled.keys()][0];
          await form.locator(`[name=${cssString(firstFilled)}]`).focus();
          await page.keyboard.press('Enter');
        } else {
          await form.locator('button[type="submit"]').click();
        }
      }, filled);
      for (const [source, e] of Object.entries(bySource)) {
        assert.equal(e.status, 200, `${section.id} (${kase.id}): ${e.path} answered ${e.status}: ${e.text?.slice(0, 300)}`);
      }
      // The main request carries the case's values (the entry-length request is derived by the page).
      const mainSource = Object.keys(section.endpoints)[0];
      checkSentRequest(section, bySource[mainSource], filled);
      await waitForResults(page, section, bySource);

      // The API's answers to the same requests, fetched from here.
      const direct = {};
      for (const [source, e] of Object.entries(bySource)) {
        const answer = await apiPost(e.path, e.requestBody);
        assert.equal(answer.status, 200, `${e.path} directly: ${answer.status}`);
        direct[source] = JSON.parse(answer.text);
      }
      const { shown, checkedAgainstReference } = await checkShownNumbers(page, section, {
        bySource,
        referenceBodies: { [mainSource]: kase.expect.body },
        tolerance: section.tolerance(kase),
        direct,
      });
      assert.ok(checkedAgainstReference >= 1, `${section.id}: no shown number is in the reference case ${kase.id}`);

      // Field errors from before are gone.
      const stale = await form.evaluate(f => ({
        invalid: [...f.querySelectorAll('[aria-invalid="true"]')].map(e => e.getAttribute('name')),
        errors: [...f.querySelectorAll('.field-error, .form-error')].map(e => e.textContent.trim()).filter(Boolean),
      }));
      assert.deepEqual(stale, { invalid: [], errors: [] }, `${section.id}: errors left after a valid submit`);

      // Diagrams.
      const diagrams = { ...section.diagrams };
      const targetDiagram = section.targetDiagram ?? 'rz-vs-feed';
      if (section.targetDiagramRoles && kase.request[section.targetField ?? 'target_rz_um'] !== undefined) {
        diagrams[targetDiagram] = [...diagrams[targetDiagram], ...section.targetDiagramRoles];
      }
      const drawn = await checkDiagrams(page, section, diagrams);
      if (section.id === 'entry') {
        // The pass program under the main-time results (POST /v1/main-time/program), as the
        // service wrote it, with its download button.
        const program = await page.evaluate(() => ({
          text: document.querySelector('#entry-program')?.textContent ?? '',
          download: document.querySelector('#entry-download')?.disabled === false,
        }));
        assert.equal(program.text, bySource.program.json.program, 'entry: the pass program shown is not the service\'s');
        assert.ok(program.text.startsWith('%\n(CUTCALC)\n(CUTCALC PASS PROGRAM)'), `entry: not a pass program: ${program.text.slice(0, 80)}`);
        assert.ok(program.download, 'entry: the program download button is not enabled');
        const entryLength = bySource['entry-length'].json;
        const pass = bySource['main-time'].json.lateral_passes;
        const parts = drawn['entry-scheme'].parts;
        assertDimension('entry-scheme', 'dimension-lvr', parts, entryLength.entry_length_mm, 'L_vr');
        assertDimension('entry-scheme', 'dimension-xn', parts, entryLength.start.x_mm, 'X_n');
        if (kase.expect.body.lateral_passes.length === 1) {
          // One pass: the page's entry-length request describes that pass, so both agree.
          const tol = section.tolerance(kase)('/entry_length_mm', 0);
          assert.ok(
            Math.abs(entryLength.entry_length_mm - pass[0].entry_length_mm) <= tol,
            `entry-length L_vr ${entryLength.entry_length_mm} != main-time pass L_vr ${pass[0].entry_length_mm} (request ${bySource['entry-length'].requestBody})`,
          );
        }
        const sources = new Set(shown.map(s => s.source));
        assert.ok(sources.has('entry-length') && sources.has('main-time'), 'both results are shown');
      }
      if (section.id === 'groove') {
        // Ra with its caveat (errata R-E8), the bearing curve from the crest (0 %) through every
        // point the API returned.
        const bearing = bySource.main.json.bearing_curve;
        assert.ok(Array.isArray(bearing) && bearing.length >= 2, 'groove: the page asked for a bearing curve');
        const line = drawn['bearing-curve'].parts['bearing-curve'].find(p => p.tag === 'polyline');
        assert.equal(line?.points, bearing.length + 1, 'groove: the bearing curve has the crest and every API point');
        const caveat = await page.locator('#groove-result [data-role="ra-caveat"]').textContent();
        assert.match(caveat ?? '', /R-E8/, `groove: the Ra caveat is shown: ${caveat}`);
      }
      if (section.id === 'polygon') {
        const polygon = drawn['polygon-hole'].parts.polygon.filter(p => p.tag === 'polygon');
        for (const p of polygon) {
          assert.ok(
            p.points === kase.request.faces || p.points === kase.request.faces + 1,
            `polygon-hole [data-role="polygon"] has ${p.points} vertices for ${kase.request.faces} faces`,
          );
        }
      }
      if (section.id === 'grooving') {
        // The groove's dimensions are the request's width and the answer's depth and tool; the
        // pattern strip has the first revolutions (at most 8) and, when there are more, the last.
        const answer = bySource.main.json;
        const parts = drawn['grooving-section'].parts;
        assertDimension('grooving-section', 'dimension-width', parts, kase.request.groove_width_mm, 'W');
        assertDimension('grooving-section', 'dimension-depth', parts, answer.groove_depth_mm, 'h');
        assertDimension('grooving-section', 'dimension-tool', parts, answer.tool_width_mm, 'B');
        assertDimension('grooving-section', 'dimension-shift', parts, answer.shift_mm, 'X2');
        const rows = drawn['grooving-pattern'].parts.revolution.length;
        const N = answer.revolutions;
        assert.equal(rows, Math.min(N, 8) + (N > 8 ? 1 : 0), `grooving-pattern: ${rows} revolutions drawn for N = ${N}`);
        const dwell = await page.locator('#grooving-result [data-role="dwell-seconds"]').textContent();
        assert.ok(dwell.includes((answer.dwell_time_min * 60).toFixed(3)), `grooving: the dwell in seconds is shown: ${dwell}`);
      }
      if (section.id === 'flat') {
        // The flat's dimensions are the answer's d and face width, the part's is the request's D;
        // the tool at five step points (fewer when 2N + 1 < 5); the step table has every row
        // i = 0..2N; the flatness error is labelled in µm on the magnified segment.
        const answer = bySource.main.json;
        const parts = drawn['flat-section'].parts;
        assertDimension('flat-section', 'dimension-axis-distance', parts, answer.axis_distance_mm, 'd');
        assertDimension('flat-section', 'dimension-width', parts, answer.face_width_mm, 'w');
        assertDimension('flat-section', 'part-diameter', parts, kase.request.part_diameter_mm, 'D');
        const rows = answer.steps_table.length;
        assert.equal(rows, 2 * answer.steps + 1, 'flat: the answer has 2N + 1 steps');
        assert.equal(parts.tool.length, Math.min(5, rows), `flat-section: ${parts.tool.length} tools drawn`);
        assertDimension('flat-spiral', 'dimension-flatness', drawn['flat-spiral'].parts, answer.flatness_error_mm * 1000, 'flatness error (µm)');
        const tableRows = await page.locator('#flat-result table[data-role="steps-table"] tbody tr').count();
        assert.equal(tableRows, rows, `flat: the step table shows ${tableRows} rows for ${rows} steps`);
      }
      if (section.program) {
        await checkProgramAndDownload(page, bySource.main, section.id, section.program);
      }
      await noHorizontalScroll(page, 1280);
      console.log(`# ${section.id}: case ${kase.id} (${section.file}), ${shown.length} numbers shown, ` +
        `${checkedAgainstReference} against the reference, diagrams ${Object.keys(diagrams).join(', ') || 'none'}`);
    });
  }

  test('no horizontal scroll, no console error, no failed request; screenshot', { timeout: TEST_MS }, async () => {
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.screenshot({ path: path.join(ARTIFACT_DIR, 'calculator-1280.png'), fullPage: true });
    await noHorizontalScroll(page, 1280);
    assert.deepEqual(log.problems, [], 'console errors, page errors or failed requests');
  });
});

async function checkProgramAndDownload(page, exchange, id, { arcs }) {
  const program = exchange.json.program;
  assert.equal(typeof program, 'string', 'the JSON answer has a program');
  await page.waitForFunction(([id, p]) => document.getElementById(`${id}-program`)?.textContent.trim() === p.trim(), [id, program], { timeout: WAIT_MS })
    .catch(async () => {
      const shown = await page.locator(`#${id}-program`).textContent();
      assert.fail(`#${id}-program does not show the API's program; it shows: ${JSON.stringify(shown?.slice(0, 200))}`);
    });
  const firstLine = program.split('\n').find(l => l.trim() !== '') ?? '';
  assert.match(firstLine.trim(), /^(%|\(|;|[GMNOT]\d)/, `the program starts like a G-code program: "${firstLine}"`);
  if (arcs) assert.match(program, /\bG0?[23]\b/, 'the program has arc blocks (G2/G3)');
  assert.match(program, /\bM0?(2|30)\b/, 'the program ends with M2 or M30');
  const pre = await page.evaluate(id => {
    const pre = document.getElementById(`${id}-program`);
    const style = getComputedStyle(pre);
    return { overflow: `${style.overflow} ${style.overflowX} ${style.overflowY}` };
  }, id);
  assert.match(pre.overflow, /auto|scroll/, `#${id}-program is scrollable (overflow: ${pre.overflow})`);

  const button = page.locator(`#${id}-download`);
  assert.ok(await button.isEnabled(), `#${id}-download is enabled after a successful calculation`);
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: WAIT_MS }), button.click()]);
  const name = download.suggestedFilename();
  assert.match(name, /\.(ngc|nc|MPF)$/, `the download's file name "${name}" ends .ngc, .nc or .MPF`);
  const file = await download.path();
  const content = readFileSync(file, 'utf8');
  const plain = await apiPost(exchange.path, exchange.requestBody, 'text/plain');
  assert.equal(plain.status, 200, 'text/plain answer');
  assert.equal(content, plain.text, 'the downloaded file is the API text/plain answer to the same request');
  const disposition = plain.headers.get('content-disposition') ?? '';
  const serverName = /filename="?([^";]+)"?/.exec(disposition)?.[1];
  if (serverName) assert.equal(name, serverName, "the download has the server's file name");
  console.log(`# ${id}: downloaded ${name} (${content.length} bytes), equal to the text/plain answer`);
}

// An id for a CSS selector (what CSS.escape does for the usual characters).
function cssId(id) {
  return id.replace(/([^a-zA-Z0-9_-])/g, '\\$1');
}

// ================================================================== keyboard only, page defaults
// The untouched page (its default values) at a phone's width and at the desktop width: every form
// is reached with Tab from the top of the page and submitted with Enter on its submit button, and
// the page never scrolls sideways, with or without results. The 375 px final state is saved.
for (const width of [375, 1280]) {
  describe(`calculator page at ${width} px, keyboard only, default values`, () => {
    let page;
    let context;
    let log;
    before(async () => {
      ({ page, context, log } = await openPage({ width, height: 812 }, `${width}px defaults`));
    });
    after(async () => {
      await context?.close();
    });

    test('every form is reached with Tab and submitted with Enter; no horizontal scroll', { timeout: TEST_MS }, async () => {
      await noHorizontalScroll(page, width);
      await page.evaluate(() => document.activeElement?.blur());
      let tabs = 0;
      for (const section of SECTIONS) {
        // Tab on from wherever focus is until this form's submit button has it.
        let reached = false;
        for (let i = 0; i < 300 && !reached; i += 1) {
          await page.keyboard.press('Tab');
          tabs += 1;
          reached = await page.evaluate(
            id => document.activeElement?.matches(`#${id}-form button[type="submit"]`) ?? false,
            section.id,
          );
        }
        assert.ok(reached, `Tab does not reach the submit button of #${section.id}-form`);
        const bySource = await exchangesFor(log, section.endpoints, () => page.keyboard.press('Enter'));
        for (const e of Object.values(bySource)) {
          assert.equal(e.status, 200, `${section.id}: the untouched form gives ${e.status} from ${e.path}: ${e.text?.slice(0, 300)}`);
        }
        await waitForResults(page, section, bySource);
      }
      await page.evaluate(() => window.scrollTo(0, 0));
      if (width === 375) await page.screenshot({ path: path.join(ARTIFACT_DIR, 'calculator-375.png'), fullPage: true });
      await noHorizontalScroll(page, width);
      console.log(`# ${width} px: ${SECTIONS.length} forms submitted with the keyboard (${tabs} Tab presses in all)`);
      assert.deepEqual(log.problems, [], 'console errors, page errors or failed requests');
    });
  });
}
