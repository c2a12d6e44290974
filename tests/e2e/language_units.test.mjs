// End-to-end test of the calculator page's language and units (issue 13, parts 4, 5 and the
// symbols of 6): Playwright (playwright-core) drives Debian's headless Chromium against a live
// cutcalc.
//
//   - catalogues: web/ui/core/catalogue_en.js and catalogue_ru.js have the same keys, no empty text and
//     the same {placeholders};
//   - every visible text of the page (English and Russian, mm and inch, every section calculated)
//     is a catalogue text, a symbol (var.sym, var.iso), a number or punctuation: no word of the
//     page is outside the catalogues;
//   - the Russian page of each section, calculated, shows no English word of the catalogue, asks
//     the API in Russian (Accept-Language: ru) and shows its messages in Russian;
//   - a calculation entered in inches (the mm defaults / 25.4) sends the same mm requests and gets
//     the same results as in mm; the page shows them in inches (value / 25.4, unit "in"); the
//     programs are asked for in inches (program.units) and download as G20;
//   - the ISO 3002 symbol stands beside each paper symbol S (a feed or a spindle speed);
//   - the language and units links work from the keyboard at 375 px and 1280 px, carry the
//     inputs over (converted) and keep the setting in the URL; no sideways scroll;
//   - on every page: no console error, page error, failed request, HTTP error or CSP violation.
//
// Environment: CUTCALC_URL (required), E2E_PAGE_URL, E2E_ARTIFACT_DIR, CHROMIUM_PATH, as in
// calculator.test.mjs.
import { before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';

import { PAGE_SECTIONS, ROUTES, env, chromiumForThisFile, repo } from './browser.mjs';
import { API, ARTIFACT_DIR, PAGE_URL, TEST_MS, assertClean, openRecordedPage, settle } from './page_session.mjs';

// The page sections and the endpoints each calls, from the route table (cutcalc --routes).
const SECTIONS = PAGE_SECTIONS;
const SECTION_PATHS = Object.fromEntries(
  SECTIONS.map(id => [id, ROUTES.filter(r => r.page_section === id).map(r => r.path)]),
);
// The page's units that are lengths (units.js), with the power of the inch they convert by.
const LENGTH_UNITS = { mm: 1, mm_per_tooth: 1, mm_per_rev: 1, mm_per_min: 1, mm2: 2 };
const INCH_UNITS = { in: 1, in_per_tooth: 1, in_per_rev: 1, in_per_min: 1, in2: 2 };
const MM_PER_INCH = 25.4;

// The page's catalogue modules as the browser loads them (ES modules; web/ has no package.json).
const catalogue = async name => {
  const source = readFileSync(path.join(repo, 'web', 'ui', 'core', `catalogue_${name}.js`), 'utf8');
  return (await import(`data:text/javascript,${encodeURIComponent(source)}`)).default;
};
const CATALOGUES = { en: await catalogue('en'), ru: await catalogue('ru') };

const browser = chromiumForThisFile();
before(() => mkdirSync(ARTIFACT_DIR, { recursive: true }));

// ------------------------------------------------------------------ a page and what happens on it
const openPage = (url, viewport) => openRecordedPage(browser(), url, { viewport });



// Every visible text of the page as [text, where]: text nodes of rendered elements, the options
// of visible selects, SVG text; not the G-code programs (machine text) nor the API's own values
// ([data-result]) and messages (.field-error, .form-error, .warnings), checked apart.
// With `everything`, the API's values and messages are in too (the programs never are).
async function visibleTexts(page, root = 'body', everything = false) {
  return page.evaluate(([root, everything]) => {
    const out = [];
    const apart = everything ? 'pre, title, desc, style, script' : 'pre, [data-result], .field-error, .form-error, .warnings, title, desc, style, script';
    const skip = el => el.closest(apart);
    const shown = el => {
      const select = el.closest('select');
      const box = select ?? el;
      return box.getClientRects().length > 0 && getComputedStyle(box).visibility !== 'hidden';
    };
    const walker = document.createTreeWalker(document.querySelector(root), NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const el = node.parentElement;
      if (!el || node.textContent.trim() === '' || skip(el) || !shown(el)) continue;
      const symbol = el.closest('var.sym, var.iso') !== null;
      out.push({ text: node.textContent, symbol, where: `${el.tagName.toLowerCase()}${el.id ? `#${el.id}` : ''} in ${el.closest('[id]')?.id ?? 'body'}` });
    }
    if (root === 'body') out.push({ text: document.title, symbol: false, where: 'title' });
    return out;
  }, [root, everything]);
}

// ------------------------------------------------------------------ catalogue texts
const PLACEHOLDER = /\{(\w+)\}/g;
const SUBSCRIPT = /_\{([^}]*)\}/g;
const escapeRegExp = s => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
// Text that is no word: numbers, signs, punctuation, units' symbols.
const NO_WORD = /^[\s\d.,:;()[\]=+\-\u2212\u2013\u2014\u00d7\u00b7/|%\u00b0\u00b2\u2032'"\u2192\u2026e]*$/;
// Bare symbols the diagrams write without a <var> (a dimension's L, then its subscript vr; the
// largest feed S max): one or two letters, or these.
const SYMBOL_WORDS = new Set(['max', 'pod', 'per', 'vr1', 'zb']);

// The pieces a catalogue text is shown in: split at its subscripts; a placeholder matches any text.
function pieces(lang) {
  const list = [];
  for (const text of Object.values(CATALOGUES[lang])) {
    for (const [i, piece] of text.split(SUBSCRIPT).entries()) {
      if (piece.trim() === '') continue;
      const pattern = escapeRegExp(piece.trim()).replace(/\\\{(\w+)\\\}/g, '.+?');
      list.push({ piece: piece.trim(), exact: new RegExp(`^${pattern}$`), sub: i % 2 === 1 });
    }
  }
  return list;
}

// Why a visible text is not from the catalogue of `lang`, or null when it is.
function outsideCatalogue(item, lang, list) {
  const text = item.text.trim();
  if (item.symbol || NO_WORD.test(text)) return null;
  if (list.some(p => p.exact.test(text))) return null;
  // A text made of catalogue texts (longest first), numbers and symbols.
  let rest = text;
  const literal = list.filter(p => !/\{\w+\}/.test(p.piece) && p.piece.length >= 2).map(p => p.piece);
  for (const piece of literal.sort((a, b) => b.length - a.length)) rest = rest.split(piece).join(' ');
  const words = rest.split(/[^\p{L}\d]+/u).filter(w => w !== '' && !/^\d+$/.test(w));
  const strange = words.filter(w => !(/^\p{L}{1,2}\d*$/u.test(w) || SYMBOL_WORDS.has(w)));
  return strange.length ? `"${text}" (${item.where}): ${strange.join(', ')} not in the ${lang} catalogue` : null;
}

// English words of the catalogue that no Russian text has (brand names like LinuxCNC are in both).
function englishOnlyWords() {
  const words = texts => new Set(texts.flatMap(t => t.replace(SUBSCRIPT, ' ').replace(PLACEHOLDER, ' ').match(/[A-Za-z]{3,}/g) ?? []).map(w => w.toLowerCase()));
  const ru = words(Object.values(CATALOGUES.ru));
  return [...words(Object.values(CATALOGUES.en))].filter(w => !ru.has(w));
}

// ================================================================== the tests
describe('catalogues', () => {
  test('English and Russian have the same keys, no empty text and the same placeholders', () => {
    const [en, ru] = [CATALOGUES.en, CATALOGUES.ru];
    assert.deepEqual(Object.keys(ru).sort(), Object.keys(en).sort(), 'the same keys');
    assert.ok(Object.keys(en).length > 100, 'the catalogue holds the page');
    for (const key of Object.keys(en)) {
      assert.ok(en[key].trim() && ru[key].trim(), `${key}: empty text`);
      const names = t => [...t.matchAll(PLACEHOLDER)].map(m => m[1]).sort();
      assert.deepEqual(names(ru[key]), names(en[key]), `${key}: placeholders`);
    }
  });
});

describe('every visible text is from the catalogue', () => {
  for (const [lang, units] of [['en', 'mm'], ['ru', 'mm'], ['en', 'inch'], ['ru', 'inch']]) {
    test(`${lang}, ${units}: no visible text outside the ${lang} catalogue`, { timeout: TEST_MS }, async () => {
      const query = new URLSearchParams({ ...(lang !== 'en' && { lang }), ...(units !== 'mm' && { units }) });
      const { context, page, log } = await openPage(`${PAGE_URL}?${query}`);
      try {
        await settle(log);
        assert.equal(await page.evaluate(() => document.documentElement.lang), lang, '<html lang>');
        const list = pieces(lang);
        const texts = await visibleTexts(page);
        assert.ok(texts.length > 300, `the page shows text (${texts.length} texts)`);
        const outside = texts.map(item => outsideCatalogue(item, lang, list)).filter(Boolean);
        assert.deepEqual(outside, [], 'visible texts outside the catalogue');
        const shot = `language-units-${lang}-${units}.png`;
        await page.screenshot({ path: path.join(ARTIFACT_DIR, shot), fullPage: true });
        console.log(`# ${lang}, ${units}: ${texts.length} visible texts, all from the catalogue, symbols or numbers (${shot})`);
        await assertClean(page, log, `${lang} ${units}`);
      } finally {
        await context.close();
      }
    });
  }
});

describe('the Russian page', () => {
  test('each section, calculated, shows no English word of the catalogue; the API answers in Russian', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(`${PAGE_URL}?lang=ru`);
    try {
      await settle(log);
      const english = englishOnlyWords();
      assert.ok(english.length > 100, 'English words to look for');
      for (const id of SECTIONS) {
        const before = log.exchanges.length;
        await page.locator(`#${id}-form button[type="submit"]`).click();
        await settle(log);
        const mine = log.exchanges.slice(before);
        assert.ok(mine.length > 0, `${id}: Calculate sent nothing`);
        for (const e of mine) assert.equal(e.headers['accept-language'], 'ru', `${id}: ${e.path} Accept-Language`);
        // What the section shows (the G-code programs are machine text); the API's addresses
        // (/v1/main-time) are names, not words.
        const text = (await visibleTexts(page, `#${id}`, true))
          .filter(item => !item.symbol)
          .map(item => item.text)
          .join('\n')
          .replace(/\/v1\/[\w/-]+/g, ' ');
        const found = english.filter(w => new RegExp(`\\b${w}\\b`, 'i').test(text));
        assert.deepEqual(found, [], `#${id} in Russian shows English words`);
      }
      // A wrong input: the service's message, next to the field, is Russian.
      log.expectProblems = true;
      await page.locator('#groove-feed_mm').fill('-1');
      await page.locator('#groove-feed_mm').press('Enter');
      await settle(log);
      const problem = log.exchanges.at(-1);
      assert.equal(problem.status, 422, 'an invalid feed is refused');
      assert.equal(problem.language, 'ru', 'Content-Language of the problem');
      const message = await page.locator('#groove-feed_mm-error').textContent();
      assert.match(message, /[А-Яа-я]/, `the message is Russian: ${message}`);
      assert.deepEqual(english.filter(w => new RegExp(`\\b${w}\\b`, 'i').test(message)), [], `English in "${message}"`);
      await page.screenshot({ path: path.join(ARTIFACT_DIR, 'language-units-ru-error.png'), fullPage: false });
      // The browser reports the refused request it was asked to make; nothing else may appear.
      log.problems = log.problems.filter(p => !/status of 422 \(/.test(p));  // any reason phrase
      console.log(`# ru: ${SECTIONS.length} sections calculated, none shows any of ${english.length} English words; the API's message: ${message}`);
      await assertClean(page, log, 'Russian page');
    } finally {
      await context.close();
    }
  });
});

// ------------------------------------------------------------------ inches
// The section's inputs on the page (enabled named controls; not a program's text area) with their
// label's unit and URL key, then those of the page's machine profile (page-wide, data-page-wide:
// keyed by their name alone, url_state.js), which the program sections are timed on.
async function inputsWithUnits(page, id) {
  return page.evaluate(id => {
    const own = [...document.querySelectorAll(`#${id}-form :is(input, select)[name^="/"]`)];
    const profile = [...document.querySelectorAll('[data-page-wide]')].filter(c => !own.includes(c));
    return [...own, ...profile]
      .filter(c => !c.disabled)
      .map(c => [
        c.name,
        c.value,
        document.querySelector(`label[for="${c.id}"] [data-unit]`)?.dataset.unit ?? '',
        c.hasAttribute('data-page-wide') ? c.name.slice(1).replaceAll('/', '.') : `${id}${c.name.replaceAll('/', '.')}`,
      ]);
  }, id);
}

async function shownResults(page, id) {
  return page.evaluate(
    id =>
      [...document.querySelectorAll(`#${id}-result [data-result]`)].map(el => ({
        ptr: el.getAttribute('data-result'),
        source: el.getAttribute('data-source') ?? '',
        value: el.getAttribute('data-value'),
        unit: el.getAttribute('data-unit') ?? '',
        text: el.textContent,
        // The unit as shown: beside the number, or in its table column's header.
        shownUnit:
          el.closest('.quantity')?.querySelector('.unit')?.textContent ??
          (() => {
            const cell = el.closest('td');
            if (!cell) return '';
            const index = [...cell.parentElement.children].indexOf(cell);
            return cell.closest('table').querySelector('thead tr').children[index]?.querySelector('.unit')?.textContent ?? '';
          })(),
      })),
    id,
  );
}

const close = (a, b, rel = 1e-9) => Math.abs(a - b) <= rel * Math.max(1, Math.abs(a), Math.abs(b));

// The JSON numbers of a request body, by pointer.
function numbersOf(body, prefix = '', out = {}) {
  for (const [k, v] of Object.entries(body)) {
    if (typeof v === 'number') out[`${prefix}/${k}`] = v;
    else if (v && typeof v === 'object') numbersOf(v, `${prefix}/${k}`, out);
  }
  return out;
}

describe('inches', () => {
  test('the programs of the inch page are asked for and download in inches (G20)', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(`${PAGE_URL}?units=inch`);
    try {
      await settle(log);
      const PROGRAM_PATHS = ['/v1/main-time/program', '/v1/polygon-hole/gcode', '/v1/grooving/cycle', '/v1/lathe-flat'];
      const programs = log.exchanges.filter(e => PROGRAM_PATHS.includes(e.path));
      assert.equal(programs.length, PROGRAM_PATHS.length, 'one program request per program section');
      for (const e of programs) {
        assert.equal(JSON.parse(e.body).program?.units, 'inch', `${e.path}: program.units`);
        assert.equal(e.json?.units ?? 'inch', 'inch', `${e.path}: the answer's units`);
      }
      for (const id of ['entry', 'polygon', 'grooving', 'flat']) {
        const [download] = await Promise.all([page.waitForEvent('download'), page.locator(`#${id}-download`).click()]);
        const program = readFileSync(await download.path(), 'utf8');
        assert.match(program, /\bG20\b/, `the ${id} program downloads in inches (G20)`);
        assert.doesNotMatch(program, /\bG21\b/, `the ${id} program is not in mm`);
      }
      await settle(log);
      console.log(`# inch page: ${programs.length} programs asked for with program.units "inch", each downloads with G20`);
      await assertClean(page, log, 'inch programs');
    } finally {
      await context.close();
    }
  });

  for (const id of SECTIONS) {
    test(`${id}: entered in inches, the same requests (in mm) and results as in mm, shown in inches`, { timeout: TEST_MS }, async () => {
      const mm = await openPage(PAGE_URL);
      let inch;
      try {
        await settle(mm.log);
        const inputs = await inputsWithUnits(mm.page, id);
        const mmResults = (await shownResults(mm.page, id)).filter(r => !r.ptr.startsWith('/warnings/'));
        // The same inputs in inches: each length / 25.4 written with every digit.
        const query = new URLSearchParams({ units: 'inch' });
        let converted = 0;
        for (const [, text, unit, key] of inputs) {
          // The program's units as in mm (an inch program is another request, tested below).
          const inches = unit in LENGTH_UNITS && text.trim() !== '' ? String(Number(text) / MM_PER_INCH ** LENGTH_UNITS[unit]) : text;
          converted += inches !== text ? 1 : 0;
          query.append(key, inches);
        }
        assert.ok(converted > 0, `${id}: no length input to convert`);
        inch = await openPage(`${PAGE_URL}?${query}#${id}`);
        await settle(inch.log);
        // The requests: the same numbers (mm) within rounding; programs asked for in inches.
        // A request by its endpoint, milling sense and opt-in fields (speeds sends three).
        const requests = log =>
          Object.fromEntries(
            log.exchanges
              .filter(e => SECTION_PATHS[id].includes(e.path))
              .map(e => {
                const body = JSON.parse(e.body);
                return [`${e.path} ${body.milling ?? ''} ${'arc_samples' in body}`, body];
              }),
          );
        const [mmSent, inchSent] = [requests(mm.log), requests(inch.log)];
        assert.deepEqual(Object.keys(inchSent).sort(), Object.keys(mmSent).sort(), `${id}: the same requests`);
        for (const key of Object.keys(mmSent)) {
          const a = numbersOf(mmSent[key]);
          const b = numbersOf(inchSent[key]);
          assert.deepEqual(Object.keys(b).sort(), Object.keys(a).sort(), `${key}: the same fields`);
          for (const ptr of Object.keys(a)) assert.ok(close(a[ptr], b[ptr]), `${key} ${ptr}: ${b[ptr]} sent in inch mode, ${a[ptr]} in mm`);
        }
        // The results: the API's values equal; the text is the value in inches, with its unit.
        // Warnings aside: an inch program prints coarser arcs and may warn about it.
        const noWarnings = list => list.filter(r => !r.ptr.startsWith('/warnings/'));
        const inchResults = noWarnings(await shownResults(inch.page, id));
        assert.equal(inchResults.length, mmResults.length, `${id}: as many results`);
        let inInches = 0;
        for (const [i, want] of mmResults.entries()) {
          const got = inchResults[i];
          const where = `#${id}-result ${got.ptr}`;
          assert.equal(got.ptr, want.ptr, where);
          if (Number.isNaN(Number(want.value))) assert.equal(got.value, want.value, where);
          else assert.ok(close(Number(got.value), Number(want.value), 1e-8), `${where}: ${got.value} in inch mode, ${want.value} in mm`);
          if (want.unit in LENGTH_UNITS) {
            assert.ok(got.unit in INCH_UNITS, `${where}: shown in ${got.unit}, not inches`);
            assert.match(got.shownUnit, /^in/, `${where}: the unit shown is "${got.shownUnit}"`);
            const inches = Number(got.value) / MM_PER_INCH ** INCH_UNITS[got.unit];
            const shown = Number(got.text);
            const decimals = (got.text.split('.')[1] ?? '').replace(/e.*/, '').length;
            assert.ok(Math.abs(shown - inches) <= 0.5 * 10 ** -decimals * (1 + 1e-9) + 1e-12 + Math.abs(inches) * 5e-4, `${where}: shows ${got.text} for ${inches} in`);
            inInches += 1;
          } else {
            assert.equal(got.text, want.text, `${where}: not a length, shown as in mm`);
          }
        }
        console.log(`# ${id}: ${converted} inputs in inches, ${mmResults.length} results equal to mm, ${inInches} shown in inches`);
        await assertClean(inch.page, inch.log, `${id} inch`);
        await assertClean(mm.page, mm.log, `${id} mm`);
      } finally {
        await mm.context.close();
        await inch?.context.close();
      }
    });
  }
});

describe('symbols', () => {
  test('the ISO 3002 symbol stands beside every paper S (a feed here, a spindle speed there)', { timeout: TEST_MS }, async () => {
    const { context, page, log } = await openPage(PAGE_URL);
    try {
      await settle(log);
      const labels = await page.evaluate(() =>
        [...document.querySelectorAll('label, dt')].map(l => ({
          name: l.getAttribute('for') ?? l.textContent,
          paper: l.querySelector('var.sym')?.textContent ?? '',
          iso: l.querySelector('var.iso')?.textContent ?? '',
        })),
      );
      const paperS = labels.filter(l => /^S/.test(l.paper));
      assert.ok(paperS.length >= 6, `labels with a paper S: ${paperS.length}`);
      for (const l of paperS) assert.match(l.iso, /^(f|v|n)/, `${l.name}: paper ${l.paper} without its ISO symbol`);
      const iso = Object.fromEntries(labels.map(l => [l.name, l.iso]));
      assert.equal(iso['polygon-spindle_speed_rpm'], 'n', 'the polygon spindle speed S is n');
      assert.equal(iso['entry-feed_per_tooth_mm'], 'fz', 'the feed per tooth S_z is f_z');
      assert.equal(iso['groove-feed_mm'], 'f', 'the groove feed S is f');
      assert.equal(iso['entry-allowance-width_of_cut_mm'], 'ae', 'the width of cut t is a_e');
      assert.equal(iso['entry-allowance-depth_of_cut_mm'], 'ap', 'the depth of cut t0 is a_p');
      assert.equal(iso['entry-cutting_speed_m_per_min'], 'vc', 'the cutting speed v is v_c');
      console.log(`# ${paperS.length} paper symbols S, each with its ISO symbol`);
      await assertClean(page, log, 'symbols');
    } finally {
      await context.close();
    }
  });
});

// ================================================================== keyboard only
for (const width of [375, 1280]) {
  describe(`language and units at ${width} px, keyboard only`, () => {
    test('Tab to Русский and to inch, Enter: the page changes, the inputs carry over converted', { timeout: TEST_MS }, async () => {
      const { context, page, log } = await openPage(PAGE_URL, { width, height: 812 });
      try {
        await settle(log);
        // Tab (or Shift+Tab) to the element matching `selector`.
        const tabTo = async (selector, key = 'Tab') => {
          for (let i = 0; i < 80; i += 1) {
            await page.keyboard.press(key);
            if (await page.evaluate(s => document.activeElement?.matches(s), selector)) return;
          }
          assert.fail(`${key} does not reach ${selector}`);
        };
        // Enter on a settings link: the page opens again with the setting.
        const follow = async (selector, key) => {
          for (let i = 0; i < 80; i += 1) {
            await page.keyboard.press(key);
            if (await page.evaluate(s => document.activeElement?.matches(s), selector)) {
              const before = page.url();
              await Promise.all([page.waitForURL(u => u.toString() !== before), page.keyboard.press('Enter')]);
              await page.waitForLoadState('load');
              await settle(log);
              return;
            }
          }
          assert.fail(`${key} does not reach ${selector}`);
        };
        await follow('a[data-setting="lang"][data-choice="ru"]', 'Tab');
        // An edit in mm, from the keyboard: a 25.4 mm cutter, 1 inch after the switch.
        await tabTo('#entry-cutter_diameter_mm');
        await page.keyboard.press('ControlOrMeta+A');
        await page.keyboard.type('25.4');
        await page.keyboard.press('Enter');
        await settle(log);
        assert.equal(new URL(page.url()).searchParams.get('lang'), 'ru', 'lang=ru in the URL');
        assert.equal(await page.evaluate(() => document.documentElement.lang), 'ru');
        assert.equal(await page.locator('#groove-form button[type="submit"]').textContent(), CATALOGUES.ru['button.calculate']);
        await follow('a[data-setting="units"][data-choice="inch"]', 'Shift+Tab');
        const url = new URL(page.url());
        assert.equal(url.searchParams.get('units'), 'inch', 'units=inch in the URL');
        assert.equal(url.searchParams.get('lang'), 'ru', 'lang kept');
        assert.equal(await page.locator('#entry-cutter_diameter_mm').inputValue(), '1', 'the 25.4 mm cutter reads 1 in');
        assert.equal(await page.locator('#entry-program-units').inputValue(), 'inch', 'the program follows the page into inches');
        const sent = log.exchanges.filter(e => e.path === '/v1/entry-length').at(-1);
        assert.equal(JSON.parse(sent.body).cutter_diameter_mm, 25.4, 'sent to the API in mm');
        const overflow = await page.evaluate(() => document.scrollingElement.scrollWidth);
        assert.ok(overflow <= width, `the page scrolls sideways at ${width} px (${overflow})`);
        await page.evaluate(() => window.scrollTo(0, 0));
        await page.screenshot({ path: path.join(ARTIFACT_DIR, `language-units-ru-inch-${width}.png`), fullPage: false });
        console.log(`# ${width} px: Русский and inch from the keyboard, ${url.search}`);
        await assertClean(page, log, `${width} px keyboard`);
      } finally {
        await context.close();
      }
    });
  });
}
