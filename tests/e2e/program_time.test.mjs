// End-to-end test of the Program time section and the page's machine profile (machine-time.md,
// POST /v1/program-time): Playwright (playwright-core) drives Debian's headless Chromium against a
// live cutcalc.
//
//   - on open, the section times its default program (a 60 mm square in G64) on the default machine
//     (a router) without a click: the estimate beside the nominal time, their split, the counts, the
//     velocity profile drawn from the answer, the slowest blocks with the program's own blocks, each
//     shown number the API's;
//   - a pasted program with a block that cannot be timed shows the API's message under the text
//     area naming its line and column, the block as written, and a button that selects that line;
//     a valid program clears it;
//   - a program opened from a file (the file input) goes into the text area and is timed;
//   - the machine profile: a preset changes the request's machine, the estimate and the page's
//     link (machine.* keys, never the program); the link opened in a new page gives the same
//     profile and estimate; a lathe profile times the lathe sections' programs (machine_time shown
//     as "on this machine") and says why the mill sections' are not;
//   - a program of 20 000 blocks is timed and stays out of the link;
//   - in Russian: the section's words are the Russian catalogue's (no English word of the catalogue
//     shows), the API's message for a refused program is Russian;
//   - in inches: the velocities are typed in in/min and sent in mm/min;
//   - on every page: no console error, page error, failed request, HTTP error (but the refusals
//     asked for) or CSP violation.
//
// Environment: CUTCALC_URL (required), E2E_PAGE_URL, E2E_ARTIFACT_DIR, CHROMIUM_PATH, as in
// calculator.test.mjs.
import { before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';

import { chromiumForThisFile, repo } from './browser.mjs';
import { API, ARTIFACT_DIR, PAGE_URL, TEST_MS, WAIT_MS, assertClean, openRecordedPage, settle } from './page_session.mjs';

const PATH = '/v1/program-time';
const MM_PER_INCH = 25.4;
const VX = '/machine/axes/x/max_velocity_mm_per_min';

const catalogue = async name => {
  const source = readFileSync(path.join(repo, 'web', 'ui', 'core', `catalogue_${name}.js`), 'utf8');
  return (await import(`data:text/javascript,${encodeURIComponent(source)}`)).default;
};
const EN = await catalogue('en');
const RU = await catalogue('ru');

const browser = chromiumForThisFile();
before(() => mkdirSync(ARTIFACT_DIR, { recursive: true }));
const openPage = (url, options) => openRecordedPage(browser(), url, options);

// ------------------------------------------------------------------ helpers
const lastOf = (log, endpoint) => log.exchanges.filter(e => e.path === endpoint).at(-1);

async function apiPost(body, language = 'en') {
  const response = await fetch(`${API}${PATH}`, {
    method: 'POST',
    headers: { 'content-type': 'application/json', 'accept-language': language },
    body,
  });
  return { status: response.status, json: await response.json() };
}

// The shown results of a section: pointer -> {value (data-value), text}.
async function shown(page, id) {
  return page.evaluate(
    id =>
      Object.fromEntries(
        [...document.querySelectorAll(`#${id}-result [data-result]`)].map(el => [
          el.getAttribute('data-result'),
          { value: el.getAttribute('data-value'), text: el.textContent },
        ]),
      ),
    id,
  );
}

// Runs `action` (an edit of the section), waits for the section's next request (it follows the
// page's pause after an edit; a large program takes longer to send), then for the page to settle.
async function recalculated(log, action) {
  const before = log.exchanges.filter(e => e.path === PATH).length;
  await action();
  const deadline = Date.now() + WAIT_MS;
  while (log.exchanges.filter(e => e.path === PATH).length === before) {
    assert.ok(Date.now() < deadline, `no ${PATH} request within ${WAIT_MS} ms of the edit`);
    await new Promise(resolve => setTimeout(resolve, 50));
  }
  await settle(log);
}

// Puts a program into the text area as a paste does (the text, one input event), then waits for
// its calculation.
async function paste(page, log, text) {
  await recalculated(log, () =>
    page.locator('#program-time-program').evaluate((area, text) => {
      area.focus();
      area.select();
      area.value = text;
      area.dispatchEvent(new InputEvent('input', { bubbles: true, inputType: 'insertFromPaste' }));
    }, text),
  );
}

const SQUARE_WITH_PARAMETER = 'G21 G90 G17 G64\nF3000\nG1 X10\nG1 X#1 Y5\nM2\n';

// ================================================================== the tests
describe('program time', () => {
  test('on open: the default program timed on the default machine, every number the API\'s', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      const sent = log.exchanges.filter(e => e.path === PATH);
      assert.equal(sent.length, 1, 'one /v1/program-time request on load');
      const [e] = sent;
      assert.equal(e.status, 200, `the default program: ${e.text?.slice(0, 300)}`);
      const body = JSON.parse(e.body);
      assert.match(body.program, /G64/, 'the default program blends (G64)');
      assert.match(body.program, /G1 X60/, 'the default program is the 60 mm square');
      assert.equal(body.dialect, 'linuxcnc');
      assert.deepEqual(body.machine.axes.x, { max_velocity_mm_per_min: 12000, max_acceleration_mm_per_s2: 1000 }, 'a router');
      assert.equal(body.machine.kind, 'mill');
      assert.ok(body.profile_points >= 100, 'the page asks for a velocity profile');

      const results = await shown(page, 'program-time');
      const answer = e.json;
      for (const ptr of ['/estimated_time_min', '/nominal_time_min', '/feed_time_min', '/rapid_time_min', '/dwell_time_min',
        '/dynamics_time_min', '/blocks', '/moves', '/feed_length_mm', '/rapid_length_mm', '/rotary_deg']) {
        assert.ok(results[ptr], `${ptr} is shown`);
        assert.equal(Number(results[ptr].value), answer[ptr.slice(1)], `${ptr}: data-value`);
      }
      assert.ok(answer.estimated_time_min > 0 && answer.nominal_time_min > 0);
      // The estimate beside the nominal time, in one list.
      const pair = await page.evaluate(() => {
        const estimated = document.querySelector('#program-time-result [data-result="/estimated_time_min"]');
        const nominal = document.querySelector('#program-time-result [data-result="/nominal_time_min"]');
        return estimated.closest('dl') === nominal.closest('dl');
      });
      assert.ok(pair, 'the estimate and the nominal time are shown together');
      const seconds = await page.locator('#program-time-result [data-role="seconds"]').textContent();
      assert.ok(seconds.includes((answer.estimated_time_min * 60).toFixed(3)), `the estimate in seconds: ${seconds}`);

      // The velocity profile: every sample of the answer, T_e and T_n marked.
      const plot = await page.evaluate(() => {
        const svg = document.querySelector('#program-time-result svg[data-diagram="velocity-profile"]');
        const line = svg?.querySelector('[data-role="profile"]');
        return {
          points: (line?.getAttribute('points') ?? '').trim().split(/\s+/).filter(Boolean).length,
          estimated: !!svg?.querySelector('[data-role="estimated-time"] line'),
          nominal: !!svg?.querySelector('[data-role="nominal-time"] line'),
          title: svg?.querySelector('title')?.textContent ?? '',
        };
      });
      assert.equal(plot.points, answer.profile.length, 'the profile polyline has every sample');
      assert.equal(answer.profile.length, body.profile_points);
      assert.ok(plot.estimated && plot.nominal, 'T_e and T_n are marked');
      assert.equal(plot.title, EN['diagram.velocity_profile_title']);

      // The slowest blocks: line, the block as the program has it, time lost, what limits it.
      const rows = await page.evaluate(() =>
        [...document.querySelectorAll('#program-time-result table[data-role="slowest-blocks"] tbody tr')].map(tr =>
          [...tr.cells].map(c => c.querySelector('[data-value]')?.getAttribute('data-value') ?? c.textContent.trim()),
        ),
      );
      assert.ok(answer.slowest_blocks.length > 0, 'the square loses time somewhere');
      const lines = body.program.split('\n');
      assert.deepEqual(
        rows,
        answer.slowest_blocks.map(b => [String(b.line), lines[b.line - 1].trim(), String(b.lost_min), b.limited_by]),
        'one row per slow block, with its text',
      );
      const words = await page.locator('#program-time-result table[data-role="slowest-blocks"] tbody td:last-child').allTextContents();
      assert.deepEqual(words, answer.slowest_blocks.map(b => EN[`limit.${b.limited_by}`]), 'limited_by in words');

      // The program is not in the link (Copy link keeps the control only).
      const link = await page.evaluate(async () => (await import('/ui/core/url_state.js')).sectionLink('program-time', document.getElementById('program-time-form')));
      assert.deepEqual([...new URL(link).searchParams.keys()], ['program-time.dialect'], `the link ${link}`);
      await page.locator('#program-time').screenshot({ path: path.join(ARTIFACT_DIR, 'program-time-1280.png') });
      await assertClean(page, log, 'on open');
    } finally {
      await context.close();
    }
  });

  test('a program with a block that cannot be timed: the message under the text area names its line', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      log.expectProblems = true;
      await paste(page, log, SQUARE_WITH_PARAMETER);
      const refused = lastOf(log, PATH);
      assert.equal(refused.status, 422, 'the parameter is refused');
      assert.equal(JSON.parse(refused.body).program, SQUARE_WITH_PARAMETER, 'the pasted text is sent as it is');
      const item = refused.json.errors.find(x => x.pointer === '/program');
      assert.ok(item, `a field error at /program: ${refused.text}`);
      assert.equal(item.line, 4);
      assert.equal(item.column, 4);
      const state = await page.evaluate(() => {
        const area = document.getElementById('program-time-program');
        const error = document.getElementById('program-time-program-error');
        return {
          text: error?.querySelector('span')?.textContent ?? '',
          block: error?.querySelector('[data-role="error-block"]')?.textContent ?? '',
          after: error?.previousElementSibling === area,
          invalid: area.getAttribute('aria-invalid'),
          describedby: (area.getAttribute('aria-describedby') ?? '').split(/\s+/),
          visible: !!(error && error.offsetHeight),
          placeholder: document.querySelector('#program-time-result .placeholder')?.textContent ?? '',
        };
      });
      assert.equal(state.text, item.detail, 'the API\'s own message');
      assert.match(state.text, /line 4, column 4/, 'it names the line and column');
      assert.equal(state.block, 'G1 X#1 Y5', 'the block as written');
      assert.ok(state.after && state.visible, 'right under the text area');
      assert.equal(state.invalid, 'true');
      assert.ok(state.describedby.includes('program-time-program-error'));
      assert.equal(state.placeholder, EN['result.no_results']);
      // "Show line 4" selects the block from the refused word on.
      await page.locator('#program-time-program-error [data-role="show-line"]').click();
      const selected = await page.evaluate(() => {
        const area = document.getElementById('program-time-program');
        return { text: area.value.slice(area.selectionStart, area.selectionEnd), focused: document.activeElement === area };
      });
      assert.deepEqual(selected, { text: 'X#1 Y5', focused: true }, 'the refused word and the rest of its block are selected');
      await page.screenshot({ path: path.join(ARTIFACT_DIR, 'program-time-error.png') });
      log.problems = log.problems.filter(p => !/status of 422 \(/.test(p) && !/HTTP 422 /.test(p));
      log.expectProblems = false;

      // A valid program clears the message.
      await paste(page, log, 'G21 G90 G17 G61.1\nF3000\nG1 X40 Y30\nM2\n');
      assert.equal(lastOf(log, PATH).status, 200);
      assert.equal(await page.locator('#program-time-form .field-error').count(), 0, 'no message left');
      assert.equal(await page.locator('#program-time-program[aria-invalid]').count(), 0);
      await assertClean(page, log, 'refused program');
    } finally {
      await context.close();
    }
  });

  test('a program opened from a file is put into the text area and timed', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      const program = 'G21 G90 G17 G61.1\r\nG0 X80\r\nG4 P0.5\r\nM2\r\n';
      await recalculated(log, () =>
        page.locator('#program-time-file').setInputFiles({ name: 'part.ngc', mimeType: 'text/plain', buffer: Buffer.from(program) }),
      );
      // A text area holds LF line ends (the API ignores a CR before LF anyway).
      const text = program.replaceAll('\r\n', '\n');
      assert.equal(await page.locator('#program-time-program').inputValue(), text, 'the file is in the text area');
      const e = lastOf(log, PATH);
      assert.equal(JSON.parse(e.body).program, text, 'the file\'s text is sent');
      assert.equal(e.status, 200);
      assert.ok(e.json.dwell_time_min > 0.008, 'the dwell is timed');
      const note = await page.locator('#program-time-file-name').textContent();
      assert.equal(note, EN['result.file_opened'].replace('{name}', 'part.ngc').replace('{lines}', '4'));
      const results = await shown(page, 'program-time');
      assert.equal(Number(results['/estimated_time_min'].value), e.json.estimated_time_min);
      await assertClean(page, log, 'file');
    } finally {
      await context.close();
    }
  });

  test('the machine profile: a preset changes the request, the estimate and the link; the link restores it', { timeout: TEST_MS }, async () => {
    const first = await openPage(PAGE_URL);
    let second;
    try {
      const { page, log } = first;
      await settle(log);
      const before = lastOf(log, PATH);
      const polygonBefore = lastOf(log, '/v1/polygon-hole/gcode');
      assert.ok(polygonBefore.json.machine_time, 'the polygon program is timed on the router');
      assert.equal(JSON.parse(polygonBefore.body).machine.axes.x.max_velocity_mm_per_min, 12000);
      await recalculated(log, () => page.locator('#program-time-machine-preset').selectOption('hobby_router'));
      const after = lastOf(log, PATH);
      assert.notEqual(after, before, 'the preset asks again');
      const machine = JSON.parse(after.body).machine;
      assert.deepEqual(machine.axes, {
        x: { max_velocity_mm_per_min: 3000, max_acceleration_mm_per_s2: 200 },
        y: { max_velocity_mm_per_min: 3000, max_acceleration_mm_per_s2: 200 },
        z: { max_velocity_mm_per_min: 1500, max_acceleration_mm_per_s2: 100 },
      });
      assert.ok(after.json.estimated_time_min > before.json.estimated_time_min, 'the hobby router is slower');
      const results = await shown(page, 'program-time');
      assert.equal(Number(results['/estimated_time_min'].value), after.json.estimated_time_min, 'the new estimate is shown');
      // The other program sections are timed on it too.
      const polygonAfter = lastOf(log, '/v1/polygon-hole/gcode');
      assert.notEqual(polygonAfter, polygonBefore, 'the polygon section calculates again');
      assert.equal(JSON.parse(polygonAfter.body).machine.axes.x.max_velocity_mm_per_min, 3000);
      const polygon = await shown(page, 'polygon');
      assert.equal(Number(polygon['/machine_time/estimated_time_min'].value), polygonAfter.json.machine_time.estimated_time_min);
      // The page's link: the machine, page-wide; never the program.
      const url = new URL(page.url());
      assert.equal(url.searchParams.get('machine.axes.x.max_velocity_mm_per_min'), '3000', `the page's URL ${url}`);
      assert.equal(url.searchParams.get('machine.axes.z.max_acceleration_mm_per_s2'), '100');
      assert.equal(url.searchParams.get('machine.kind'), 'mill');
      assert.ok(![...url.searchParams.keys()].some(k => k.includes('program.') || k.endsWith('.program')), 'no program in the URL');
      // A velocity typed in: Custom.
      await recalculated(log, () => page.locator(`#program-time-form [name="${VX}"]`).fill('2500'));
      assert.equal(await page.locator('#program-time-machine-preset').inputValue(), '', 'an edited profile is Custom');
      assert.equal(JSON.parse(lastOf(log, PATH).body).machine.axes.x.max_velocity_mm_per_min, 2500);
      const estimate = lastOf(log, PATH).json.estimated_time_min;
      assert.equal(new URL(page.url()).searchParams.get('machine.axes.x.max_velocity_mm_per_min'), '2500');

      // Copy link of another section carries the profile too; opened, it restores it.
      const link = await page.evaluate(async () => (await import('/ui/core/url_state.js')).sectionLink('polygon', document.getElementById('polygon-form')));
      assert.equal(new URL(link).searchParams.get('machine.axes.x.max_velocity_mm_per_min'), '2500', `the polygon link ${link}`);
      second = await openPage(new URL(page.url()).href);
      await settle(second.log);
      assert.equal(await second.page.locator(`#program-time-form [name="${VX}"]`).inputValue(), '2500');
      assert.equal(await second.page.locator('#program-time-machine-preset').inputValue(), '');
      assert.equal(lastOf(second.log, PATH).json.estimated_time_min, estimate, 'the same estimate');
      // Back: the hobby router again, the program in the text area kept.
      await paste(page, log, 'G21 G90 G17 G61.1\nG0 X80\nM2\n');
      await recalculated(log, () => page.goBack());
      assert.equal(await page.locator(`#program-time-form [name="${VX}"]`).inputValue(), '3000', 'back: the hobby router');
      assert.equal(await page.locator('#program-time-program').inputValue(), 'G21 G90 G17 G61.1\nG0 X80\nM2\n', 'back keeps the program');
      await assertClean(page, log, 'profile (first page)');
      await assertClean(second.page, second.log, 'profile (opened link)');
    } finally {
      await first.context.close();
      await second?.context.close();
    }
  });

  test('a lathe profile times the lathe sections and says why the mill sections are not', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      log.expectProblems = true; // the square moves Y, which a lathe lacks: refused, at its input
      await recalculated(log, () => page.locator('#program-time-machine-preset').selectOption('lathe'));
      assert.equal(lastOf(log, PATH).status, 422);
      const yError = await page.locator('#program-time-machine-axes-y-max_velocity_mm_per_min-error').textContent();
      assert.match(yError, /\by\b/, `the missing axis Y is named at its input: ${yError}`);
      log.problems = log.problems.filter(p => !/status of 422 \(/.test(p) && !/HTTP 422 /.test(p));
      log.expectProblems = false;
      for (const [id, endpoint] of [['grooving', '/v1/grooving/cycle'], ['flat', '/v1/lathe-flat']]) {
        const e = lastOf(log, endpoint);
        assert.equal(e.status, 200, `${id}: ${e.text?.slice(0, 200)}`);
        assert.equal(JSON.parse(e.body).machine.kind, 'lathe', `${id}: the lathe profile is sent`);
        const line = await page.locator(`#${id}-result [data-role="machine-time"]`).textContent();
        assert.ok(line.startsWith(EN['result.on_this_machine']), `${id}: ${line}`);
        const results = await shown(page, id);
        assert.equal(Number(results['/machine_time/estimated_time_min'].value), e.json.machine_time.estimated_time_min);
        assert.equal(Number(results['/machine_time/nominal_time_min'].value), e.json.machine_time.nominal_time_min);
      }
      for (const [id, endpoint] of [['entry', '/v1/main-time/program'], ['polygon', '/v1/polygon-hole/gcode']]) {
        assert.equal(JSON.parse(lastOf(log, endpoint).body).machine, undefined, `${id}: no lathe for a mill program`);
        const note = await page.locator(`#${id}-result [data-role="machine-time-note"]`).textContent();
        assert.ok(note.includes(EN['result.machine_not_timed_lathe']), `${id}: ${note}`);
      }
      // A lathe program on the lathe profile.
      await paste(page, log, 'G18 G7 G21 G90 G95\nS1000 M3\nG0 X40 Z2\nG1 Z-30 F0.2\nG0 X42\nM5\nM30\n');
      const e = lastOf(log, PATH);
      assert.equal(e.status, 200, e.text?.slice(0, 300));
      assert.equal(JSON.parse(e.body).machine.kind, 'lathe');
      assert.equal(await page.locator('#program-time-form .field-error').count(), 0, 'the Y message is gone');
      await assertClean(page, log, 'lathe');
    } finally {
      await context.close();
    }
  });

  test('a program of 20 000 blocks is timed and stays out of the link', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      const blocks = ['G21 G90 G17 G64 P0.01', 'F2000'];
      for (let i = 0; i < 20000; i += 1) blocks.push(`G1 X${((i % 200) * 0.25).toFixed(2)} Y${(Math.floor(i / 200) * 0.5).toFixed(1)}`);
      blocks.push('M2', '');
      const program = blocks.join('\n');
      await paste(page, log, program);
      const e = lastOf(log, PATH);
      assert.equal(e.status, 200, e.text?.slice(0, 300));
      assert.equal(JSON.parse(e.body).program, program);
      assert.equal(e.json.blocks, 20003);
      const results = await shown(page, 'program-time');
      assert.equal(Number(results['/blocks'].value), 20003);
      assert.ok(page.url().length < 2000, `the page's URL stays short (${page.url().length})`);
      assert.ok(!page.url().includes('X49.75'), 'no program in the URL');
      await assertClean(page, log, 'large program');
    } finally {
      await context.close();
    }
  });

  test('in Russian: the Russian catalogue\'s words, the API\'s message in Russian', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(`${PAGE_URL}?lang=ru#program-time`);
    try {
      await settle(log);
      const e = lastOf(log, PATH);
      assert.equal(e.headers['accept-language'], 'ru');
      assert.equal(await page.locator('#program-time-title').textContent(), RU['section.program_time']);
      assert.equal(await page.locator('#program-time-machine legend').textContent(), RU['legend.machine']);
      assert.equal(await page.locator('label[for="program-time-file"]').textContent(), RU['button.open_file']);
      const headings = await page.locator('#program-time-result h3').allTextContents();
      for (const key of ['result.time_on_this_machine', 'result.time_split', 'result.velocity_profile', 'result.slowest_blocks']) {
        assert.ok(headings.includes(RU[key]), `the heading ${RU[key]} (${key})`);
      }
      const words = await page.locator('#program-time-result table[data-role="slowest-blocks"] tbody td:last-child').allTextContents();
      assert.deepEqual(words, e.json.slowest_blocks.map(b => RU[`limit.${b.limited_by}`]), 'limited_by in Russian');
      const presets = await page.locator('#program-time-machine-preset option').allTextContents();
      assert.deepEqual(presets, ['custom', 'hobby_router', 'router', 'machining_centre', 'lathe'].map(p => RU[`option.preset_${p}`]));
      // No English word of the catalogue (that Russian has not) in what the section shows.
      const english = new Set(
        Object.values(EN).flatMap(text => text.replace(/_\{[^}]*\}|\{\w+\}/g, ' ').match(/[A-Za-z]{3,}/g) ?? []).map(w => w.toLowerCase()),
      );
      for (const text of Object.values(RU)) for (const w of text.match(/[A-Za-z]{3,}/g) ?? []) english.delete(w.toLowerCase());
      const text = (await page.locator('#program-time').innerText()).replace(/\/v1\/[\w/-]+/g, ' ');
      const found = [...english].filter(w => new RegExp(`\\b${w}\\b`, 'i').test(text));
      assert.deepEqual(found, [], 'English words in the Russian section');
      assert.match(text, /[А-Яа-я]/);
      // A refused program: the API's message, in Russian, under the text area.
      log.expectProblems = true;
      await paste(page, log, SQUARE_WITH_PARAMETER);
      const refused = lastOf(log, PATH);
      assert.equal(refused.status, 422);
      assert.equal(refused.language, 'ru');
      const message = await page.locator('#program-time-program-error span').first().textContent();
      assert.match(message, /строка 4/, `the message names the line in Russian: ${message}`);
      assert.equal(await page.locator('#program-time-program-error [data-role="show-line"]').textContent(), RU['button.show_line'].replace('{line}', '4'));
      // The message is the one the API gives in Russian.
      const direct = await apiPost(refused.body, 'ru');
      assert.equal(message, direct.json.errors.find(x => x.pointer === '/program').detail);
      await page.locator('#program-time').screenshot({ path: path.join(ARTIFACT_DIR, 'program-time-ru.png') });
      log.problems = log.problems.filter(p => !/status of 422 \(/.test(p) && !/HTTP 422 /.test(p));
      log.expectProblems = false;
      await assertClean(page, log, 'Russian');
    } finally {
      await context.close();
    }
  });

  test('in inches: the velocities in in/min, sent in mm/min', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(`${PAGE_URL}?units=inch`);
    try {
      await settle(log);
      const unit = await page.locator(`label[for="program-time-machine-axes-x-max_velocity_mm_per_min"] [data-unit]`).textContent();
      assert.equal(unit, EN['unit.in_per_min']);
      const typed = await page.locator(`#program-time-form [name="${VX}"]`).inputValue();
      assert.equal(Number(typed), Number((12000 / MM_PER_INCH).toPrecision(5)), 'the router\'s 12 m/min in in/min');
      assert.equal(await page.locator('#program-time-machine-preset').inputValue(), 'router', 'still the router preset');
      await recalculated(log, () => page.locator(`#program-time-form [name="${VX}"]`).fill('100'));
      const sent = JSON.parse(lastOf(log, PATH).body).machine.axes.x.max_velocity_mm_per_min;
      assert.ok(Math.abs(sent - 2540) < 1e-9, `100 in/min is sent as ${sent} mm/min`);
      assert.equal(new URL(page.url()).searchParams.get('machine.axes.x.max_velocity_mm_per_min'), '100', 'the link keeps the text as typed');
      await assertClean(page, log, 'inch');
    } finally {
      await context.close();
    }
  });
});
